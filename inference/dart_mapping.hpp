// Mappings of preserved darts from a before map G to an after map H (thesis §7.1.2 and §7.3). A
// mapping is a set of dart pairs (g, h): dart g of G is preserved as dart h of H. It must be
// injective both ways. Three ways to give one:
//  * identity on dart ids: every dart id alive in both maps is paired with itself (the snapshot
//    mode of Jerboa Studio: one object edited in place, e.g. by the scheme engine, which keeps the
//    ids of preserved darts);
//  * explicit dart pairs;
//  * orbit pairs: (g, h, <o>, <o'>) pairs the <o>-orbit of g in G with the <o'>-orbit of h in H
//    through orbit isomorphism (thesis Alg. 5, positional relabeling <o> -> <o'>).
//
// File format "gmr.mapping" (version 1):
//   {
//     "format": "gmr.mapping", "version": 1,
//     "pairs":  [[0, 0], [5, 11]],                            optional: dart pairs [before, after]
//     "orbits": [{"before": 3, "after": 7, "orbit": "<0,1>",   optional: orbit pairs; "after_orbit"
//                 "after_orbit": "<0,1>"}],                    defaults to "orbit"
//     "before_selection": [0, 1],                              optional: the darts in scope
//     "after_selection": [0, 1, 8, 9]
//   }
// Selections (thesis §7.1.2, local operations): when a side has one, only its selected darts enter
// the joint graph, and a link to an unselected dart becomes an undefined neighbour (folding then
// leaves that dimension out of the rule at that node, all or none). Mapped darts must be selected.
// Readers report the first problem by JSON path (Error(Schema)); pairs are validated against the
// two maps (live darts, injectivity both ways, isomorphic orbits).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "inference/joint_graph.hpp"
#include "model/core/map.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr::inference {

struct OrbitPair {
  Dart before = 0, after = 0;
  OrbitType orbit, after_orbit;
};

struct DartMapping {
  std::vector<std::pair<Dart, Dart>> pairs;
  std::vector<OrbitPair> orbits;
  std::optional<std::vector<Dart>> before_selection, after_selection;
};

// Every dart id alive in both maps, paired with itself.
DartMapping identity_mapping(const Map& before, const Map& after);

DartMapping parse_mapping(std::string_view text, const std::string& source = {});
DartMapping read_mapping_file(const std::filesystem::path& path);
std::string mapping_to_json_text(const DartMapping& m);

// The dart pairs of m, orbit pairs expanded by Alg. 5, sorted by before dart. Throws Error(Schema)
// (located "pairs[k]" / "orbits[k]") for a dead dart, a dart paired twice on either side, or
// orbits that are not isomorphic.
std::vector<std::pair<Dart, Dart>> expand_mapping(const Map& before, const Map& after,
                                                  const DartMapping& m);

// κ(G, H) (thesis Def. 36 on maps): the (selected) darts of G on side L, then those of H on side R,
// links copied (undefined towards unselected darts), one κ-link per mapped pair. Both maps must be
// G-maps of the same dimension. Throws Error(Schema) for a selected dart that does not exist or a
// mapped dart that is not selected ("before_selection[k]", "pairs[k]").
JointGraph joint_from_pair(const Map& before, const Map& after, const DartMapping& m,
                           JointIndex* index = nullptr);

}  // namespace gmr::inference
