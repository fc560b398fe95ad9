// Facts about a map for `gmr info` and `gmr demo`: kind, dimension, darts, links per dimension,
// cells per dimension, components, Euler characteristic, boundary, validity (orbit.hpp,
// validity.hpp). Cell counts are computed only for a valid map (orbits of an invalid map do not
// describe cells).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::cli {

struct MapSummary {
  MapKind kind;
  int dimension;
  size_t darts;
  std::vector<size_t> links;  // indexed by dimension (lowest..n; 0 unused for an O-map)
  bool valid;
  size_t violations;
  bool cells_known;  // the rest is meaningful only when valid
  std::vector<size_t> cells;
  size_t components = 0;
  long long euler = 0;
  bool closed = false;
  size_t boundary_cells = 0;
};

MapSummary summarize(const Map& g);
// "2-G-map", "3-O-map".
std::string map_name(const Map& g);
// "0:8 1:12 2:6"
std::string per_dimension(const std::vector<size_t>& v, int lo);
// Appends the summary's members to the object j.
void add_to_json(nlohmann::ordered_json& j, const MapSummary& s);

// What an operation changed (`gmr apply`), for valid maps before and after:
// "cells 0:8 1:12 2:6 -> 0:26 1:48 2:24, components 1 -> 1, Euler characteristic 2 -> 2";
// empty when either map is invalid.
std::string describe_change(const MapSummary& before, const MapSummary& after);
// {"cells": [[before], [after]], "components": [b, a], "euler": [b, a]}; null when either is
// invalid.
nlohmann::ordered_json change_to_json(const MapSummary& before, const MapSummary& after);

}  // namespace gmr::cli
