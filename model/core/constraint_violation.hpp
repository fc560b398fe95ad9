// A constraint of the model broken at a place: the one vocabulary of violations shared by the
// validity of maps (validity.hpp, places are darts), the D-graph constraints
// (model/graph/constraints.hpp, places are nodes) and the checkers' diagnostics
// (checker/diagnostic.hpp, whose conditions on I, O and C are named by `symbol`).
//
// The local constraints of the thesis (Defs. 29–31), at a node v of a D-graph or a dart of a map:
//   I(i)    incident arcs: v is the source of a unique i-arc and the target of a unique i-arc
//           (a link to a dart; beta_1 of an O-map a permutation);
//   O(i)    non-orientation: every i-arc incident to v has a reverse (alpha_i an involution);
//   C(i,j)  cycle: v is the source of an ijij-cycle.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gmr {

enum class Constraint : uint8_t { IncidentArcs, NonOrientation, Cycle };

const char* to_text(Constraint c);  // "incident-arcs", "non-orientation", "cycle"
const char* symbol(Constraint c);   // "I", "O", "C"

// A condition with its dimensions in the thesis' notation: "I(2)", "C(0,2)"; the name alone when
// i < 0, the name and i when j < 0.
std::string condition_text(std::string_view name, int i, int j = -1);

// Built with designated initializers: {.constraint = Constraint::Cycle, .at = d, .i = 0, .j = 2}.
struct ConstraintViolation {
  Constraint constraint{};
  // The dart (map) or the node's index (D-graph, graph::Node::index) where the local constraint
  // fails; `path` names darts or node indices alike.
  uint32_t at{};
  int i = -1, j = -1;            // dimension(s)
  std::vector<uint32_t> path{};  // the offending darts or nodes (a path from `at` for C)
  std::string message{};  // what is broken: "no outgoing 2-arc", "alpha_2 is not an involution..."
};

// A violation located on a map, darts named by their index:
// "non-orientation at dart 3: alpha_2 is not an involution: 3 -> 4 -> 5".
std::string to_text(const ConstraintViolation& v);

}  // namespace gmr
