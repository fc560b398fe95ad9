// DOT (Graphviz) text of rules, in the conventions of the papers: the left- and
// right-hand sides side by side as two clusters "L" and "R", arcs coloured per dimension with
// dimension_colour (io_dot.hpp: 0 black, 1 red, 2 blue, 3 green, ...).
//
// Concrete rules (model/rule.hpp): nodes are labelled by their name; two opposite i-arcs of one
// side are drawn as one undirected edge, any other arc (O-map beta_1, an unpaired arc) as a
// directed edge; a loop is drawn as a loop. Optional κ arcs of the joint representation (Def. 36):
// one pink dashed arc from every preserved L node to its R node.
// Rule schemes (model/rule_scheme.hpp): node labels "n0 <_,1,2>" (node_label_text), explicit arcs
// (undirected, loops drawn) coloured per dimension, hooks with a double border (peripheries=2).
//
// Node roles, on both kinds: preserved nodes have a solid border, deleted nodes (L only) a dashed
// border, added nodes (R only) a bold border; deleted and added arcs are drawn thicker
// (penwidth=2.5) than preserved ones.
//
// Diagnostics overlay: each DotHighlight names a node (by side and name) and a text; the node is
// filled (errors light red, warnings light orange), gets "code: message" lines as tooltip (shown by
// SVG viewers), and a note node "<id>_note" (shape=note) listing the codes is attached to it. The
// conversion from checker reports is in checker/dot_overlay.hpp (the model does not depend on the
// checker).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::draw {
using graph::Side;
using rewrite::Rule;
using scheme::RuleScheme;

struct DotHighlight {
  std::optional<Side> side;  // nullopt: a node of that name on either side
  std::string node;          // node name
  std::string code;          // short text shown in the note next to the node, e.g. "I-added-node"
  std::string message;       // tooltip
  bool error = true;         // false: warning colour
};

struct RuleDotOptions {
  bool kappa = false;  // concrete rules: draw the κ arcs of the joint representation
  std::string name;    // graph name; default: the rule's name, else "rule"
  std::vector<DotHighlight> highlights;
};

// Fill colours of highlighted nodes.
inline constexpr const char* kDotErrorFill = "#ff9c9c";
inline constexpr const char* kDotWarningFill = "#ffd58a";
inline constexpr const char* kDotKappaColour = "pink";

std::string to_dot(const Rule& r, const RuleDotOptions& opt = {});
std::string to_dot(const RuleScheme& s, const RuleDotOptions& opt = {});

}  // namespace gmr::draw
