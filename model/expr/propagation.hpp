// Embedding values through a rule-scheme application, as Jerboa does it (thesis §6.3.4 and §5.3):
//  1. before the rewrite, the expressions are evaluated on the object before, into a buffer: the
//     instantiated right-hand side is split into its classes over the arcs whose dimension is in
//     <o_pi> (implicit and explicit arcs of the instantiated R), and each class's expression is
//     evaluated once, at its first (node, orbit dart) in node order;
//  2. after the rewrite, each value is propagated over the whole <o_pi>-orbit of the result that
//     contains its class (darts outside the match included);
//  3. every other orbit of the result that meets the right-hand side keeps the value of its
//     preserved darts (thesis §5.4.2 completion: an orbit without expression inherits), and added
//     darts get it.
// Problems are reported, not thrown (the map is already rewritten): an orbit that receives two
// different values (E-overlap, thesis Def. 84, compared on values with a relative tolerance of
// 1e-9), an orbit merging preserved darts of different values without an expression (E-merge), an
// orbit of added darts without value (E-no-value). Embeddings of the map the scheme does not declare
// are propagated by steps 2–3 only. A declared embedding the map lacks is left out (the map is not
// embedded for it; expressions reading it from another embedding's expression fail at evaluation).
#pragma once
#include <string>
#include <vector>

#include "model/expr/compiled_scheme.hpp"
#include "model/expr/embedded_map.hpp"
#include "model/expr/evaluator.hpp"
#include "model/scheme/apply_everywhere.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::expr {

struct PropagationIssue {
  std::string code;  // "E-overlap", "E-merge", "E-no-value"
  std::string embedding;
  Dart dart = kNoDart;  // a dart of the offending orbit in the result
  std::string message;
};

class EmbeddingPropagation : public scheme::ApplicationObserver {
 public:
  // Binds the declarations to m's fields (declarations the map lacks are left out).
  // Error(Schema) when a field of the same name has another orbit type or arity.
  EmbeddingPropagation(const CompiledScheme& cs, EmbeddedMap& m);

  void before_rewrite(const Map& g, const scheme::SchemeApplication& app, const scheme::OrbitGraph& O) override;
  void after_rewrite(const Map& g, const scheme::SchemeApplication& app, const scheme::OrbitGraph& O) override;

  const std::vector<PropagationIssue>& issues() const { return issues_; }
  size_t issue_count() const { return issue_count_; }  // issues() keeps the first 100
  size_t evaluations() const { return evaluations_; }

 private:
  struct Pending {
    uint32_t v, b;  // right node, orbit dart
    Vec3 value;
  };
  void report(std::string code, const EmbeddingField& f, Dart d, std::string message);

  const CompiledScheme& cs_;
  EmbeddedMap& m_;
  std::vector<int> field_of_decl_;               // declaration -> field index
  std::vector<std::vector<Pending>> pending_;    // per field
  std::vector<PropagationIssue> issues_;
  size_t issue_count_ = 0, evaluations_ = 0;
  std::vector<uint32_t> parent_;
  std::vector<Dart> stack_, touched_, orbit_darts_;
  bool touched_all_ = false;  // more darts marked than touched_ lists: clear the marker whole
};

// One application at the hook darts (scheme_engine.hpp), embeddings included.
scheme::SchemeApplication apply_embedded(const scheme::SchemeEngine& engine, EmbeddingPropagation& p,
                                         EmbeddedMap& m, const std::vector<Dart>& hooks);

// Application at every dart (model/scheme/apply_everywhere.hpp), embeddings included.
scheme::EverywhereApplication apply_everywhere_embedded(const scheme::SchemeEngine& engine, EmbeddingPropagation& p,
                                                        EmbeddedMap& m);

}  // namespace gmr::expr
