// Text and JSON of the validation reports of conditions (docs/verify.md): the one writer of
// ValidationReport (condition_validation.hpp, the enumerating engines), SymbolicReport
// (symbolic_validation.hpp) and SchemeValidationReport (scheme_conditions.hpp). Documents
// "gmr.condition-validation" (concrete rules, both engines) and "gmr.scheme-condition-validation",
// version 1; their counterexamples are "gmr.counterexample" documents (counterexample.hpp).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "checker/smt/condition_validation.hpp"
#include "checker/smt/scheme_conditions.hpp"
#include "checker/smt/symbolic_validation.hpp"

namespace gmr::smt {

inline constexpr const char* kValidationFormat = "gmr.condition-validation";

// Concrete rules, the enumerating engines.
std::string to_text(const ValidationReport& r);
nlohmann::ordered_json to_json(const ValidationReport& r);

// Concrete rules, the symbolic engine.
std::string to_text(const SymbolicReport& r);
nlohmann::ordered_json to_json(const SymbolicReport& r);

// Rule schemes.
std::string to_text(const SchemeValidationReport& r);
// The "gmr.scheme-condition-validation" document; `sufficient_only` as the condition declares it.
nlohmann::ordered_json to_json(const SchemeValidationReport& r, bool sufficient_only);

// The text lines of an unsoundness witness: the rule, the map size, the match and the broken
// constraint (or the failing gluing condition).
std::string unsound_witness_text(const ValidationWitness& w);
// The first members of every gmr.condition-validation document: format, version, condition,
// engine (omitted when empty), model, n, labels.
nlohmann::ordered_json validation_header(const std::string& condition, const std::string& engine,
                                         const ValidationOptions& o);
// The verdict counts of a report over a list (rules or schemes): holds, fails, vacuous, unsound,
// incomplete, sound, complete.
template <class Report>
void put_verdict_counts(nlohmann::ordered_json& j, const Report& r) {
  j["holds"] = r.holds;
  j["fails"] = r.fails;
  j["vacuous"] = r.vacuous;
  j["unsound"] = r.unsound;
  j["incomplete"] = r.incomplete;
  j["sound"] = r.sound();
  j["complete"] = r.complete();
}

// Merges the JSON reports of the shards of one sweep (same condition, engine, model, labels,
// bounds and shard count M; distinct K): counts added, `nodes_covered` the least, the smallest
// witnesses the least of the shards' (nodes, then darts, then family index); "shard" lists the
// shards merged. Error(Usage), located by file index, when the reports do not belong together.
nlohmann::ordered_json merge_reports(const std::vector<nlohmann::json>& shards);

}  // namespace gmr::smt
