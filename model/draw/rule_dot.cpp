#include "model/draw/rule_dot.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "model/draw/map_dot.hpp"

namespace gmr::draw {
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::scheme;

namespace {

std::string quote(const std::string& s) { return nlohmann::json(s).dump(); }

std::string node_id(Side side, size_t v) { return to_string(side) + std::to_string(v); }
std::string node_id(Side side, Node v) { return node_id(side, v.index()); }

std::string graph_header(const std::string& kind, const std::string& name,
                         const RuleDotOptions& opt, int n) {
  std::string out =
      "digraph " +
      quote(opt.name.empty() ? (name.empty() ? std::string("rule") : name) : opt.name) + " {\n";
  out += "  // gmr " + kind + " " + quote(name) + ", dimension " + std::to_string(n) +
         "; arcs coloured per dimension: 0 black, 1 red, 2 blue, 3 green, 4 orange, 5 purple, 6 "
         "brown, 7 cyan, "
         "8+ gray; deleted nodes dashed, added nodes bold, hooks double-bordered, kappa arcs pink "
         "dashed\n";
  out += "  compound=true;\n  node [fontsize=10];\n  edge [arrowsize=0.6];\n";
  return out;
}

// A node statement: role, hook, highlights. A highlighted node is filled, its tooltip lists
// "code: message" lines, and a note node (shape=note, the codes) is attached to it by a dotted
// edge: Graphviz places xlabels poorly in clusters, a note stays next to its node.
std::string node_stmt(const std::string& id, const std::string& label, Side side,
                      const std::string& name, ElemStatus role, bool hook,
                      const std::vector<DotHighlight>& hl) {
  std::vector<std::string> style;
  std::string a = "label=" + quote(label);
  if (role == ElemStatus::Deleted) style.push_back("dashed");
  if (role == ElemStatus::Added) style.push_back("bold");
  if (hook) a += ", peripheries=2";
  std::string codes, messages;
  bool any = false, error = false;
  for (const auto& h : hl) {
    if (h.node != name || (h.side && *h.side != side)) continue;
    any = true;
    error = error || h.error;
    if (!h.code.empty() && ("\n" + codes + "\n").find("\n" + h.code + "\n") == std::string::npos)
      codes += (codes.empty() ? "" : "\n") + h.code;
    const std::string line = h.code.empty()      ? h.message
                             : h.message.empty() ? h.code
                                                 : h.code + ": " + h.message;
    messages += (messages.empty() ? "" : "\n") + line;
  }
  std::string note;
  if (any) {
    style.push_back("filled");
    a += std::string(", fillcolor=\"") + (error ? kDotErrorFill : kDotWarningFill) + "\"";
    a += ", tooltip=" + quote(messages);
    if (!codes.empty())
      note = "    " + id +
             "_note [shape=note, fontsize=8, fontcolor=darkred, color=gray, label=" + quote(codes) +
             "];\n    " + id + " -> " + id +
             "_note [style=dotted, color=gray, dir=none, arrowhead=none];\n";
  }
  if (!style.empty()) {
    std::string st;
    for (const auto& x : style) st += (st.empty() ? "" : ",") + x;
    a += ", style=\"" + st + "\"";
  }
  return "    " + id + " [" + a + "];\n" + note;
}

std::string arc_attrs(int dim, bool changed) {
  std::string a = "color=" + dimension_colour(dim);
  if (dim >= 8) a += ", label=\"" + std::to_string(dim) + "\"";
  if (changed) a += ", penwidth=2.5";
  return a;
}

std::string cluster_open(Side side) {
  return std::string("  subgraph cluster_") + to_string(side) + " {\n    label=\"" +
         to_string(side) + "\";\n    color=gray;\n";
}

}  // namespace

std::string to_dot(const Rule& r, const RuleDotOptions& opt) {
  std::string out = graph_header(
      std::string("concrete ") + (r.kind() == MapKind::OMap ? "O-map" : "G-map") + " rule",
      r.name(), opt, r.dimension());
  out += "  node [shape=circle, width=0.4];\n";
  for (Side side : kSides) {
    const DGraph& g = r.side(side);
    out += cluster_open(side);
    for (Node v : g.nodes())
      out += node_stmt(node_id(side, v), g.node_str(v), side, g.name(v), r.node_status(side, v),
                       false, opt.highlights);
    // Opposite arcs of one label are drawn as one undirected edge; the others are directed.
    HandleVector<ArcId, bool> drawn(g.num_arc_slots(), false);
    for (ArcId a : g.arc_slots()) {
      if (!g.arc_alive(a) || drawn[a]) continue;
      drawn[a] = true;
      const Arc& arc = g.arc(a);
      const bool changed = r.arc_status(side, a) != ElemStatus::Preserved;
      std::string attrs = arc_attrs(arc.label, changed);
      bool paired = arc.src == arc.tgt;
      if (!paired) {
        for (ArcId b : g.out_arcs(arc.tgt)) {
          if (b == a || drawn[b] || !g.arc_alive(b)) continue;
          const Arc& rev = g.arc(b);
          if (rev.tgt == arc.src && rev.label == arc.label) {
            drawn[b] = true;
            paired = true;
            break;
          }
        }
      }
      if (paired) attrs += ", dir=none";
      out +=
          "    " + node_id(side, arc.src) + " -> " + node_id(side, arc.tgt) + " [" + attrs + "];\n";
    }
    out += "  }\n";
  }
  if (opt.kappa)
    for (Node v : r.left().nodes())
      if (auto w = r.right_of(v))
        out += "  " + node_id(Side::L, v) + " -> " + node_id(Side::R, *w) +
               " [color=" + kDotKappaColour +
               ", style=dashed, constraint=false, label=<&kappa;>, fontcolor=" + kDotKappaColour +
               "];\n";
  out += "}\n";
  return out;
}

std::string to_dot(const RuleScheme& s, const RuleDotOptions& opt) {
  std::string out = graph_header("rule scheme " + s.orbit.str(), s.name, opt, s.dimension);
  out += "  node [shape=ellipse];\n  edge [dir=none];\n";
  std::vector<bool> hook(s.left.size(), false);
  for (const auto& h : s.hooks)
    if (auto v = s.left.find(h)) hook[*v] = true;
  for (Side side : kSides) {
    const bool right = side == Side::R;
    const GraphScheme& g = right ? s.right : s.left;
    out += cluster_open(side);
    for (uint32_t v = 0; v < g.size(); ++v) {
      const NodeRole role = right ? s.role_right(v) : s.role_left(v);
      out += node_stmt(node_id(side, v), node_label_text(g.nodes[v]), side, g.nodes[v].name, role,
                       !right && hook[v], opt.highlights);
    }
    const GraphScheme& other = right ? s.left : s.right;
    for (const SchemeArc& arc : g.arcs) {
      // An explicit arc is preserved when both ends are preserved and the other side has it too.
      bool kept = false;
      const auto oa = other.find(g.nodes[arc.a].name), ob = other.find(g.nodes[arc.b].name);
      if (oa && ob)
        kept = std::any_of(other.arcs.begin(), other.arcs.end(), [&](const SchemeArc& x) {
          return x.dim == arc.dim && ((x.a == *oa && x.b == *ob) || (x.a == *ob && x.b == *oa));
        });
      out += "    " + node_id(side, arc.a) + " -> " + node_id(side, arc.b) + " [" +
             arc_attrs(arc.dim, !kept) + "];\n";
    }
    out += "  }\n";
  }
  out += "}\n";
  return out;
}

}  // namespace gmr::draw
