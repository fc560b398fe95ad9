#include "inference/fold.hpp"

#include <deque>
#include <optional>

#include "model/core/error.hpp"

namespace gmr::inference {

using namespace gmr::scheme;

const char* to_string(FoldFailureKind k) {
  switch (k) {
    case FoldFailureKind::None:
      return "none";
    case FoldFailureKind::ArcFailure:
      return "arc failure";
    case FoldFailureKind::InstantiationFailure:
      return "instantiation failure";
    case FoldFailureKind::RelabelingFailure:
      return "relabeling failure";
    case FoldFailureKind::PartialNeighbourhood:
      return "partial neighbourhood";
    case FoldFailureKind::NotSpanning:
      return "instantiation not spanning all links";
    case FoldFailureKind::PartialHookOrbit:
      return "partial hook orbit";
    case FoldFailureKind::NotConnected:
      return "not connected";
  }
  return "?";
}

std::string node_name(uint32_t k) { return "n" + std::to_string(k); }

namespace {

class Folder {
 public:
  Folder(const JointGraph& j, const OrbitType& o, uint32_t start, const FoldOptions& opt,
         FoldResult& r, FoldWorkspace& ws)
      : j_(j),
        o_(o),
        opt_(opt),
        r_(r),
        n_(j.dimension()),
        node_of_(ws.node_of),
        index_of_(ws.index_of),
        touched_(ws.touched) {
    r_.orbit = o;
    r_.start = start;
  }
  // Leaves the workspace clean for the next fold.
  ~Folder() {
    for (uint32_t x : touched_) {
      node_of_[x] = kNoFoldNode;
      index_of_[x] = kUndefined;
    }
    touched_.clear();
  }

  void run() {
    if (!create_hook()) return;
    std::deque<uint32_t> queue{0};
    while (!queue.empty()) {
      const uint32_t m = queue.front();
      queue.pop_front();
      for (int d = 0; d <= n_ + 1; ++d) {
        const int dim = d <= n_ ? d : kKappa;
        if (dim != kKappa && r_.nodes[m].label.contains(dim)) continue;
        const auto v = extend(m, dim);
        if (!r_.ok()) return;
        if (v != kNoFoldNode) queue.push_back(v);
      }
    }
    if (!check_connected()) return;
    check_spanning();
  }

 private:
  const JointGraph& j_;
  const OrbitType& o_;
  const FoldOptions& opt_;
  FoldResult& r_;
  int n_;
  std::vector<uint32_t>& node_of_;
  std::vector<uint32_t>& index_of_;
  std::vector<uint32_t>& touched_;
  size_t bound_ = 0;
  size_t s_ = 0;
  std::vector<uint32_t> nb_;  // nb_[b * |o| + p]

  uint32_t nb(uint32_t b, size_t p) const { return nb_[b * o_.size() + p]; }
  uint32_t dart(uint32_t m, uint32_t b) const { return r_.nodes[m].darts[b]; }
  std::string d(uint32_t x) const { return j_.describe(x); }
  // "(b, n3) = before 12".
  std::string at(uint32_t m, uint32_t b) const {
    return "(" + std::to_string(b) + "," + node_name(m) + ") = dart " + d(dart(m, b));
  }

  void fail(FoldFailureKind kind, uint32_t node, int dim, std::vector<uint32_t> darts,
            std::string message, int position = -1) {
    r_.failure = {kind, node, dim, position, std::move(darts), std::move(message)};
  }

  void bind(uint32_t x, uint32_t m, uint32_t b) {
    if (index_of_[x] == kUndefined) touched_.push_back(x);
    ++bound_;
    node_of_[x] = m;
    index_of_[x] = b;
    r_.nodes[m].darts[b] = x;
  }

  uint32_t new_node(Side side) {
    arc_to_.resize(arc_to_.size() + static_cast<size_t>(n_) + 2, kNoFoldNode);
    r_.nodes.push_back({OrbitType(std::vector<int>(o_.size(), OrbitType::kHole)), side,
                        std::vector<uint32_t>(s_, kUndefined)});
    return static_cast<uint32_t>(r_.nodes.size() - 1);
  }

