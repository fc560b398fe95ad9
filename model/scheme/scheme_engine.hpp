// The Jerboa rule-scheme application engine (thesis §4.3.4, §6.3.4).
//
// `apply(engine, g, hooks)` applies a scheme at one hook set: in place on a `Map&`, on a copy
// (returned with the report) on a `const Map&` (docs/architecture.md, "Applying rules"). Given a
// scheme S of parameter <o> and one dart per hook (hooks[0] = reference hook):
//  1. hook orbit: O = G<t>(d_ref), t = label of the reference hook (Alg. 4), darts indexed b =
//  0..s-1,
//     nb(b,p) = index of O[b]@t[p];
//  2. other hooks: orbit isomorphism (Alg. 5, orbit_isomorphism in model/core/orbit.hpp) of
//     G<t>(d_ref) with G<t_c>(d_c) up to the positional relabeling t -> t_c, giving M[b][h_c];
//  3. match table M[b][v] for every L node, propagated along explicit L arcs from the hooks;
//  4. match checks (the instantiated L must be a subgraph of G under M, injectively): (a) all
//  M[b][v]
//     pairwise distinct; (b) explicit arcs v –i– v': M[b][v]@i = M[b][v']; (c) implicit arcs
//     (label position p with t^v[p] = j): M[b][v]@j = M[nb(b,p)][v];
//  5. darts: a preserved R node reuses M[b][v], an added node gets s fresh darts;
//  6. links of R are written over the old ones (implicit: T[b][v]@j := T[nb(b,p)][v]; explicit:
//     T[b][v]@i := T[b][v'] both ways); a dimension a preserved node has neither in L nor in R
//     keeps its outside link;
//  7. the darts of deleted nodes are freed.
// Cost O(s·(|V_L| + |V_R|)·(n+1)): linear in the size of the instantiated rule (expected: step 2
// uses hash maps; plus O(capacity/64) only when the orbit covers more than 1/8 of the map, for the
// dense dart index).
//
// Scope and decisions (named in the docs):
//  * G-maps only (Jerboa schemes are G-map schemes); the map's dimension must equal the scheme's.
//  * The engine requires the scheme to satisfy incident arcs I_S(0..n) (thesis Alg. 1): otherwise
//  no
//    result of an application is a G-map (a dart would get 0 or 2 links of some dimension) and the
//    overwrite semantics would differ from DPO. Such a scheme is reported as not applicable
//    (reason NotCombinatorial) with the first failing node. Under I_S, the gluing (dangling)
//    condition holds for every match (Fact 1), and the engine's result equals the DPO direct
//    derivation of the instantiated rule (tested in model/scheme/tests/scheme_dpo_test.cpp).
//  * The cycle condition is not required: a scheme breaking it yields a map that check_validity
//    rejects, exactly as DPO would.
//  * Embedding expressions are not evaluated here; an ApplicationObserver (model/expr) sees the
//    map before and after the rewrite, which is where Jerboa evaluates them into a buffer and
//    propagates them (thesis §6.3.4). Jerboa preconditions are not evaluated.
//  * A scheme whose L is empty is applied on one abstract dart free at every position (it creates
//    |V_R| darts); it takes no hook dart.
// Inapplicability is a result (SchemeApplication::applied == false, with a reason), never an
// exception; misuse (wrong number of hook darts, dead dart, wrong map kind or dimension, malformed
// scheme) throws gmr::Error. When not applicable, the map is unchanged.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "model/core/map.hpp"
#include "model/scheme/rule_scheme.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::scheme {

enum class NotApplicableReason {
  None,
  NotCombinatorial,         // the scheme breaks I_S(0..n) (Alg. 1)
  HookOrbitsNotIsomorphic,  // Alg. 5 fails for another hook
  NotInjective,             // two instantiated L nodes matched to one dart
  MissingExplicitArc,       // an explicit arc of L is not in G at the match
  MissingImplicitArc,       // an implicit arc of L is not in G at the match
};
const char* to_string(NotApplicableReason r);

struct SchemeApplication {
  bool applied = false;
  NotApplicableReason reason = NotApplicableReason::None;
  std::string why;  // "not applicable, because ..." text when !applied

  // Orbit darts of the reference hook, orbit[b] (before the application).
  std::vector<Dart> orbit;
  size_t orbit_size() const { return orbit.size(); }
  // Match: match[v * s + b] = dart of G for L node v and orbit dart b.
  std::vector<Dart> match;
  // Comatch: comatch[v * s + b] = dart of the result for R node v and orbit dart b.
  std::vector<Dart> comatch;
  Dart match_at(uint32_t v, uint32_t b) const { return match[v * orbit.size() + b]; }
  Dart comatch_at(uint32_t v, uint32_t b) const { return comatch[v * orbit.size() + b]; }
  size_t darts_added = 0, darts_deleted = 0;

