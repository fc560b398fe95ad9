#include "model/scheme/scheme_engine.hpp"

#include <ranges>
#include <unordered_map>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::scheme {

namespace {
constexpr uint32_t kAdded = SchemeEngine::kAdded;
}

const char* to_string(NotApplicableReason r) {
  switch (r) {
    case NotApplicableReason::None:
      return "none";
    case NotApplicableReason::NotCombinatorial:
      return "not-combinatorial";
    case NotApplicableReason::HookOrbitsNotIsomorphic:
      return "hook-orbits-not-isomorphic";
    case NotApplicableReason::NotInjective:
      return "not-injective";
    case NotApplicableReason::MissingExplicitArc:
      return "missing-explicit-arc";
    case NotApplicableReason::MissingImplicitArc:
      return "missing-implicit-arc";
  }
  return "?";
}

std::string incident_arcs_problem(const RuleScheme& s) {
  for (int d = 0; d <= s.dimension; ++d) {
    for (uint32_t v = 0; v < s.left.size(); ++v) {
      const size_t cl = s.left.count_arcs(v, d);
      const std::string nm = s.left.nodes[v].name;
      if (cl > 1)
        return "L node " + nm + " has " + std::to_string(cl) + " " + std::to_string(d) + "-arcs";
      if (auto r = s.right_of(v)) {
        const size_t cr = s.right.count_arcs(*r, d);
        if (cr != cl)
          return "preserved node " + nm + " has " + std::to_string(cl) + " " + std::to_string(d) +
                 "-arc(s) in L and " + std::to_string(cr) + " in R";
      } else if (cl != 1) {
        return "deleted node " + nm + " has no " + std::to_string(d) +
               "-arc in L (gluing condition)";
      }
    }
    for (uint32_t v = 0; v < s.right.size(); ++v) {
      if (s.left_of(v)) continue;
      const size_t cr = s.right.count_arcs(v, d);
      if (cr != 1)
        return "added node " + s.right.nodes[v].name + " has " + std::to_string(cr) + " " +
               std::to_string(d) + "-arcs in R (exactly one needed)";
    }
  }
  return {};
}

SchemeEngine::SchemeEngine(RuleScheme scheme) : s_(std::move(scheme)) {
  s_.validate_structure();
  hooks_ = s_.hook_nodes();
  for (uint32_t h : hooks_)
    if (s_.left.nodes[h].label.has_hole())
      throw Error(ErrorCode::Schema, "hook label " + s_.left.nodes[h].label.str() + " has `_`",
                  "L node " + s_.left.nodes[h].name);
  const size_t nl = s_.left.size();
  // Propagation order: BFS over explicit L arcs from the hooks.
  std::vector<bool> seen(nl, false);
  std::vector<uint32_t> queue;
  for (uint32_t h : hooks_) {
    if (seen[h])
      throw Error(ErrorCode::Schema, "two hooks in one connected component of L",
                  "L node " + s_.left.nodes[h].name);
    seen[h] = true;
    queue.push_back(h);
    for (size_t k = queue.size() - 1; k < queue.size(); ++k) {
      const uint32_t v = queue[k];
      for (const auto& e : s_.left.arcs) {
        if (e.a != v && e.b != v) continue;
        const uint32_t w = e.a == v ? e.b : e.a;
        if (seen[w]) {
          continue;
        }
        seen[w] = true;
        queue.push_back(w);
        steps_.push_back(Step{w, v, e.dim});
      }
    }
  }
  for (uint32_t v = 0; v < nl; ++v)
    if (!seen[v])
      throw Error(ErrorCode::Schema, "L node is in a connected component without hook",
                  "L node " + s_.left.nodes[v].name);
  auto implicit = [](const SchemeNode& n) {
    std::vector<Implicit> out;
    for (uint32_t p = 0; p < n.label.size(); ++p)
      if (n.label[p] != OrbitType::kHole) out.push_back(Implicit{p, n.label[p]});
    return out;
  };
  for (const auto& n : s_.left.nodes) impl_l_.push_back(implicit(n));
  for (const auto& n : s_.right.nodes) impl_r_.push_back(implicit(n));
  r_source_.assign(s_.right.size(), kAdded);
  added_rank_.assign(s_.right.size(), kAdded);
  for (uint32_t v = 0; v < s_.right.size(); ++v) {
    if (auto l = s_.left_of(v))
      r_source_[v] = *l;
    else
      added_rank_[v] = static_cast<uint32_t>(num_added_++);
  }
  for (uint32_t v = 0; v < nl; ++v)
    if (!s_.right_of(v)) deleted_.push_back(v);
  not_combinatorial_ = incident_arcs_problem(s_);
}

