// Bounded verification of a concrete rule (docs/verify.md): "no map of the model with at most
// `bound` darts has an application of the rule (a match satisfying the gluing condition, thesis
// Defs. 24-25) whose result H breaks a constraint of the model (Def. 32)", or a counterexample.
//
// Two engines, whose verdicts are compared in checker/smt/tests:
//  * Smt   the encodings of map_encoding.hpp and derivation_encoding.hpp; one solver, the map
//          constraints asserted once, then for b = max(1, |V_L|) .. bound a push, `size = b`, a
//          check and a pop (incremental solving; the first counterexample has the fewest darts).
//          Every model is replayed through the concrete derivation (rewrite/dpo.hpp) and
//          checked with check_gmap_constraints: an encoding error would stop the run
//          (std::logic_error) instead of reporting a false counterexample.
//  * Enum  the exhaustive enumerator (checker/semantic.hpp) on map_family(n, kind, bound).
// `applicable` tells whether some application exists within the bound (a second SMT query
// without the violation, when no counterexample was found): a rule that never applies preserves
// the model vacuously.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "checker/smt/map_encoding.hpp"
#include "model/core/gmap.hpp"
#include "model/graph/constraints.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/match.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {
using graph::ConstraintViolation;
using graph::DGraph;
using rewrite::Match;
using rewrite::Rule;

enum class Engine { Smt, Enum };
const char* to_string(Engine e);

struct EncodingOptions {
  DartSort sort = DartSort::Int;
  bool fixed_match = true;   // symmetry breaking: the k-th node of L on dart k
  bool incremental = true;   // one solver, push/pop per bound; false: a fresh solver per bound
};

struct Counterexample {
  GMap G{0};
  Match match;              // L node -> dart of G (as nodes of to_dgraph(G))
  DGraph H;                 // the result of the derivation (derive_in_place)
  std::vector<ConstraintViolation> violations;  // of H (check_gmap_constraints)
  Engine engine = Engine::Smt;
};

struct VerifyResult {
  Engine engine = Engine::Smt;
  unsigned bound = 0;       // maps of at most `bound` darts
  bool preserves = true;
  bool applicable = false;  // some application within the bound
  std::optional<Counterexample> counterexample;
  double seconds = 0;
};

VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt = {});
// applicable_check = false skips the applicability query (verdict only).
VerifyResult verify_smt(const Rule& r, unsigned bound, const EncodingOptions& opt, bool applicable_check);
VerifyResult verify_enum(const Rule& r, unsigned bound);
inline VerifyResult verify(const Rule& r, unsigned bound, Engine e, const EncodingOptions& opt = {}) {
  return e == Engine::Smt ? verify_smt(r, bound, opt) : verify_enum(r, bound);
}

// Replays (G, node map) through the concrete derivation; nullopt when the node map is not a match
// satisfying the gluing condition or when H is a map of the model.
std::optional<Counterexample> replay(const Rule& r, const GMap& G, const std::vector<graph::Node>& nodes, Engine e);

}  // namespace gmr::smt
