// Bounded verification of a concrete rule (docs/verify.md): "no map of the model with at most
// `bound` darts has an application of the rule (a match satisfying the gluing condition, thesis
// Defs. 24-25) whose result H breaks a constraint of the model (Def. 32)", or a counterexample.
//
// Two engines, whose verdicts are compared in checker/smt/tests:
//  * Smt   the encodings of map_encoding.hpp and derivation_encoding.hpp; one solver, the map
//          constraints asserted once, then for b = max(1, |V_L|) .. bound a push, `size = b`, a
//          check and a pop (incremental solving; the first counterexample has the fewest darts).
//          Every model is replayed through the concrete derivation (rewrite/dpo.hpp) and
//          checked with check_map_constraints: an encoding error would stop the run
//          (std::logic_error) instead of reporting a false counterexample.
//  * Enum  the exhaustive enumerator (checker/semantic.hpp) on map_family(n, kind, bound).
// `applicable` tells whether some application exists within the bound (a second SMT query
// without the violation, when no counterexample was found): a rule that never applies preserves
// the model vacuously.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/smt/map_encoding.hpp"
#include "model/core/map.hpp"
#include "model/graph/constraints.hpp"
#include "model/graph/dgraph.hpp"
#include "model/graph/map_family.hpp"
#include "model/rewrite/match.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {
using graph::DGraph;
using rewrite::Match;
using rewrite::Rule;

enum class Engine { Smt, Enum };
const char* to_string(Engine e);

// What counts as a break. Preservation: an application (a match satisfying the gluing condition)
// whose H is not a map of the model. Consistency: also a match that fails the gluing condition
// (the rule cannot be applied where it matches; the property the incident-arcs condition I_r,
// with its dangling part, guarantees — Fact 1): the semantics condition plug-ins are validated
// against (condition_validation.hpp).
enum class Semantics { Preservation, Consistency };

struct EncodingOptions {
  DartSort sort = DartSort::BitVec;  // measured: docs/verify.md
  bool fixed_match = true;           // symmetry breaking: the k-th node of L on dart k
  bool incremental = true;  // one solver, push/pop per bound; false: a fresh solver per bound
  Semantics semantics = Semantics::Preservation;
  bool local_violations =
      true;  // look for violations at the touched nodes only (derivation_encoding.hpp)
};

struct Counterexample {
  Map G{0};
  Match match;                // L node -> dart of G (as nodes of to_dgraph(G))
  bool gluing_fails = false;  // Consistency: the match fails the gluing condition (no H)
  DGraph H;                   // the result of the derivation (rewriting construction)
  std::vector<ConstraintViolation> violations;  // of H (check_map_constraints)
  Engine engine = Engine::Smt;
};

struct VerifyResult {
  Engine engine = Engine::Smt;
  unsigned bound = 0;  // maps of at most `bound` darts
  bool preserves = true;
  bool applicable = false;  // some application within the bound
  std::optional<Counterexample> counterexample;
  double seconds = 0;
};

// One Z3 context and solver holding the map constraints of a model and bound, shared by the
// verifications of many rules (each in its own push/pop scope): the sweeps of
// condition_validation.hpp. `max_added`: most nodes a rule may add (numerals reserved).
class SmtSession {
 public:
  SmtSession(MapSpec spec, unsigned bound, unsigned max_added, const EncodingOptions& opt = {});
  ~SmtSession();
  SmtSession(const SmtSession&) = delete;
  SmtSession& operator=(const SmtSession&) = delete;
  VerifyResult verify(const Rule& r, bool applicable_check = true);
  const MapSpec& spec() const;
  unsigned bound() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt = {});
// applicable_check = false skips the applicability query (verdict only).
VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt,
                        bool applicable_check);
VerifyResult verify_enum(const Rule& r, unsigned bound, Semantics sem = Semantics::Preservation);
// On a family computed once (graph::map_family of the rule's model).
VerifyResult verify_enum(const Rule& r, const graph::MapFamily& family, Semantics sem);
inline VerifyResult verify(const Rule& r, unsigned bound, Engine e,
                           const EncodingOptions& opt = {}) {
  return e == Engine::Smt ? verify_smt(r, bound, opt) : verify_enum(r, bound, opt.semantics);
}

// Replays (G, node map) through the concrete derivation; nullopt when the node map is not a match
// satisfying the gluing condition or when H is a map of the model.
std::optional<Counterexample> replay(const Rule& r, const Map& G, const rewrite::NodeMap& nodes,
                                     Engine e);
std::optional<Counterexample> replay(const Rule& r, const Map& G, const rewrite::NodeMap& nodes,
                                     Engine e, Semantics sem);

}  // namespace gmr::smt
