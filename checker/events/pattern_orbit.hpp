// Orbits inside the patterns of a rule scheme (Gaide et al. 2023, §2.2): X<o>(n), for a side X (L
// or R) and an orbit type <o>, is the set of nodes of X reachable from n through explicit arcs
// labelled in <o>, with those arcs and the nodes' implicit links labelled in <o>. Implicit links
// never join two nodes, so the pattern orbits of one side are the connected components of its
// explicit <o>-arcs.
//
// Completeness (§2.2): X<o>(n) is complete when every node m of it has, for every i in <o>, an
// explicit i-arc (a loop counts) or a label position k with λ_k(m) = i. An instance of a complete
// pattern orbit on the hook orbit is a whole orbit of the map (of G for L, of H for R); an
// incomplete one may be part of a larger orbit. The paper states "entirely matched iff complete";
// only "if" holds (a loop of the map can close an incomplete pattern orbit), so an incomplete
// pattern orbit is read as "unknown", never as "partial".
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/orbit_type.hpp"
#include "model/graph/elem_status.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::events {

using graph::Side;

// The pattern orbits of one side for one orbit type.
struct PatternOrbits {
  Side side = Side::L;
  DimMask orbit = 0;                         // the analysed orbit type <o>
  std::vector<uint32_t> class_of;            // node index -> pattern orbit index
  std::vector<std::vector<uint32_t>> nodes;  // pattern orbit -> its nodes (increasing)
  std::vector<bool> complete;                // pattern orbit -> completeness
  // Label positions k whose dimension λ_k(m) lies in <o> for some node m of the pattern orbit
  // (the positions along which its instance spans the hook orbit).
  std::vector<std::vector<uint32_t>> positions;
  size_t size() const { return nodes.size(); }
};

// True when node m of `side` has an i-link in the pattern: an explicit i-arc or an implicit one.
bool has_link(const scheme::GraphScheme& side, uint32_t m, int i);

// The pattern orbits of `side` for <o> (Gaide et al. §2.2).
PatternOrbits pattern_orbits(const scheme::GraphScheme& side, Side which, DimMask o);

}  // namespace gmr::events