  explicit operator bool() const { return applied; }
};

// Hooks around the rewrite of one successful application: `before_rewrite` is called once the
// match is checked (step 4), on the unchanged map; `after_rewrite` once the deleted darts are freed
// (step 7), with the comatch filled. Both receive the hook orbit graph O.
class ApplicationObserver {
 public:
  virtual ~ApplicationObserver() = default;
  virtual void before_rewrite(const Map& g, const SchemeApplication& app, const OrbitGraph& O) = 0;
  virtual void after_rewrite(const Map& g, const SchemeApplication& app, const OrbitGraph& O) = 0;
};

class SchemeEngine;

// S applied at `hook_darts` (hook_darts[k] is the dart for hooks[k]), in g. `observer` (optional)
// sees the rewrite (embeddings, model/expr/propagation.hpp; events, checker/events/event_log.hpp).
SchemeApplication apply(const SchemeEngine& engine, Map& g, const std::vector<Dart>& hook_darts,
                        ApplicationObserver* observer = nullptr);
// The same on a copy of g: the result map (the copy unchanged when not applicable) and the report.
std::pair<Map, SchemeApplication> apply(const SchemeEngine& engine, const Map& g,
                                        const std::vector<Dart>& hook_darts,
                                        ApplicationObserver* observer = nullptr);

// A scheme prepared for repeated application.
class SchemeEngine {
 public:
  // Throws Error(Schema) when the scheme is malformed (validate_structure), when a hook has `_`,
  // or when an L node is not reachable from a hook through explicit arcs.
  explicit SchemeEngine(RuleScheme scheme);

  const RuleScheme& scheme() const { return s_; }
  // Empty when the scheme satisfies I_S(0..n); else the reason it is never applicable.
  const std::string& not_combinatorial() const { return not_combinatorial_; }

  // The tables of phases 5-7, for the whole-component path (component_rewrite.hpp).
  static constexpr uint32_t kAdded = UINT32_MAX;
  uint32_t right_source(uint32_t v) const { return r_source_[v]; }  // L node of R node v, or kAdded
  uint32_t added_rank(uint32_t v) const {
    return added_rank_[v];
  }  // rank among added R nodes, or kAdded
  size_t added_count() const { return num_added_; }
  const std::vector<uint32_t>& deleted_nodes() const { return deleted_; }
  const std::vector<uint32_t>& hook_nodes() const { return hooks_; }

 private:
  friend SchemeApplication apply(const SchemeEngine&, Map&, const std::vector<Dart>&,
                                 ApplicationObserver*);
  // Phases 1-7 in g.
  SchemeApplication rewrite(Map& g, const std::vector<Dart>& hook_darts,
                            ApplicationObserver* observer) const;
  // The phases of rewrite, numbered as in the header comment. check_call throws on misuse; a check
  // that fails marks `res` as not applicable and returns false.
  void check_call(const Map& g, const std::vector<Dart>& hook_darts) const;
  OrbitGraph hook_orbit(const Map& g, const std::vector<Dart>& hook_darts,
                        SchemeApplication& res) const;  // 1
  bool match_other_hooks(const Map& g, const std::vector<Dart>& hook_darts, const OrbitGraph& O,
                         SchemeApplication& res) const;                                   // 2
  void propagate_match(const Map& g, size_t s, std::vector<Dart>& M) const;               // 3
  bool check_match(const Map& g, const OrbitGraph& O, SchemeApplication& res) const;      // 4
  void place_right_darts(Map& g, size_t s, SchemeApplication& res) const;                 // 5
  void write_right_links(Map& g, const OrbitGraph& O, const std::vector<Dart>& T) const;  // 6
  void remove_deleted_darts(Map& g, size_t s, const std::vector<Dart>& M) const;          // 7

  struct Step {
    uint32_t v, from;
    int dim;
  };
  struct Implicit {
    uint32_t p;
    int dim;
  };
  RuleScheme s_;
  std::vector<uint32_t> hooks_;
  std::vector<Step> steps_;                    // match propagation order over L
  std::vector<std::vector<Implicit>> impl_l_;  // per L node
  std::vector<std::vector<Implicit>> impl_r_;  // per R node
  std::vector<uint32_t> r_source_;             // per R node: L node index, or kAdded
  std::vector<uint32_t> added_rank_;           // per R node: rank among added nodes
  std::vector<uint32_t> deleted_;              // L nodes not in R
  size_t num_added_ = 0;
  std::string not_combinatorial_;
};

// Incident arcs I_S(d) for d in 0..n (thesis Alg. 1 on the core): the first failure as text, or "".
std::string incident_arcs_problem(const RuleScheme& s);

}  // namespace gmr::scheme
