// DOT (Graphviz) text of a G-map or O-map, in the conventions of the papers: darts are nodes
// labelled by their index, an i-link is an undirected edge coloured by dimension
//   0 black, 1 red, 2 blue, 3 green (the papers), and, chosen here, 4 orange, 5 purple, 6 brown,
//   7 cyan; dimensions 8 and above are gray and labelled with their dimension.
// i-loops (free darts) are drawn only on request. For an O-map (digraph), beta_1 is drawn as
// directed red arcs and the involutions 2..n as undirected edges. A link that is not reciprocated
// (an invalid map: alpha_i(alpha_i(d)) != d) is drawn once per direction, dashed, with an arrow.
#pragma once
#include <string>

#include "model/core/map.hpp"

namespace gmr::draw {

struct DotOptions {
  bool loops = false;         // draw i-loops of free darts
  std::string name = "gmap";  // graph name
};

// The colour of dimension i ("black", "red", ...).
std::string dimension_colour(int i);

std::string to_dot(const Map& g, const DotOptions& opt = {});

}  // namespace gmr::draw
