#include "tools/cli/summary.hpp"

#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"

namespace gmr::cli {

std::string map_name(const Map& g) {
  return std::to_string(g.dimension()) + (g.is_omap() ? "-O-map" : "-G-map");
}

std::string per_dimension(const std::vector<size_t>& v, int lo) {
  std::string s;
  for (size_t i = static_cast<size_t>(lo); i < v.size(); ++i)
    s += (s.empty() ? "" : " ") + std::to_string(i) + ":" + std::to_string(v[i]);
  return s;
}

MapSummary summarize(const Map& g) {
  MapSummary s{};
  s.kind = g.kind();
  s.dimension = g.dimension();
  s.darts = g.size();
  s.links.assign(static_cast<size_t>(g.dimension()) + 1, 0);
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
    s.links[static_cast<size_t>(i)] = g.count_links(i);
  const ValidityReport r = check_validity(g, 0);
  s.valid = r.ok();
  s.violations = r.total();
  s.cells_known = s.valid;
  if (s.valid) {
    s.cells = count_all_cells(g);
    s.components = count_components(g);
    s.euler = euler_characteristic(g);
    s.closed = is_closed(g);
    s.boundary_cells = count_boundary_cells(g);
  }
  return s;
}

void add_to_json(nlohmann::ordered_json& j, const MapSummary& s) {
  j["kind"] = to_string(s.kind);
  j["dimension"] = s.dimension;
  j["darts"] = s.darts;
  nlohmann::ordered_json links = nlohmann::ordered_json::object();
  for (int i = s.kind == MapKind::OMap ? 1 : 0; i <= s.dimension; ++i)
    links[std::to_string(i)] = s.links[static_cast<size_t>(i)];
  j["links"] = links;
  j["valid"] = s.valid;
  j["violations"] = s.violations;
  if (s.cells_known) {
    j["cells"] = s.cells;
    j["components"] = s.components;
    j["euler"] = s.euler;
    j["closed"] = s.closed;
    j["boundary_cells"] = s.boundary_cells;
  }
}

std::string describe_change(const MapSummary& before, const MapSummary& after) {
  if (!before.cells_known || !after.cells_known) return {};
  const int lo = before.kind == MapKind::OMap ? 1 : 0;
  return "cells " + per_dimension(before.cells, lo) + " -> " + per_dimension(after.cells, lo) +
         ", components " + std::to_string(before.components) + " -> " +
         std::to_string(after.components) + ", Euler characteristic " +
         std::to_string(before.euler) + " -> " + std::to_string(after.euler);
}

nlohmann::ordered_json change_to_json(const MapSummary& before, const MapSummary& after) {
  if (!before.cells_known || !after.cells_known) return nullptr;
  nlohmann::ordered_json j;
  j["cells"] = {before.cells, after.cells};
  j["components"] = {before.components, after.components};
  j["euler"] = {before.euler, after.euler};
  return j;
}

}  // namespace gmr::cli
