#include "model/rewrite/dpo.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "model/core/error.hpp"

namespace gmr::rewrite {
using namespace gmr::graph;

std::string DanglingArc::describe(const Rule& r, const DGraph& G) const {
  const Arc& e = G.arc(g_arc);
  return "deleted node " + r.left().node_str(l_node) +
         " is matched to a node incident to the unmatched arc " + G.node_str(e.src) + " -" +
         std::to_string(e.label) + "-> " + G.node_str(e.tgt) + " (dangling condition)";
}

void check_match(const Rule& r, const DGraph& G, const Match& m) {
  const DGraph& L = r.left();
  if (m.node.size() != L.num_nodes() || m.arc.size() != L.num_arc_slots())
    throw Error(ErrorCode::Usage, "match size does not fit the left-hand side", "match");
  HandleVector<Node, bool> used(G.num_nodes(), false);
  for (Node v : L.nodes()) {
    const Node g = m.node[v];
    if (g.index() >= G.num_nodes())
      throw Error(ErrorCode::Usage, "image is not a node of G", "match of " + L.node_str(v));
    if (used[g])
      throw Error(ErrorCode::Usage, "match is not injective on nodes", "match of " + L.node_str(v));
    used[g] = true;
  }
  HandleVector<ArcId, bool> aused(G.num_arc_slots(), false);
  for (ArcId a : L.arc_slots()) {
    if (!L.arc_alive(a)) continue;
    const ArcId b = m.arc[a];
    const std::string loc = "match of arc " + r.arc_str(Side::L, a);
    if (b.index() >= G.num_arc_slots() || !G.arc_alive(b))
      throw Error(ErrorCode::Usage, "image is not an arc of G", loc);
    if (aused[b]) throw Error(ErrorCode::Usage, "match is not injective on arcs", loc);
    aused[b] = true;
    const Arc &e = L.arc(a), &f = G.arc(b);
    if (f.label != e.label || f.src != m.node[e.src] || f.tgt != m.node[e.tgt])
      throw Error(ErrorCode::Usage, "match does not preserve the ends or the label of the arc",
                  loc);
  }
}

std::vector<DanglingArc> dangling_arcs(const Rule& r, const DGraph& G, const Match& m) {
  HandleVector<ArcId, bool> matched(G.num_arc_slots(), false);
  for (ArcId b : m.arc)
    if (b != kNoArc) matched[b] = true;
  std::vector<DanglingArc> out;
  for (Node v : r.deleted_nodes()) {
    const Node g = m.node[v];
    for (ArcId b : G.out_arcs(g))
      if (!matched[b]) out.push_back({v, b});
    for (ArcId b : G.in_arcs(g))
      if (!matched[b] && G.arc(b).src != g) out.push_back({v, b});  // a loop is listed once
  }
  return out;
}

namespace {

void require_gluing(const Rule& r, const DGraph& G, const Match& m) {
  check_match(r, G, m);
  auto d = dangling_arcs(r, G, m);
  if (!d.empty())
    throw Error(ErrorCode::Usage, "the match violates the gluing condition: " + d[0].describe(r, G),
                "match of " + r.left().node_str(d[0].l_node));
}

// Deleted nodes and arcs of G (images of L \ L∩R).
void deleted_images(const Rule& r, const DGraph& G, const Match& m, HandleVector<Node, bool>& dn,
                    HandleVector<ArcId, bool>& da) {
  dn.assign(G.num_nodes(), false);
  da.assign(G.num_arc_slots(), false);
  for (Node v : r.deleted_nodes()) dn[m.node[v]] = true;
  const DGraph& L = r.left();
  for (ArcId a : L.arc_slots())
    if (L.arc_alive(a) && r.left_arc_status(a) == ElemStatus::Deleted) da[m.arc[a]] = true;
}

std::string added_name(const DGraph& R, Node v) { return R.node_str(v) + "'"; }

Derivation derive_categorical(const Rule& r, const DGraph& G, const Match& m) {
  require_gluing(r, G, m);
  HandleVector<Node, bool> dn;
  HandleVector<ArcId, bool> da;
  deleted_images(r, G, m, dn, da);
  Derivation out;
  // Pushout complement D with the inclusion D -> G.
  HandleVector<Node, Node> g_to_d(G.num_nodes(), kNoNode);
  for (Node g : G.nodes())
    if (!dn[g]) {
      g_to_d[g] = out.D.add_node(G.name(g));
      out.d_to_g.push_back(g);
    }
  HandleVector<ArcId, ArcId> garc_to_d(G.num_arc_slots(), kNoArc);
  for (ArcId b : G.arc_slots())
    if (G.arc_alive(b) && !da[b])
      garc_to_d[b] = out.D.add_arc(g_to_d[G.arc(b).src], g_to_d[G.arc(b).tgt], G.arc(b).label);
  // Pushout of D <- L∩R -> R: the K-part of R is glued on D through m (k |-> g_to_d(m(k))).
  out.H = out.D;
  out.g_to_h = g_to_d;  // H starts as a copy of D, same ids
  const DGraph& R = r.right();
  out.comatch.assign(R.num_nodes(), kNoNode);
  for (Node v : R.nodes()) {
    if (auto l = r.left_of(v))
      out.comatch[v] = g_to_d[m.node[*l]];
    else
      out.comatch[v] = out.H.add_node(added_name(R, v));
  }
  out.comatch_arc.assign(R.num_arc_slots(), kNoArc);
  for (ArcId a : R.arc_slots()) {
    if (!R.arc_alive(a)) continue;
    if (auto l = r.left_arc_of(a))
      out.comatch_arc[a] = garc_to_d[m.arc[*l]];
    else
      out.comatch_arc[a] =
          out.H.add_arc(out.comatch[R.arc(a).src], out.comatch[R.arc(a).tgt], R.arc(a).label);
  }
  return out;
}

Derivation derive_rewriting(const Rule& r, const DGraph& G, const Match& m) {
  require_gluing(r, G, m);
  HandleVector<Node, bool> dn;
  HandleVector<ArcId, bool> da;
  deleted_images(r, G, m, dn, da);
  DGraph W = G;  // work copy: same node and arc ids as G
  for (ArcId b : G.arc_slots())
    if (da[b]) W.remove_arc(b);
  const DGraph& R = r.right();
  HandleVector<Node, Node> co(R.num_nodes(), kNoNode);
  for (Node v : R.nodes()) {
    if (auto l = r.left_of(v))
      co[v] = m.node[*l];
    else
      co[v] = W.add_node(added_name(R, v));
  }
  HandleVector<ArcId, ArcId> coa(R.num_arc_slots(), kNoArc);
  for (ArcId a : R.arc_slots()) {
    if (!R.arc_alive(a)) continue;
    if (auto l = r.left_arc_of(a))
      coa[a] = m.arc[*l];
    else
      coa[a] = W.add_arc(co[R.arc(a).src], co[R.arc(a).tgt], R.arc(a).label);
  }
  // Compaction: fill each hole left by a deleted node with the last live node.
  HandleVector<Node, bool> dead(W.num_nodes(), false);
  for (Node g : G.nodes()) dead[g] = dn[g];
  HandleVector<Node, Node> newid(W.num_nodes(), kNoNode);
  for (Node v : W.nodes()) newid[v] = v;
  Node end(static_cast<uint32_t>(W.num_nodes()));
  auto pop_dead_tail = [&] {
    while (end > Node(0) && dead[Node(end.index() - 1)]) end = Node(end.index() - 1);
  };
  pop_dead_tail();
  for (Node h(0); h < end; ++h) {
    if (!dead[h]) continue;
    const Node last(end.index() - 1);
    newid[last] = h;
    newid[h] = kNoNode;
    dead[h] = false;  // the hole is filled
    dead[last] = true;
    end = last;
    pop_dead_tail();
  }
  for (Node v : W.nodes())
    if (v >= end && newid[v] >= end) newid[v] = kNoNode;
  for (Node g : G.nodes())
    if (dn[g]) newid[g] = kNoNode;
  Derivation out;
  HandleVector<Node, Node> order(end.index(), kNoNode);
  for (Node v : W.nodes())
    if (newid[v] != kNoNode) order[newid[v]] = v;
  for (Node k : order.handles()) out.H.add_node(W.name(order[k]));
  HandleVector<ArcId, ArcId> newarc(W.num_arc_slots(), kNoArc);
  for (ArcId b : W.arc_slots())
    if (W.arc_alive(b))
      newarc[b] = out.H.add_arc(newid[W.arc(b).src], newid[W.arc(b).tgt], W.arc(b).label);
  out.g_to_h.assign(G.num_nodes(), kNoNode);
  for (Node g : G.nodes()) out.g_to_h[g] = newid[g];
  out.comatch.assign(R.num_nodes(), kNoNode);
  for (Node v : R.nodes()) out.comatch[v] = newid[co[v]];
  out.comatch_arc.assign(R.num_arc_slots(), kNoArc);
  for (ArcId a : R.arc_slots())
    if (coa[a] != kNoArc) out.comatch_arc[a] = newarc[coa[a]];
  return out;
}

}  // namespace

Derivation derive(const Rule& r, const DGraph& G, const Match& m, Construction c) {
  return c == Construction::Categorical ? derive_categorical(r, G, m) : derive_rewriting(r, G, m);
}

bool same_derivation(const Derivation& a, const Derivation& b, std::string* why) {
  auto fail = [&](const std::string& s) {
    if (why) *why = s;
    return false;
  };
  if (a.H.num_nodes() != b.H.num_nodes()) return fail("different node counts");
  if (a.g_to_h.size() != b.g_to_h.size() || a.comatch.size() != b.comatch.size())
    return fail("different tracks");
  HandleVector<Node, Node> phi(a.H.num_nodes(), kNoNode);
  auto set = [&](Node x, Node y) {
    if (x == kNoNode || y == kNoNode) return x == y;
    if (x.index() >= phi.size() || y.index() >= b.H.num_nodes()) return false;
    if (phi[x] != kNoNode) return phi[x] == y;
    phi[x] = y;
    return true;
  };
  for (Node g : a.g_to_h.handles())
    if (!set(a.g_to_h[g], b.g_to_h[g]))
      return fail("G node " + std::to_string(g.index()) + " tracked differently");
  for (Node v : a.comatch.handles())
    if (!set(a.comatch[v], b.comatch[v]))
      return fail("comatch differs on R node " + std::to_string(v.index()));
  HandleVector<Node, bool> hit(b.H.num_nodes(), false);
  for (Node x : phi.handles()) {
    if (phi[x] == kNoNode)
      return fail("H node " + a.H.node_str(x) + " is neither tracked from G nor in the comatch");
    if (hit[phi[x]]) return fail("two nodes sent to one");
    hit[phi[x]] = true;
  }
  std::map<std::tuple<Node, Node, int>, long> arcs;
  for (ArcId e : a.H.arc_slots())
    if (a.H.arc_alive(e)) ++arcs[{phi[a.H.arc(e).src], phi[a.H.arc(e).tgt], a.H.arc(e).label}];
  for (ArcId e : b.H.arc_slots())
    if (b.H.arc_alive(e)) --arcs[{b.H.arc(e).src, b.H.arc(e).tgt, b.H.arc(e).label}];
  for (auto& [k, c] : arcs)
    if (c != 0) return fail("arc multisets differ");
  if (a.comatch_arc.size() != b.comatch_arc.size()) return fail("different arc comatches");
  for (ArcId e : a.comatch_arc.handles()) {
    if ((a.comatch_arc[e] == kNoArc) != (b.comatch_arc[e] == kNoArc))
      return fail("arc comatch differs");
    if (a.comatch_arc[e] == kNoArc) continue;
    const Arc &x = a.H.arc(a.comatch_arc[e]), &y = b.H.arc(b.comatch_arc[e]);
    if (phi[x.src] != y.src || phi[x.tgt] != y.tgt || x.label != y.label)
      return fail("arc comatch differs");
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Maps.

namespace {

void check_rule_fits_map(const Rule& r, const Map& g) {
  if (r.kind() != g.kind())
    throw Error(
        ErrorCode::Usage,
        std::string("a ") + to_string(r.kind()) + " rule applied to a " + to_string(g.kind()),
        "rule");
  if (r.dimension() > g.dimension())
    throw Error(ErrorCode::Usage,
                "rule of dimension " + std::to_string(r.dimension()) +
                    " applied to a map of dimension " + std::to_string(g.dimension()),
                "rule");
}

}  // namespace

std::vector<std::vector<Dart>> find_map_matches(const Rule& r, const Map& g, size_t limit) {
  check_rule_fits_map(r, g);
  const DGraph dg = to_dgraph(g);
  const auto darts = g.darts();
  std::vector<std::vector<Dart>> out;
  if (limit == 0) return out;
  for_each_match(r.left(), dg, [&](const Match& m) {
    std::vector<Dart> mm;
    for (Node v : m.node) mm.push_back(darts[v.index()]);
    out.push_back(std::move(mm));
    return out.size() < limit;
  });
  return out;
}

namespace {

MapDerivation apply_categorical(const Rule& r, const Map& g, const std::vector<Dart>& match) {
  check_rule_fits_map(r, g);
  const DGraph dg = to_dgraph(g);
  const auto darts = g.darts();
  std::vector<Node> node_at(g.capacity(), kNoNode);  // to_dgraph numbers the live darts in order
  for (size_t k = 0; k < darts.size(); ++k) node_at[darts[k]] = Node(static_cast<uint32_t>(k));
  NodeMap nm;
  for (Dart d : match) {
    if (!g.alive(d))
      throw Error(ErrorCode::Usage, "match on a dart that does not exist",
                  "dart " + std::to_string(d));
    nm.push_back(node_at[d]);
  }
  auto m = match_from_nodes(r.left(), dg, nm);
  if (!m)
    throw Error(ErrorCode::Usage,
                "the node map is not a match of the left-hand side (injective, label-preserving)",
                "match");
  Derivation der = derive_categorical(r, dg, *m);
  // H must be combinatorial to be stored as a map (I_H on every label).
  for (Node v : der.H.nodes())
    for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
      if (der.H.predecessors(v, i).size() != 1 || der.H.successors(v, i).size() != 1)
        throw Error(
            ErrorCode::InvalidMap,
            "the result is not combinatorial: incident arcs I(" + std::to_string(i) + ") fails",
            "node " + der.H.node_str(v));
  MapDerivation out;
  out.H = to_map(der.H, g.dimension(), g.kind());
  out.g_to_h.assign(g.capacity(), kNoDart);
  for (Node k : der.g_to_h.handles())
    out.g_to_h[darts[k.index()]] = der.g_to_h[k] == kNoNode ? kNoDart : dart_of(der.g_to_h[k]);
  for (Node v : der.comatch) out.comatch.push_back(dart_of(v));
  return out;
}

// The unique x with alpha_i(x) == d in a valid map; throws Error(InvalidMap) when there is none.
Dart predecessor(const Map& g, int i, Dart d) {
  if (g.is_involutive_dim(i)) {
    const Dart x = g.alpha(i, d);
    if (g.alpha(i, x) != d)
      throw Error(ErrorCode::InvalidMap,
                  "input map: alpha_" + std::to_string(i) + " is not an involution",
                  "dart " + std::to_string(d));
    return x;
  }
  Dart p = d;
  for (size_t k = 0; k <= g.capacity(); ++k) {
    if (g.alpha(i, p) == d) return p;
    p = g.alpha(i, p);
  }
  throw Error(ErrorCode::InvalidMap,
              "input map: beta_" + std::to_string(i) + " is not a permutation",
              "dart " + std::to_string(d));
}

// Phase 1: the match is injective and every L arc has its image; L has at most one arc per label
// at a node. Returns the L node matched to each dart of g (kNoNode elsewhere).
std::vector<Node> check_map_match(const Rule& r, const Map& g, const std::vector<Dart>& match) {
  const DGraph& L = r.left();
  std::vector<Node> lnode_of(g.capacity(), kNoNode);
  for (Node v : L.nodes()) {
    const Dart d = match[v.index()];
    if (!g.alive(d))
      throw Error(ErrorCode::Usage, "match on a dart that does not exist",
                  "match of " + L.node_str(v));
    if (lnode_of[d] != kNoNode)
      throw Error(ErrorCode::Usage, "match is not injective", "match of " + L.node_str(v));
    lnode_of[d] = v;
  }
  for (ArcId a : L.arc_slots()) {
    if (!L.arc_alive(a)) continue;
    const Arc& e = L.arc(a);
    if (g.alpha(e.label, match[e.src.index()]) != match[e.tgt.index()])
      throw Error(ErrorCode::Usage, "the arc has no image in the map",
                  "match of arc " + r.arc_str(Side::L, a));
  }
  // In a map each dart has one i-arc out; two arcs of L from one node with one label cannot both
  // be matched (injective on arcs): reject parallel duplicates.
  std::string where;
  if (!at_most_one_arc_per_label(L, &where))
    throw Error(ErrorCode::Usage, "left-hand side not combinatorial: no injective match into a map",
                "left " + where);
  return lnode_of;
}

// Phase 2, gluing (dangling condition): every i-arc at the image of a deleted node is the image of
// an L arc.
void check_map_gluing(const Rule& r, const Map& g, const std::vector<Dart>& match) {
  const DGraph& L = r.left();
  for (Node v : r.deleted_nodes()) {
    const Dart d = match[v.index()];
    for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
      const auto out_l = L.successors(v, i), in_l = L.predecessors(v, i);
      const Dart t = g.alpha(i, d), s = predecessor(g, i, d);
      if (out_l.empty() || match[out_l[0].index()] != t || in_l.empty() ||
          match[in_l[0].index()] != s)
        throw Error(ErrorCode::Usage,
                    "the match violates the gluing condition: the " + std::to_string(i) +
                        "-arcs of dart " + std::to_string(d) +
                        " are not all matched (dangling condition)",
                    "match of " + L.node_str(v));
    }
  }
}

// The out-link of a touched (dimension, dart) slot of H while the links are rewritten.
enum class SlotState {
  Unchanged,  // the link of G is kept
  Unset,      // the link was removed (deleted L arc, fresh dart) and not yet rewritten
  Rewritten,  // an added R arc set it
};
using Slot = std::pair<int, Dart>;  // (dimension, dart)

struct LinkRewrite {
  std::map<Slot, SlotState> out;    // touched out-links
  std::map<Slot, int> indeg_delta;  // change of the number of in-arcs
};

// Phase 4: removes the deleted L arcs and writes the added R arcs into H (at the comatch darts).
// Throws Error(InvalidMap) when an added arc would be a second out-arc of its label.
LinkRewrite rewrite_links(const Rule& r, Map& H, const std::vector<Dart>& match,
                          const std::vector<Dart>& comatch) {
  const DGraph &L = r.left(), &R = r.right();
  const int lo = H.lowest_dim(), n = H.dimension();
  LinkRewrite w;
  for (Node v : r.added_nodes())
    for (int i = lo; i <= n; ++i) {
      w.out[{i, comatch[v.index()]}] = SlotState::Unset;
      w.indeg_delta[{i, comatch[v.index()]}] =
          -1;  // a fresh dart starts with no in-arc (its loop is not an arc)
    }
  for (ArcId a : L.arc_slots()) {
    if (!L.arc_alive(a) || r.left_arc_status(a) != ElemStatus::Deleted) continue;
    const Arc& e = L.arc(a);
    w.out[{e.label, match[e.src.index()]}] = SlotState::Unset;
    --w.indeg_delta[{e.label, match[e.tgt.index()]}];
  }
  for (ArcId a : R.arc_slots()) {
    if (!R.arc_alive(a) || r.right_arc_status(a) != ElemStatus::Added) continue;
    const Arc& e = R.arc(a);
    const Dart s = comatch[e.src.index()], t = comatch[e.tgt.index()];
    SlotState& st = w.out[{e.label, s}];
    if (st != SlotState::Unset)
      throw Error(
          ErrorCode::InvalidMap,
          "the result is not combinatorial: two outgoing " + std::to_string(e.label) + "-arcs",
          "R node " + R.node_str(e.src));
    st = SlotState::Rewritten;
    H.set_alpha(e.label, s, t);
    ++w.indeg_delta[{e.label, t}];
  }
  return w;
}

// Phase 5: every surviving touched dart has exactly one out-arc and one in-arc per label
// (incident arcs on H); throws Error(InvalidMap) naming the first dart that fails.
void check_result_combinatorial(const Rule& r, const std::vector<Node>& lnode_of,
                                const LinkRewrite& w) {
  auto deleted_dart = [&](Dart d) {
    return lnode_of.size() > d && lnode_of[d] != kNoNode && !r.right_of(lnode_of[d]);
  };
  for (const auto& [k, st] : w.out)
    if (st == SlotState::Unset && !deleted_dart(k.second))
      throw Error(
          ErrorCode::InvalidMap,
          "the result is not combinatorial: no outgoing " + std::to_string(k.first) + "-arc",
          "dart " + std::to_string(k.second));
  for (const auto& [k, delta] : w.indeg_delta)
    if (delta != 0 && !deleted_dart(k.second))
      throw Error(ErrorCode::InvalidMap,
                  "the result is not combinatorial: " + std::to_string(1 + delta) + " incoming " +
                      std::to_string(k.first) + "-arcs",
                  "dart " + std::to_string(k.second));
}

// Phase 6: removes the darts of the deleted nodes (detached first: remove_dart must not touch live
// darts) and fills the dart track G -> H.
void remove_deleted_darts(const Rule& r, const Map& g, const std::vector<Dart>& match,
                          MapDerivation& out) {
  Map& H = out.H;
  out.g_to_h.assign(g.capacity(), kNoDart);
  g.for_each_dart([&](Dart d) { out.g_to_h[d] = d; });
  for (Node v : r.deleted_nodes()) {
    const Dart d = match[v.index()];
    for (int i = H.lowest_dim(); i <= H.dimension(); ++i) H.set_alpha(i, d, d);
    H.remove_dart(d);
    out.g_to_h[d] = kNoDart;
  }
}

MapDerivation apply_rewriting(const Rule& r, const Map& g, const std::vector<Dart>& match) {
  check_rule_fits_map(r, g);
  const DGraph& R = r.right();
  if (match.size() != r.left().num_nodes())
    throw Error(ErrorCode::Usage, "match size does not fit the left-hand side", "match");
  const std::vector<Node> lnode_of = check_map_match(r, g, match);
  check_map_gluing(r, g, match);
  MapDerivation out;
  out.H = g;
  // Phase 3: fresh darts for added nodes (before removals, so that no index is reused within this
  // step).
  out.comatch.assign(R.num_nodes(), kNoDart);
  for (Node v : R.nodes())
    out.comatch[v.index()] = r.left_of(v) ? match[r.left_of(v)->index()] : out.H.add_dart();
  const LinkRewrite w = rewrite_links(r, out.H, match, out.comatch);
  check_result_combinatorial(r, lnode_of, w);
  remove_deleted_darts(r, g, match, out);
  return out;
}

}  // namespace

MapDerivation apply(const Rule& r, const Map& g, const std::vector<Dart>& match, Construction c) {
  return c == Construction::Categorical ? apply_categorical(r, g, match)
                                        : apply_rewriting(r, g, match);
}

}  // namespace gmr::rewrite