namespace {

// Marks res as not applicable; always returns false (a failed phase).
bool fail(SchemeApplication& res, NotApplicableReason r, std::string why) {
  res.applied = false;
  res.reason = r;
  res.why = "not applicable, because " + std::move(why);
  res.match.clear();
  return false;
}

}  // namespace

void SchemeEngine::check_call(const Map& g, const std::vector<Dart>& hook_darts) const {
  if (g.kind() != MapKind::GMap)
    throw Error(ErrorCode::Usage, "rule schemes apply to G-maps only", "scheme " + s_.name);
  if (g.dimension() != s_.dimension)
    throw Error(ErrorCode::Usage,
                "the scheme rewrites " + std::to_string(s_.dimension) + "-G-maps, the map is a " +
                    std::to_string(g.dimension()) + "-G-map",
                "scheme " + s_.name);
  if (hook_darts.size() != hooks_.size())
    throw Error(ErrorCode::Usage,
                "the scheme has " + std::to_string(hooks_.size()) + " hook(s), " +
                    std::to_string(hook_darts.size()) + " dart(s) given",
                "scheme " + s_.name);
  for (size_t k = 0; k < hook_darts.size(); ++k)
    if (!g.alive(hook_darts[k]))
      throw Error(ErrorCode::Range, "no such dart", "dart " + std::to_string(hook_darts[k]));
}

OrbitGraph SchemeEngine::hook_orbit(const Map& g, const std::vector<Dart>& hook_darts,
                                    SchemeApplication& res) const {
  OrbitGraph O = hooks_.empty() ? single_dart_orbit(s_.orbit.size())
                                : orbit_graph(g, s_.left.nodes[hooks_[0]].label, hook_darts[0]);
  const size_t s = O.size();
  res.orbit = O.darts;
  res.match.assign(s_.left.size() * s, kNoDart);
  if (!hooks_.empty())
    for (uint32_t b = 0; b < s; ++b) res.match[hooks_[0] * s + b] = O.darts[b];
  return O;
}

bool SchemeEngine::match_other_hooks(const Map& g, const std::vector<Dart>& hook_darts,
                                     const OrbitGraph& O, SchemeApplication& res) const {
  if (hooks_.size() < 2) return true;
  const size_t s = O.size();
  const OrbitType& lref = s_.left.nodes[hooks_[0]].label;
  std::unordered_map<Dart, uint32_t> index;  // reference orbit dart -> b
  for (uint32_t b = 0; b < s; ++b) index.emplace(O.darts[b], b);
  for (size_t c = 1; c < hooks_.size(); ++c) {
    const uint32_t h = hooks_[c];
    const OrbitType& lc = s_.left.nodes[h].label;
    OrbitIsoConflict conflict;
    const auto pairs = orbit_isomorphism(g, lref, hook_darts[0], g, lc, hook_darts[c], &conflict);
    std::string err;
    if (!pairs)
      err = conflict.earlier == kNoDart
                ? "dart " + std::to_string(conflict.x2) +
                      " would correspond to two darts of the reference orbit"
                : "dart " + std::to_string(conflict.x) + " would correspond to both " +
                      std::to_string(conflict.earlier) + " and " + std::to_string(conflict.x2);
    else if (pairs->size() != s)
      err = "the orbits have different sizes";
    if (!err.empty())
      return fail(res, NotApplicableReason::HookOrbitsNotIsomorphic,
                  "the " + lc.str() + "-orbit of hook " + s_.hooks[c] + " at dart " +
                      std::to_string(hook_darts[c]) + " is not isomorphic to the " + lref.str() +
                      "-orbit of hook " + s_.hooks[0] + " at dart " +
                      std::to_string(hook_darts[0]) + ": " + err);
    Dart* Mh = &res.match[h * s];
    for (const auto& [x, x2] : *pairs) Mh[index.at(x)] = x2;
  }
  return true;
}

