// Conditions on rule schemes (thesis Ch. 4, Theorems 4-6) registered by name, validated through
// instantiation (scheme_verifier.hpp; docs/verify.md, "Scheme conditions"): over a list of schemes
// and every G-map of at most k darts,
//   unsound     the condition holds, but some application (an instance on a hook orbit of at most
//               k darts, matched on a map of at most k darts) fails the gluing condition or breaks
//               the map (consistency semantics, rule_verifier.hpp);
//   incomplete  the condition fails, the scheme applies within the bound, and every application
//               glues and preserves; for a condition that is sufficient only (Theorem 6) this is
//               counted, not a failure of the theorem;
//   vacuous     no application within the bound.
// Built-in conditions (scheme_checker.hpp, topology only: embedding expressions are not evaluated):
//   scheme-thesis                  structure, hooks, I_S(d) (Thm. 4), O_S(d) (Thm. 5), C_S(i,j)
//                                  (Thm. 6) for every dimension and pair: sufficient only (Thm. 6);
// and two deliberately wrong variants, which the validation must refute:
//   wrong-scheme-cycle-dropped     no C_S;
//   wrong-scheme-dangling-dropped  I_S without its dangling part (I-deleted-node ignored).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/smt/scheme_verifier.hpp"

namespace gmr::smt {

struct SchemeCondition {
  std::string name;
  std::string description;
  bool sufficient_only = false;  // incompleteness is expected (Theorem 6)
  std::function<bool(const RuleScheme&)> holds;
};

const std::vector<SchemeCondition>& builtin_scheme_conditions();
const SchemeCondition* find_builtin_scheme_condition(const std::string& name);

struct SchemeWitness {
  RuleScheme scheme;
  SchemeVerifyResult result;  // unsound: the breaking instance and counterexample
};

struct SchemeValidationReport {
  std::string condition;
  unsigned bound = 0;
  size_t schemes = 0, holds = 0, fails = 0, vacuous = 0, unsound = 0, incomplete = 0;
  std::optional<SchemeWitness> smallest_unsound;  // fewest darts in the counterexample's G
  std::optional<RuleScheme> first_incomplete;
  double seconds = 0;
  bool sound() const { return unsound == 0; }
  bool complete() const { return incomplete == 0; }
};

SchemeValidationReport validate_scheme_condition(const SchemeCondition& c,
                                                 const std::vector<RuleScheme>& schemes,
                                                 unsigned bound);

// The two phases of a validation, for several conditions over one family: the verdict of every
// scheme (verify_scheme, consistency semantics; independent of any condition), then a condition's
// classification against them (holds[k] and verdicts[k] for schemes[k]).
struct SchemeFamilyVerdicts {
  unsigned bound = 0;
  std::vector<SchemeVerifyResult> results;  // results[k] for schemes[k]
  double seconds = 0;
};
SchemeFamilyVerdicts verify_scheme_family(const std::vector<RuleScheme>& schemes, unsigned bound);
SchemeValidationReport classify_scheme_condition(const std::string& name,
                                                 const std::vector<bool>& holds,
                                                 const std::vector<RuleScheme>& schemes,
                                                 const SchemeFamilyVerdicts& verdicts);
std::vector<bool> evaluate_scheme_condition(const SchemeCondition& c,
                                            const std::vector<RuleScheme>& schemes);
// The same with the condition's verdicts given (holds[k] for schemes[k]: a plug-in's, evaluated in
// its guarded child, condition_plugin.hpp).
SchemeValidationReport validate_scheme_condition(const std::string& name,
                                                 const std::vector<bool>& holds,
                                                 const std::vector<RuleScheme>& schemes,
                                                 unsigned bound);

}  // namespace gmr::smt
