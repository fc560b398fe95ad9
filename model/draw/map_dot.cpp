#include "model/draw/map_dot.hpp"

#include <nlohmann/json.hpp>

namespace gmr::draw {

std::string dimension_colour(int i) {
  static const char* const kColours[] = {"black",  "red",    "blue",  "green",
                                         "orange", "purple", "brown", "cyan"};
  return i >= 0 && i < 8 ? kColours[i] : "gray";
}

std::string to_dot(const Map& g, const DotOptions& opt) {
  const bool directed = g.is_omap();
  const std::string arc = directed ? " -> " : " -- ";
  std::string out =
      std::string(directed ? "digraph " : "graph ") + nlohmann::json(opt.name).dump() + " {\n";
  out += "  // gmr " + std::to_string(g.dimension()) + "-" + (directed ? "O-map" : "G-map") + ", " +
         std::to_string(g.size()) +
         " darts; colours per dimension: 0 black, 1 red, 2 blue, 3 green, 4 orange, "
         "5 purple, 6 brown, 7 cyan, 8+ gray\n";
  out += "  node [shape=circle, fontsize=10, width=0.35, fixedsize=true];\n";
  g.for_each_dart([&](Dart d) { out += "  " + std::to_string(d) + ";\n"; });
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    std::string attrs = "color=" + dimension_colour(i);
    if (i >= 8) attrs += ", label=\"" + std::to_string(i) + "\"";
    const bool invol = g.is_involutive_dim(i);
    g.for_each_dart([&](Dart d) {
      const Dart e = g.alpha(i, d);
      std::string a = attrs;
      if (e == d && !opt.loops) return;
      if (invol && e != d) {
        const bool reciprocated = e < g.capacity() && g.alpha(i, e) == d;
        if (reciprocated && e < d) return;  // drawn from the smaller end
        a += reciprocated ? (directed ? ", dir=none" : "") : ", style=dashed, dir=forward";
      } else if (invol && directed) {
        a += ", dir=none";
      }
      out += "  " + std::to_string(d) + arc + std::to_string(e) + " [" + a + "];\n";
    });
  }
  out += "}\n";
  return out;
}

}  // namespace gmr::draw
