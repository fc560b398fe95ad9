#include "model/rewrite/rule.hpp"

#include <map>
#include <set>
#include <tuple>

#include "model/core/error.hpp"

namespace gmr::rewrite {
using namespace gmr::graph;

namespace {

void validate_side(const DGraph& g, const char* side, int lo, int n) {
  std::set<std::string> seen;
  for (Node v : g.nodes()) {
    const std::string loc = std::string(side) + ".nodes[" + std::to_string(v.index()) + "]";
    if (g.name(v).empty()) throw Error(ErrorCode::Schema, "rule nodes must be named", loc);
    if (!seen.insert(g.name(v)).second)
      throw Error(ErrorCode::Schema, "duplicate node name \"" + g.name(v) + "\"", loc);
  }
  for (ArcId a : g.arc_slots()) {
    if (!g.arc_alive(a)) continue;
    const int l = g.arc(a).label;
    if (l < lo || l > n)
      throw Error(ErrorCode::Schema,
                  "label " + std::to_string(l) + " outside the dimension set " +
                      std::to_string(lo) + ".." + std::to_string(n),
                  std::string(side) + ".arcs[" + std::to_string(a.index()) + "]");
  }
}

}  // namespace

Rule::Rule(DGraph left, DGraph right, int n, MapKind kind, std::string name)
    : name_(std::move(name)), n_(n), kind_(kind), L_(std::move(left)), R_(std::move(right)) {
  if (n < 0 || n >= kMaxDim || (kind == MapKind::OMap && n < 1))
    throw Error(ErrorCode::Schema, "dimension " + std::to_string(n) + " out of range", "n");
  validate_side(L_, "left", lowest_dim(), n_);
  validate_side(R_, "right", lowest_dim(), n_);
  deduce();
}

void Rule::deduce() {
  l_to_r_.assign(L_.num_nodes(), std::nullopt);
  r_to_l_.assign(R_.num_nodes(), std::nullopt);
  for (Node v : L_.nodes())
    if (auto w = R_.find(L_.name(v))) {
      l_to_r_[v] = *w;
      r_to_l_[*w] = v;
    }
  // Assumption 4: pair arcs with the same (source, target, label) between preserved nodes; the
  // k-th parallel arc of L with the k-th of R.
  la_to_ra_.assign(L_.num_arc_slots(), std::nullopt);
  ra_to_la_.assign(R_.num_arc_slots(), std::nullopt);
  std::map<std::tuple<Node, Node, int>, std::vector<ArcId>> pool;  // keyed by R ids
  for (ArcId a : R_.arc_slots())
    if (R_.arc_alive(a)) pool[{R_.arc(a).src, R_.arc(a).tgt, R_.arc(a).label}].push_back(a);
  std::map<std::tuple<Node, Node, int>, size_t> used;
  for (ArcId a : L_.arc_slots()) {
    if (!L_.arc_alive(a)) continue;
    const Arc& e = L_.arc(a);
    if (!l_to_r_[e.src] || !l_to_r_[e.tgt]) continue;
    const std::tuple<Node, Node, int> key{*l_to_r_[e.src], *l_to_r_[e.tgt], e.label};
    auto it = pool.find(key);
    if (it == pool.end()) continue;
    size_t& k = used[key];
    if (k < it->second.size()) {
      la_to_ra_[a] = it->second[k];
      ra_to_la_[it->second[k]] = a;
      ++k;
    }
  }
}

std::vector<int> Rule::labels() const {
  std::vector<int> out;
  for (int i = lowest_dim(); i <= n_; ++i) out.push_back(i);
  return out;
}

std::optional<Node> Rule::right_of(Node l) const { return l_to_r_.at(l); }
std::optional<Node> Rule::left_of(Node r) const { return r_to_l_.at(r); }
std::optional<ArcId> Rule::right_arc_of(ArcId l) const { return la_to_ra_.at(l); }
std::optional<ArcId> Rule::left_arc_of(ArcId r) const { return ra_to_la_.at(r); }

std::vector<Node> Rule::preserved_nodes() const {
  std::vector<Node> out;
  for (Node v : L_.nodes())
    if (l_to_r_[v]) out.push_back(v);
  return out;
}
std::vector<Node> Rule::deleted_nodes() const {
  std::vector<Node> out;
  for (Node v : L_.nodes())
    if (!l_to_r_[v]) out.push_back(v);
  return out;
}
std::vector<Node> Rule::added_nodes() const {
  std::vector<Node> out;
  for (Node v : R_.nodes())
    if (!r_to_l_[v]) out.push_back(v);
  return out;
}

std::string Rule::arc_str(Side s, ArcId a) const {
  const DGraph& g = side(s);
  const Arc& e = g.arc(a);
  return g.node_str(e.src) + " -" + std::to_string(e.label) + "-> " + g.node_str(e.tgt) + " (" +
         to_string(s) + ")";
}

JointRepresentation to_joint(const Rule& r) {
  JointRepresentation j;
  j.n = r.dimension();
  j.kind = r.kind();
  j.name = r.name();
  const DGraph &L = r.left(), &R = r.right();
  for (Node v : L.nodes()) {
    j.graph.add_node(L.name(v));
    j.right_side.push_back(false);
  }
  auto right_node = [&](Node v) { return Node(static_cast<uint32_t>(L.num_nodes()) + v.index()); };
  for (Node v : R.nodes()) {
    j.graph.add_node(R.name(v));
    j.right_side.push_back(true);
  }
  for (ArcId a : L.arc_slots())
    if (L.arc_alive(a)) j.graph.add_arc(L.arc(a).src, L.arc(a).tgt, L.arc(a).label);
  for (ArcId a : R.arc_slots())
    if (R.arc_alive(a))
      j.graph.add_arc(right_node(R.arc(a).src), right_node(R.arc(a).tgt), R.arc(a).label);
  for (Node v : L.nodes())
    if (auto w = r.right_of(v)) j.graph.add_arc(v, right_node(*w), kKappaLabel);
  return j;
}

Rule from_joint(const JointRepresentation& j) {
  const DGraph& g = j.graph;
  if (j.right_side.size() != g.num_nodes())
    throw Error(ErrorCode::Schema, "side flags do not cover the nodes", "joint");
  HandleVector<Node, Node> local(g.num_nodes());
  DGraph L, R;
  HandleVector<Node, std::string> rname(g.num_nodes());
  for (Node v : g.nodes()) rname[v] = g.name(v);
  HandleVector<Node, int> kappa_in(g.num_nodes(), 0), kappa_out(g.num_nodes(), 0);
  for (ArcId a : g.arc_slots()) {
    if (!g.arc_alive(a) || g.arc(a).label != kKappaLabel) continue;
    const Arc& e = g.arc(a);
    if (j.right_side[e.src] || !j.right_side[e.tgt])
      throw Error(ErrorCode::Schema, "κ-arc must go from an L node to an R node",
                  "joint arc " + g.node_str(e.src) + " -> " + g.node_str(e.tgt));
    if (++kappa_out[e.src] > 1 || ++kappa_in[e.tgt] > 1)
      throw Error(ErrorCode::Schema, "node with two κ-arcs",
                  "joint arc " + g.node_str(e.src) + " -> " + g.node_str(e.tgt));
    rname[e.tgt] = g.name(e.src);
  }
  for (Node v : g.nodes()) {
    if (j.right_side[v]) {
      // An R node without κ-arc must not take the name of an L node (it would become preserved).
      if (!kappa_in[v])
        for (Node u : g.nodes())
          if (!j.right_side[u] && g.name(u) == rname[v])
            throw Error(ErrorCode::Schema, "added R node shares its name with an L node",
                        "joint node " + rname[v]);
      local[v] = R.add_node(rname[v]);
    } else {
      local[v] = L.add_node(g.name(v));
    }
  }
  for (ArcId a : g.arc_slots()) {
    if (!g.arc_alive(a) || g.arc(a).label == kKappaLabel) continue;
    const Arc& e = g.arc(a);
    if (j.right_side[e.src] != j.right_side[e.tgt])
      throw Error(ErrorCode::Schema, "a non-κ arc crosses the L/R sides",
                  "joint arc " + g.node_str(e.src) + " -> " + g.node_str(e.tgt));
    (j.right_side[e.src] ? R : L).add_arc(local[e.src], local[e.tgt], e.label);
  }
  return Rule(std::move(L), std::move(R), j.n, j.kind, j.name);
}

}  // namespace gmr::rewrite
