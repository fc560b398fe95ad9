#include "checker/smt/scheme_conditions.hpp"

#include <chrono>

#include "checker/scheme_checker.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/counterexample.hpp"

namespace gmr::smt {

namespace {
checker::CheckReport topology(const RuleScheme& s) {
  checker::SchemeCheckOptions o;
  o.embeddings = false;
  return checker::check_scheme(s, o);
}
// No error diagnostic except those whose code `ignored` accepts.
bool no_error_but(const RuleScheme& s,
                  const std::function<bool(const checker::Diagnostic&)>& ignored) {
  for (const auto& d : topology(s).diagnostics)
    if (d.severity == checker::Severity::Error && !ignored(d)) return false;
  return true;
}
}  // namespace

const std::vector<SchemeCondition>& builtin_scheme_conditions() {
  static const std::vector<SchemeCondition> all = {
      {"scheme-thesis",
       "Theorems 4-6: I_S, O_S, C_S for every dimension and pair (sufficient only)", true,
       [](const RuleScheme& s) { return topology(s).ok(); }},
      {"wrong-scheme-cycle-dropped", "WRONG: I_S and O_S only, C_S dropped", true,
       [](const RuleScheme& s) {
         return no_error_but(
             s, [](const checker::Diagnostic& d) { return d.condition.rfind("C(", 0) == 0; });
       }},
      {"wrong-scheme-dangling-dropped", "WRONG: I_S without its dangling part (deleted nodes)",
       true,
       [](const RuleScheme& s) {
         return no_error_but(
             s, [](const checker::Diagnostic& d) { return d.code == "I-deleted-node"; });
       }},
  };
  return all;
}

const SchemeCondition* find_builtin_scheme_condition(const std::string& name) {
  for (const auto& c : builtin_scheme_conditions())
    if (c.name == name) return &c;
  return nullptr;
}

std::vector<bool> evaluate_scheme_condition(const SchemeCondition& c,
                                            const std::vector<RuleScheme>& schemes) {
  std::vector<bool> holds;
  for (const RuleScheme& s : schemes) holds.push_back(c.holds(s));
  return holds;
}

SchemeValidationReport validate_scheme_condition(const SchemeCondition& c,
                                                 const std::vector<RuleScheme>& schemes,
                                                 unsigned bound) {
  return validate_scheme_condition(c.name, evaluate_scheme_condition(c, schemes), schemes, bound);
}

SchemeValidationReport validate_scheme_condition(const std::string& name,
                                                 const std::vector<bool>& holds,
                                                 const std::vector<RuleScheme>& schemes,
                                                 unsigned bound) {
  return classify_scheme_condition(name, holds, schemes, verify_scheme_family(schemes, bound));
}

SchemeFamilyVerdicts verify_scheme_family(const std::vector<RuleScheme>& schemes, unsigned bound) {
  const auto t0 = std::chrono::steady_clock::now();
  SchemeFamilyVerdicts out;
  out.bound = bound;
  EncodingOptions eo;
  eo.semantics = Semantics::Consistency;
  out.results.reserve(schemes.size());
  for (const RuleScheme& s : schemes)
    out.results.push_back(verify_scheme(s, bound, Engine::Smt, 0, eo));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

SchemeValidationReport classify_scheme_condition(const std::string& name,
                                                 const std::vector<bool>& holds,
                                                 const std::vector<RuleScheme>& schemes,
                                                 const SchemeFamilyVerdicts& verdicts) {
  const auto t0 = std::chrono::steady_clock::now();
  SchemeValidationReport rep;
  rep.condition = name;
  rep.bound = verdicts.bound;
  const auto darts = [](const SchemeVerifyResult& r) { return r.result->counterexample->G.size(); };
  for (size_t k = 0; k < schemes.size(); ++k) {
    const SchemeVerifyResult& v = verdicts.results[k];
    ++rep.schemes;
    (holds[k] ? rep.holds : rep.fails)++;
    if (v.applicable == 0 && v.preserves) {
      ++rep.vacuous;
    } else if (holds[k] && !v.preserves) {
      ++rep.unsound;
      if (!rep.smallest_unsound || darts(v) < darts(rep.smallest_unsound->result))
        rep.smallest_unsound = SchemeWitness{schemes[k], v};
    } else if (!holds[k] && v.preserves) {
      ++rep.incomplete;
      if (!rep.first_incomplete) rep.first_incomplete = schemes[k];
    }
  }
  rep.seconds = verdicts.seconds +
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

}  // namespace gmr::smt
