// The three local constraints of the thesis on a D-graph (Defs. 29–31), checkable per node and per
// label, each violation located (node, label(s), offending arcs or path).
//   I_G(i): v is the source of a unique i-arc and the target of a unique i-arc;
//   O_G(i): every i-arc incident to v has a reverse;
//   C_G(i,j): v is the source of an ijij-cycle.
// Combinatorial graphs, G-maps and O-maps (Def. 32) are checked by `check_gmap_constraints`.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "model/graph/dgraph.hpp"

namespace gmr::graph {

enum class ConstraintKind { IncidentArcs, NonOrientation, Cycle };
const char* to_string(ConstraintKind k);

struct ConstraintViolation {
  ConstraintKind kind;
  Node node;
  int i = -1, j = -1;
  std::string what;          // "no outgoing 2-arc", "2 incoming 1-arcs", "arc a->b has no reverse", ...
  std::vector<Node> path;    // offending path (for cycle: the longest ijij prefix found from node)
  std::string describe(const DGraph& g) const;
};

std::vector<ConstraintViolation> check_incident_arcs(const DGraph& g, Node v, int i);
std::vector<ConstraintViolation> check_non_orientation(const DGraph& g, Node v, int i);
std::vector<ConstraintViolation> check_cycle(const DGraph& g, Node v, int i, int j);

// Def. 32 on the whole graph: kind G (labels 0..n, I, O on all, C on (0..n)_{+2}) or O (labels
// 1..n, I on all, O on 2..n, C on (1..n)_{+2}). Also reports arcs whose label is outside the set.
std::vector<ConstraintViolation> check_gmap_constraints(const DGraph& g, int n, MapKind kind);

}  // namespace gmr::graph
