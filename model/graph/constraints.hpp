// The three local constraints of the thesis on a D-graph (Defs. 29–31), checkable per node and per
// label, each violation a ConstraintViolation located at a node
// (model/core/constraint_violation.hpp; its message says what is wrong, its path holds the
// offending arcs' ends or ijij-path).
//   I_G(i): v is the source of a unique i-arc and the target of a unique i-arc;
//   O_G(i): every i-arc incident to v has a reverse;
//   C_G(i,j): v is the source of an ijij-cycle.
// Combinatorial graphs, G-maps and O-maps (Def. 32) are checked by `check_map_constraints`.
#pragma once
#include <string>
#include <vector>

#include "model/core/constraint_violation.hpp"
#include "model/graph/dgraph.hpp"

namespace gmr::graph {

// A violation located on g, nodes named by g.node_str:
// "incident-arcs I(2) at node a: no outgoing 2-arc [path ...]". For C, the path is the longest
// ijij-prefix found from the node.
std::string to_text(const ConstraintViolation& v, const DGraph& g);

std::vector<ConstraintViolation> check_incident_arcs(const DGraph& g, Node v, int i);
std::vector<ConstraintViolation> check_non_orientation(const DGraph& g, Node v, int i);
std::vector<ConstraintViolation> check_cycle(const DGraph& g, Node v, int i, int j);

// Def. 32 on the whole graph: kind G (labels 0..n, I, O on all, C on (0..n)_{+2}) or O (labels
// 1..n, I on all, O on 2..n, C on (1..n)_{+2}). Also reports arcs whose label is outside the set.
std::vector<ConstraintViolation> check_map_constraints(const DGraph& g, int n, MapKind kind);

}  // namespace gmr::graph