  // Step 1.
  bool create_hook() {
    const uint32_t a = r_.start;
    std::vector<uint32_t> order{a};
    index_of_[a] = 0;
    touched_.push_back(a);
    for (size_t q = 0; q < order.size(); ++q) {
      const uint32_t x = order[q];
      for (size_t p = 0; p < o_.size(); ++p) {
        const uint32_t y = j_.nbr(x, o_[p]);
        if (y == kUndefined) {
          for (uint32_t z : order) index_of_[z] = kUndefined;
          fail(FoldFailureKind::PartialHookOrbit, kNoFoldNode, o_[p], {x},
               "partial hook orbit: dart " + d(x) + " of the " + o_.str() +
                   "-orbit of the start dart has no " + std::to_string(o_[p]) +
                   "-neighbour (cut by the selection); the hook orbit must be complete",
               static_cast<int>(p));
          return false;
        }
        if (index_of_[y] == kUndefined) {
          touched_.push_back(y);
          index_of_[y] = static_cast<uint32_t>(order.size());
          order.push_back(y);
        }
      }
    }
    s_ = order.size();
    nb_.resize(s_ * o_.size());
    for (uint32_t b = 0; b < s_; ++b)
      for (size_t p = 0; p < o_.size(); ++p)
        nb_[b * o_.size() + p] = index_of_[j_.nbr(order[b], o_[p])];
    r_.hook_orbit.arity = o_.size();
    r_.hook_orbit.nb = nb_;
    for (uint32_t x : order) r_.hook_orbit.darts.push_back(j_.origin(x));
    const uint32_t h = new_node(j_.side(a));
    r_.nodes[h].label = o_;
    for (uint32_t b = 0; b < s_; ++b) bind(order[b], h, b);
    return true;
  }

  // Explicit arcs by (node, dimension slot): O(1) "arc already present" (the fold stays linear).
  std::vector<uint32_t> arc_to_;
  size_t slot(int dim) const {
    return dim == kKappa ? static_cast<size_t>(n_) + 1 : static_cast<size_t>(dim);
  }
  bool has_arc(uint32_t m, int dim, uint32_t m2) const {
    return arc_to_[m * (n_ + 2) + slot(dim)] == m2;
  }
  void add_arc(uint32_t m, int dim, uint32_t m2) {
    r_.arcs.push_back({std::min(m, m2), std::max(m, m2), dim});
    arc_to_[m * (n_ + 2) + slot(dim)] = m2;
    arc_to_[m2 * (n_ + 2) + slot(dim)] = m;
  }