void SchemeEngine::propagate_match(const Map& g, size_t s, std::vector<Dart>& M) const {
  for (const Step& st : steps_)
    for (uint32_t b = 0; b < s; ++b) M[st.v * s + b] = g.alpha(st.dim, M[st.from * s + b]);
}

bool SchemeEngine::check_match(const Map& g, const OrbitGraph& O, SchemeApplication& res) const {
  const size_t s = O.size();
  const size_t nl = s_.left.size();
  const std::vector<Dart>& M = res.match;
  // (a) injectivity
  {
    ScopedMarker mk(g);
    bool dup = false;
    for (Dart x : M) {
      if (mk.test(x)) {
        dup = true;
        break;
      }
      mk.mark(x);
    }
    for (Dart x : M) mk.unmark(x);
    mk.set_clean();
    if (dup) {
      std::unordered_map<Dart, size_t> first;
      std::string why;
      for (size_t k = 0; k < M.size(); ++k) {
        auto [it, fresh] = first.emplace(M[k], k);
        if (!fresh) {
          auto name = [&](size_t idx) {
            return instance_name(O, static_cast<uint32_t>(idx % s), s_.left.nodes[idx / s].name);
          };
          why = "the match is not injective: " + name(it->second) + " and " + name(k) +
                " both map to dart " + std::to_string(M[k]);
          break;
        }
      }
      return fail(res, NotApplicableReason::NotInjective, why);
    }
  }
  // (b) explicit arcs of L
  for (const auto& e : s_.left.arcs)
    for (uint32_t b = 0; b < s; ++b) {
      const Dart x = M[e.a * s + b], y = M[e.b * s + b];
      if (g.alpha(e.dim, x) != y)
        return fail(res, NotApplicableReason::MissingExplicitArc,
                    "the L arc " + s_.left.nodes[e.a].name + " -" + std::to_string(e.dim) + "- " +
                        s_.left.nodes[e.b].name + " is not in G at orbit dart " +
                        std::to_string(O.darts[b]) + ": dart " + std::to_string(x) + " has " +
                        std::to_string(e.dim) + "-neighbour " + std::to_string(g.alpha(e.dim, x)) +
                        ", not " + std::to_string(y));
    }
  // (c) implicit arcs of L
  for (uint32_t v = 0; v < nl; ++v)
    for (const Implicit& im : impl_l_[v])
      for (uint32_t b = 0; b < s; ++b) {
        const Dart x = M[v * s + b], y = M[v * s + O.neighbor(b, im.p)];
        if (g.alpha(im.dim, x) != y)
          return fail(res, NotApplicableReason::MissingImplicitArc,
                      "the implicit " + std::to_string(im.dim) + "-arcs of L node " +
                          s_.left.nodes[v].name + " " + s_.left.nodes[v].label.str() +
                          " are not in G: dart " + std::to_string(x) + " has " +
                          std::to_string(im.dim) + "-neighbour " +
                          std::to_string(g.alpha(im.dim, x)) + ", not " + std::to_string(y));
      }
  return true;
}

