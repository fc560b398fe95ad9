#include "model/replace/configurations.hpp"

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/replace/edge_split.hpp"

namespace gmr::replace {

namespace {

// Every non-empty subset of `edges` (one dart per edge) split in 2 on a copy of `base`.
ConfigurationSet subsets(std::string name, int cell_dim, const GMap& base, const std::vector<Dart>& edges) {
  ConfigurationSet set;
  set.generator = std::move(name);
  set.cell_dim = cell_dim;
  const size_t k = edges.size();
  for (uint32_t mask = 1; mask < (1u << k); ++mask) {
    Configuration c;
    c.map.map = base;
    c.map.flag.assign(base.capacity(), 1);
    for (size_t e = 0; e < k; ++e)
      if (mask >> e & 1) {
        c.split.push_back(static_cast<int>(e));
        split_edge(c.map, edges[e], 2);
      }
    set.configurations.push_back(std::move(c));
  }
  return set;
}

// The edges of the polygon of dart 0 in cyclic order: one dart each, alpha_1 then alpha_0 steps.
std::vector<Dart> polygon_edges(const GMap& g) {
  std::vector<Dart> edges;
  Dart d = 0;
  do {
    edges.push_back(d);
    d = g.alpha(1, g.alpha(0, d));
  } while (d != 0);
  return edges;
}

}  // namespace

std::vector<std::string> configuration_generators() { return {"square-edges", "triangle-edges", "hex-edges"}; }

std::vector<std::array<int, 2>> cube_edges() {
  std::vector<std::array<int, 2>> e;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      if (__builtin_popcount(static_cast<unsigned>(a ^ b)) == 1) e.push_back({a, b});
  return e;
}

ConfigurationSet generate_configurations(std::string_view generator) {
  if (generator == "square-edges" || generator == "triangle-edges") {
    const GMap g = make_polygon(generator == "square-edges" ? 4 : 3);
    return subsets(std::string(generator), 2, g, polygon_edges(g));
  }
  if (generator == "hex-edges") {
    std::vector<uint32_t> vertex;
    const GMap g = surface_from_faces({{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}},
                                      8, {}, &vertex);
    std::vector<Dart> edges;
    for (const auto& [a, b] : cube_edges()) {
      Dart found = kNoDart;
      g.for_each_dart([&](Dart d) {
        if (found == kNoDart && vertex[d] == uint32_t(a) && vertex[g.alpha(0, d)] == uint32_t(b)) found = d;
      });
      edges.push_back(found);
    }
    return subsets("hex-edges", 3, g, edges);
  }
  std::string known;
  for (const auto& n : configuration_generators()) known += (known.empty() ? "" : ", ") + n;
  throw Error(ErrorCode::Usage, "unknown configuration generator \"" + std::string(generator) + "\" (known: " + known + ")",
              "--configurations");
}

}  // namespace gmr::replace