  // Step 2.1 for node m and dimension dim; returns a new node to enqueue, or kNoFoldNode.
  uint32_t extend(uint32_t m, int dim) {
    const uint32_t x = j_.nbr(dart(m, 0), dim);
    // All or none (App. C).
    for (uint32_t b = 1; b < s_; ++b) {
      const bool defined = j_.nbr(dart(m, b), dim) != kUndefined;
      if (defined != (x != kUndefined)) {
        const uint32_t with = defined ? b : 0, without = defined ? 0 : b;
        fail(FoldFailureKind::PartialNeighbourhood, m, dim, {dart(m, with), dart(m, without)},
             "partial neighbourhood at node " + node_name(m) + ", dimension " +
                 dimension_text(dim) + ": " + at(m, with) + " has a " + dimension_text(dim) +
                 "-neighbour but " + at(m, without) + " has none (all or none, thesis App. C)");
        return kNoFoldNode;
      }
    }
    if (x == kUndefined) return kNoFoldNode;
    const uint32_t m2 = node_of_[x];
    if (m2 != kNoFoldNode && index_of_[x] == 0) {  // arc addition
      if (!has_arc(m, dim, m2)) add_arc(m, dim, m2);
      for (uint32_t b = 1; b < s_; ++b) {
        const uint32_t y = j_.nbr(dart(m, b), dim);
        if (y != dart(m2, b)) {
          fail(FoldFailureKind::InstantiationFailure, m, dim, {dart(m, b), y, dart(m2, b)},
               "instantiation failure at arc " + node_name(m) + " -" + dimension_text(dim) + "- " +
                   node_name(m2) + ": " + at(m, b) + " is " + dimension_text(dim) +
                   "-linked to dart " + d(y) + ", not to " + at(m2, b) +
                   " (thesis Alg. 6 step 2.1)");
          return kNoFoldNode;
        }
      }
      return kNoFoldNode;
    }
    if (m2 != kNoFoldNode) {  // arc failure
      fail(FoldFailureKind::ArcFailure, m, dim, {dart(m, 0), x},
           "arc failure at node " + node_name(m) + ", dimension " + dimension_text(dim) + ": " +
               at(m, 0) + " is " + dimension_text(dim) + "-linked to (" +
               std::to_string(index_of_[x]) + "," + node_name(m2) + ") = dart " + d(x) +
               "; neither an explicit arc nor an implicit arc produces a link between " +
               "different orbit indices (thesis Alg. 6 step 2.1)");
      return kNoFoldNode;
    }
    // Arc extension.
    const uint32_t v = new_node(j_.side(x));
    add_arc(m, dim, v);
    for (uint32_t b = 0; b < s_; ++b) {
      const uint32_t y = j_.nbr(dart(m, b), dim);
      if (node_of_[y] != kNoFoldNode) {
        fail(FoldFailureKind::InstantiationFailure, m, dim, {dart(m, b), y},
             "instantiation failure at arc " + node_name(m) + " -" + dimension_text(dim) + "- " +
                 node_name(v) + ": " + at(m, b) + " is " + dimension_text(dim) +
                 "-linked to dart " + d(y) + ", which already " + "stands for (" +
                 std::to_string(index_of_[y]) + "," + node_name(node_of_[y]) +
                 ") (thesis Alg. 6 step 2.1)");
        return kNoFoldNode;
      }
      bind(y, v, b);
    }
    if (!build_label(v)) return kNoFoldNode;
    return v;
  }

  // Step 2.2.
  bool build_label(uint32_t v) {
    RelabelingCandidates c;
    for (size_t p = 0; p < o_.size(); ++p) {
      const uint32_t cb = nb(0, p);
      std::vector<int> dims;
      for (int jd = 0; jd <= n_; ++jd)
        if (j_.nbr(dart(v, 0), jd) == dart(v, cb)) dims.push_back(jd);
      c.candidates.push_back(order_candidates(std::move(dims), o_[p], cb == 0, opt_.loops));
      c.loop.push_back(cb == 0 ? 1 : 0);
    }
    uint32_t bad_b = 0;
    auto passes = [&](size_t p, int jd) {
      for (uint32_t b = 0; b < s_; ++b)
        if (j_.nbr(dart(v, b), jd) != dart(v, nb(b, p))) {
          bad_b = b;
          return false;
        }
      return true;
    };
    if (opt_.record_alternatives) {
      const auto all = enumerate_relabelings(c, passes);
      r_.alternatives.push_back(static_cast<uint32_t>(all.size()));
      const size_t k = v - 1;
      const size_t pick = k < opt_.choices.size() ? opt_.choices[k] : 0;
      if (pick < all.size()) {
        r_.nodes[v].label = OrbitType(all[pick]);
        return true;
      }
    }
    const RelabelingChoice ch = choose_relabeling(c, passes);
    if (ch.label && !opt_.record_alternatives) {
      r_.nodes[v].label = OrbitType(*ch.label);
      return true;
    }
    if (ch.label)
      throw Error(ErrorCode::Usage, "relabeling choice out of range at node " + node_name(v));
    const auto p = static_cast<size_t>(ch.failed_position);
    const int jd = ch.failed_dim;
    std::string why;
    std::vector<uint32_t> darts;
    if (jd != OrbitType::kHole && !passes(p, jd)) {
      const uint32_t cb = nb(bad_b, p);
      darts = {dart(v, bad_b), dart(v, cb)};
      why = "the link " + at(v, bad_b) + " -" + std::to_string(o_[p]) + "- " + at(v, cb) +
            " of the orbit is not a " + std::to_string(jd) + "-link in J";
    } else {
      darts = {dart(v, 0)};
      why = "no injective choice of dimensions for the positions";
    }
    std::string cands;
    for (int k : c.candidates[p])
      cands += (cands.empty() ? "" : ", ") +
               (k == OrbitType::kHole ? std::string("_") : std::to_string(k));
    fail(FoldFailureKind::RelabelingFailure, v, jd == OrbitType::kHole ? kNoDimension : jd, darts,
         "relabeling failure at node " + node_name(v) + ", position " + std::to_string(p) +
             " (dimension " + std::to_string(o_[p]) + " of " + o_.str() + ", candidates " + cands +
             "): " + std::to_string(o_[p]) + " -> " +
             (jd == OrbitType::kHole ? std::string("_") : std::to_string(jd)) + " fails: " + why +
             " (thesis Alg. 6 step 2.2)",
         static_cast<int>(p));
    return false;
  }