void SchemeEngine::place_right_darts(Map& g, size_t s, SchemeApplication& res) const {
  const size_t nr = s_.right.size();
  const std::vector<Dart>& M = res.match;
  std::vector<Dart>& T = res.comatch;
  T.clear();
  T.reserve(nr * s);  // written once, node by node (no fill first)
  const Dart base = num_added_ > 0 ? g.add_darts(num_added_ * s) : 0;
  for (uint32_t v = 0; v < nr; ++v) {
    if (r_source_[v] != kAdded) {
      const Dart* Mv = &M[r_source_[v] * s];
      T.insert(T.end(), Mv, Mv + s);
    } else {
      const Dart first = base + static_cast<Dart>(added_rank_[v] * s);
      const auto fresh = std::views::iota(first, static_cast<Dart>(first + s));
      T.insert(T.end(), fresh.begin(), fresh.end());
    }
  }
}

void SchemeEngine::write_right_links(Map& g, const OrbitGraph& O,
                                     const std::vector<Dart>& T) const {
  const size_t s = O.size();
  for (uint32_t v = 0; v < s_.right.size(); ++v) {
    const Dart* Tv = &T[v * s];
    for (const Implicit& im : impl_r_[v]) {
      for (uint32_t b = 0; b < s; ++b) g.set_alpha(im.dim, Tv[b], Tv[O.neighbor(b, im.p)]);
    }
  }
  for (const auto& e : s_.right.arcs) {
    const Dart* Ta = &T[e.a * s];
    const Dart* Tb = &T[e.b * s];
    for (uint32_t b = 0; b < s; ++b) {
      g.set_alpha(e.dim, Ta[b], Tb[b]);
      g.set_alpha(e.dim, Tb[b], Ta[b]);
    }
  }
}

void SchemeEngine::remove_deleted_darts(Map& g, size_t s, const std::vector<Dart>& M) const {
  // The deleted darts' own links become loops first, so that remove_dart touches no surviving dart
  // (their links were all overwritten in step 6, by I_S).
  for (uint32_t v : deleted_)
    for (uint32_t b = 0; b < s; ++b) {
      const Dart x = M[v * s + b];
      for (int i = 0; i <= g.dimension(); ++i) g.set_alpha(i, x, x);
      g.remove_dart(x);
    }
}

SchemeApplication SchemeEngine::rewrite(Map& g, const std::vector<Dart>& hook_darts,
                                        ApplicationObserver* observer) const {
  check_call(g, hook_darts);
  SchemeApplication res;
  if (!not_combinatorial_.empty()) {
    fail(res, NotApplicableReason::NotCombinatorial,
         "the scheme breaks incident arcs (Alg. 1): " + not_combinatorial_);
    return res;
  }
  const OrbitGraph O = hook_orbit(g, hook_darts, res);  // 1
  const size_t s = O.size();
  if (!match_other_hooks(g, hook_darts, O, res)) return res;  // 2
  propagate_match(g, s, res.match);                           // 3
  if (!check_match(g, O, res)) return res;                    // 4
  if (observer) observer->before_rewrite(g, res, O);
  place_right_darts(g, s, res);           // 5
  write_right_links(g, O, res.comatch);   // 6
  remove_deleted_darts(g, s, res.match);  // 7
  res.applied = true;
  res.darts_added = num_added_ * s;
  res.darts_deleted = deleted_.size() * s;
  if (observer) observer->after_rewrite(g, res, O);
  return res;
}

SchemeApplication apply(const SchemeEngine& engine, Map& g, const std::vector<Dart>& hook_darts,
                        ApplicationObserver* observer) {
  return engine.rewrite(g, hook_darts, observer);
}

std::pair<Map, SchemeApplication> apply(const SchemeEngine& engine, const Map& g,
                                        const std::vector<Dart>& hook_darts,
                                        ApplicationObserver* observer) {
  Map h = g;
  SchemeApplication a = apply(engine, h, hook_darts, observer);
  return {std::move(h), std::move(a)};
}

}  // namespace gmr::scheme
