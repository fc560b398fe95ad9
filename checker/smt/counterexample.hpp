// Verification reports and counterexamples as JSON and DOT (docs/verify.md).
//
//  * `to_json(Counterexample)`: the document "gmr.counterexample" (version 1): the rule, the
//    engine, G (a gmr.gmap document), the match (L node name -> dart), H (nodes and arcs, a D-graph
//    that is not a map), the broken constraints (kind, node of H, labels, text) and the darts of G
//    on which they lie ("offending_darts"; nodes added by the rule have no dart of G).
//  * `to_dot(Counterexample)`: G drawn by the map renderer (model/draw/map_dot.hpp), the matched
//    darts filled light blue and labelled by their L node, the offending darts filled red.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "checker/smt/rule_verifier.hpp"
#include "checker/smt/scheme_verifier.hpp"

namespace gmr::smt {

inline constexpr const char* kCounterexampleFormat = "gmr.counterexample";
inline constexpr int kCounterexampleVersion = 1;

// Darts of G under the nodes of H that break a constraint.
std::vector<Dart> offending_darts(const Counterexample& c);
nlohmann::ordered_json to_json(const Rule& r, unsigned bound, const Counterexample& c);
std::string to_dot(const Rule& r, const Counterexample& c);
// Summary of a verdict: "gmr.verify" document body (engine, bound, verdict, applicable, seconds).
nlohmann::ordered_json verdict_json(const VerifyResult& v);

}  // namespace gmr::smt
