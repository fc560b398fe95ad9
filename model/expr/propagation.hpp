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
// orbit of added darts without value (E-no-value). Embeddings of the map the scheme does not
// declare are propagated by steps 2–3 only. A declared embedding the map lacks is left out (the map
// is not embedded for it; expressions reading it from another embedding's expression fail at
// evaluation).
//
// Whole components (model/scheme/component_rewrite.hpp: L is the hook alone, labelled with every
// dimension): every link of the rewritten component comes from the instantiated R, so the classes
// of step 1 are the <o_pi>-orbits of the result, and they have a form known from the scheme alone:
// a class is V × B, with V a set of R nodes joined by explicit arcs of dimensions in <o_pi> and B
// an orbit of O under the label positions p of V's nodes with o^v[p] in <o_pi>, i.e. the darts of
// an orbit of the map before under the dimensions o[p] of those positions (O's links follow o[p]).
// So the classes are derived once per scheme and embedding (V and those dimensions), each class's
// expression is evaluated at its first node with an expression and its first orbit dart (the
// order of step 1), its darts receive one slot in one sweep (step 2), and a class without
// expression takes the slot of its preserved darts (step 3). Each kind's expression is compiled
// once into a flat program (program.hpp), and in memo mode the evaluator tells orbits apart by the
// kinds' class labels. No overlap can occur (each orbit of
// the result is one class); E-merge and E-no-value are reported as above. Tested equal to the
// general path (values per dart, issues) in model/expr/tests/component_propagation_test.cpp.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/core/buffer_pool.hpp"
#include "model/core/embedded_map.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/component_view.hpp"
#include "model/expr/evaluator.hpp"
#include "model/scheme/apply_everywhere.hpp"
#include "model/scheme/component_rewrite.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::expr {

namespace detail {
// Values compared with a relative tolerance of 1e-9 (E-overlap, E-merge), and their text.
bool same_value(const Vec3& a, const Vec3& b);
std::string text(const Vec3& v, int arity);
}  // namespace detail

struct PropagationIssue {
  std::string code;  // "E-overlap", "E-merge", "E-no-value"
  std::string embedding;
  Dart dart = kNoDart;  // a dart of the offending orbit in the result
  std::string message;
};

// The propagation as an observer of the applications of a scheme to m.map: passed to scheme::apply
// (scheme_engine.hpp) or scheme::apply_everywhere (apply_everywhere.hpp), whose whole-component
// path it also observes.
class EmbeddingPropagation : public scheme::ApplicationObserver, public scheme::ComponentObserver {
 public:
  // Binds the declarations to m's fields (declarations the map lacks are left out).
  // Error(Schema) when a field of the same name has another orbit type or arity, or when a field
  // holds JSON values (rule applications carry numeric embeddings only).
  EmbeddingPropagation(const CompiledScheme& cs, EmbeddedMap& m);

  void before_rewrite(const Map& g, const scheme::SchemeApplication& app,
                      const scheme::OrbitGraph& O) override;
  void after_rewrite(const Map& g, const scheme::SchemeApplication& app,
                     const scheme::OrbitGraph& O) override;
  // The same for one whole component (component_propagation.cpp).
  void before_rewrite(const Map& g, const scheme::ComponentInstance& c) override;
  void after_rewrite(const Map& g, const scheme::ComponentInstance& c) override;

  const std::vector<PropagationIssue>& issues() const { return issues_; }
  size_t issue_count() const { return issue_count_; }  // issues() keeps the first 100
  size_t evaluations() const { return evaluations_; }

 private:
  struct Pending {
    uint32_t v, b;  // right node, orbit dart
    Vec3 value;
  };
  void report(std::string code, const EmbeddingField& f, Dart d, std::string message);
  // A kind of class of a whole component (see the header): the R nodes V (increasing), the
  // dimensions of the map before whose orbits are the B's, and the expression evaluated for it.
  struct ClassKind {
    std::vector<uint32_t> nodes;
    DimMask dims = 0;                 // as a set of dimensions of the map before
    std::vector<size_t> positions;    // the same as positions of O (o[p] in dims)
    int declaration = -1;             // the expression's embedding declaration, or -1 (inherited)
    uint32_t expression_node = 0;     // its R node
    ScratchTable<uint32_t> class_of;  // per orbit dart b: the class (computed before the rewrite)
    ScratchTable<uint32_t> first_b;   // per class: its first orbit dart
    // Kinds of two positions whose orbits an expression enumerates (listed): the orbit darts of
    // each class in the order of Evaluator::list_two_dims from its first one, class by class (class
    // id from orbit_start[id] to orbit_start[id + 1]).
    bool listed = false;
    ScratchTable<uint32_t> orbit_list;
    ScratchTable<uint32_t> orbit_start;
    uint32_t offset = 0;             // computed kinds: class id's value slot is offset + id
    std::optional<Program> program;  // the expression compiled (program.hpp), when it compiles
  };
  void derive_class_kinds();
  uint32_t label_classes(const Map& g, const scheme::ComponentInstance& c, ClassKind& k);
  void evaluate_classes(Evaluator& ev, const Map& g, const scheme::ComponentInstance& c,
                        const ClassKind& k, uint32_t count, bool on_view,
                        const std::vector<const EmbeddingField*>& fields, std::vector<Vec3>& out);
  void inherited_slots(const Map& g, const scheme::ComponentInstance& c, EmbeddingField& f,
                       ClassKind& k, std::vector<uint32_t>& chosen);
  std::vector<std::vector<ClassKind>> kinds_;  // per field, in order of expression node
  bool kinds_derived_ = false;

  const CompiledScheme& cs_;
  EmbeddedMap& m_;
  std::vector<int> field_of_decl_;             // declaration -> field index
  std::vector<std::vector<Pending>> pending_;  // per field
  std::vector<PropagationIssue> issues_;
  size_t issue_count_ = 0, evaluations_ = 0;
  std::vector<uint32_t> parent_;
  std::vector<Dart> stack_, touched_, orbit_darts_;
  std::vector<std::vector<uint32_t>> chosen_;  // per kind without expression: its classes' slots
  ComponentView view_;        // the component evaluated (whole components, component_view.hpp)
  bool touched_all_ = false;  // more darts marked than touched_ lists: clear the marker whole
};

}  // namespace gmr::expr