  bool check_connected() {
    if (bound_ == j_.size()) return true;  // every dart is bound exactly once
    for (uint32_t x = 0; x < j_.size(); ++x)
      if (node_of_[x] == kNoFoldNode) {
        fail(FoldFailureKind::NotConnected, kNoFoldNode, kNoDimension, {x},
             "not connected: dart " + d(x) + " is not reachable from the start dart " +
                 d(r_.start) + " (folding needs a connected map or joint representation)");
        return false;
      }
    return true;
  }

  // App. C: every link of J is produced by ι(P, O), and ι(P, O) produces no other link.
  void check_spanning() {
    const size_t k = static_cast<size_t>(n_) + 2;  // slot n+1 = κ
    std::vector<uint32_t> arc_at(r_.nodes.size() * k, kNoFoldNode);
    for (const auto& e : r_.arcs) {
      const size_t slot = e.dim == kKappa ? k - 1 : static_cast<size_t>(e.dim);
      for (auto [u, w] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
        // ι(P, O) must give each dart one link per dimension: no second arc, no arc on a dimension
        // of the node's relabeling.
        const bool twice = arc_at[u * k + slot] != kNoFoldNode && arc_at[u * k + slot] != w;
        if (twice || (e.dim != kKappa && r_.nodes[u].label.contains(e.dim))) {
          fail(FoldFailureKind::NotSpanning, u, e.dim, {dart(u, 0)},
               "instantiation not spanning all links at node " + node_name(u) + ", dimension " +
                   dimension_text(e.dim) + ": the folded scheme gives " + at(u, 0) + " two " +
                   dimension_text(e.dim) +
                   "-links (J is not a G-map here: a link seen from one side only; thesis App. C)");
          return;
        }
        arc_at[u * k + slot] = w;
      }
    }
    for (uint32_t m = 0; m < r_.nodes.size(); ++m) {
      const OrbitType& label = r_.nodes[m].label;
      for (size_t slot = 0; slot < k; ++slot) {
        const int dim = slot + 1 == k ? kKappa : static_cast<int>(slot);
        int pos = -1;
        for (size_t p = 0; p < label.size(); ++p)
          if (dim != kKappa && label[p] == dim) pos = static_cast<int>(p);
        for (uint32_t b = 0; b < s_; ++b) {
          uint32_t expected = kUndefined;
          if (pos >= 0)
            expected = dart(m, nb(b, static_cast<size_t>(pos)));
          else if (arc_at[m * k + slot] != kNoFoldNode)
            expected = dart(arc_at[m * k + slot], b);
          const uint32_t got = j_.nbr(dart(m, b), dim);
          // ι(P, O) is undirected: a link seen from one side only is never spanned.
          if (got == expected && (got == kUndefined || j_.nbr(got, dim) == dart(m, b))) continue;
          if (got == expected) {
            fail(FoldFailureKind::NotSpanning, m, dim, {dart(m, b), got},
                 "instantiation not spanning all links at node " + node_name(m) + ", dimension " +
                     dimension_text(dim) + ": " + at(m, b) + " is " + dimension_text(dim) +
                     "-linked to dart " + d(got) + " but not conversely (thesis App. C)");
            return;
          }
          std::string what = got == kUndefined
                                 ? "has no " + dimension_text(dim) + "-neighbour"
                                 : "is " + dimension_text(dim) + "-linked to dart " + d(got);
          std::string want = expected == kUndefined ? "no link" : "a link to dart " + d(expected);
          fail(FoldFailureKind::NotSpanning, m, dim, {dart(m, b)},
               "instantiation not spanning all links at node " + node_name(m) + ", dimension " +
                   dimension_text(dim) + ": " + at(m, b) + " " + what +
                   " while the folded scheme instantiates " + want + " (thesis App. C)");
          return;
        }
      }
    }
  }
};

}  // namespace

FoldResult fold(const JointGraph& j, const OrbitType& o, uint32_t start, const FoldOptions& opt,
                FoldWorkspace* ws) {
  DimMask seen = 0;
  for (int dim : o.dims()) {
    if (dim == OrbitType::kHole)
      throw Error(ErrorCode::Usage, "the folding orbit type " + o.str() + " has `_`");
    if (dim < 0 || dim > j.dimension())
      throw Error(ErrorCode::Usage, "dimension " + std::to_string(dim) + " of " + o.str() +
                                        " is not in 0.." + std::to_string(j.dimension()));
    if ((seen >> dim) & 1u)
      throw Error(ErrorCode::Usage,
                  "the orbit type " + o.str() + " repeats dimension " + std::to_string(dim));
    seen |= DimMask(1) << dim;
  }
  if (start >= j.size()) throw Error(ErrorCode::Usage, "no start dart " + std::to_string(start));
  if (j.side(start) != Side::L)
    throw Error(ErrorCode::Usage, "the start dart " + j.describe(start) +
                                      " is on the after side; folding starts in L");
  FoldResult r;
  std::optional<FoldWorkspace> local;
  if (!ws) ws = &local.emplace(j.size());
  if (ws->node_of.size() != j.size())
    throw Error(ErrorCode::Usage, "fold workspace made for another joint graph");
  Folder(j, o, start, opt, r, *ws).run();
  return r;
}

FoldAll fold_all(const JointGraph& j, const OrbitType& o, uint32_t start, const FoldOptions& opt,
                 size_t limit, FoldWorkspace* ws) {
  FoldAll out;
  std::optional<FoldWorkspace> local;
  if (!ws) ws = &local.emplace(j.size());
  FoldOptions o2 = opt;
  o2.record_alternatives = true;
  // Depth-first over choice vectors: each run fixes a prefix; the nodes after it take choice 0,
  // and each of their other alternatives becomes a new prefix.
  std::vector<std::vector<uint32_t>> todo{opt.choices};
  while (!todo.empty()) {
    if (out.runs == limit) {
      out.truncated = true;
      break;
    }
    std::vector<uint32_t> prefix = std::move(todo.back());
    todo.pop_back();
    o2.choices = prefix;
    FoldResult r = fold(j, o, start, o2, ws);
    ++out.runs;
    for (size_t k = r.alternatives.size(); k-- > prefix.size();)
      for (uint32_t c = r.alternatives[k]; c-- > 1;) {
        std::vector<uint32_t> next = prefix;
        next.resize(k, 0);
        next.push_back(c);
        todo.push_back(std::move(next));
      }
    if (r.ok()) {
      std::vector<uint32_t> full = prefix;
      full.resize(r.alternatives.size(), 0);
      out.choices.push_back(std::move(full));
      out.folds.push_back(std::move(r));
    }
  }
  return out;
}

GraphScheme to_graph_scheme(const FoldResult& f) {
  if (!f.ok()) throw Error(ErrorCode::Usage, "the fold failed: " + f.failure.message);
  GraphScheme s;
  for (uint32_t k = 0; k < f.nodes.size(); ++k) {
    if (f.nodes[k].side != Side::L)
      throw Error(ErrorCode::Usage, "the fold has an after side: make a rule of it");
    s.add_node(node_name(k), f.nodes[k].label);
  }
  for (const auto& e : f.arcs) {
    if (e.dim == kKappa) throw Error(ErrorCode::Usage, "the fold has κ arcs: make a rule of it");
    s.arcs.push_back({e.a, e.b, e.dim});
  }
  return s;
}

}  // namespace gmr::inference
