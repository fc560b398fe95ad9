// Bounded verification of a Jerboa rule scheme through instantiation (thesis Defs. 88-89;
// docs/verify.md). An application of a scheme on a G-map instantiates it on the hook orbit(s) and
// applies the concrete rule by DPO. Every application on a map of at most k darts has a hook orbit
// of at most k darts, and every hook is instantiated on an orbit isomorphic to the reference
// hook's. So the scheme breaks no map of at most k darts iff, for every orbit graph O of the
// parameter <o> with at most k darts, the concrete rule instantiate_rule(S, O) breaks no map of
// at most k darts (rule_verifier.hpp; its match then sends each hook's instances onto an orbit
// of G isomorphic to O).
//
// `hook_orbits(<o>, k)`: every orbit graph with 1..k darts up to isomorphism: one involution per
// position of <o> (a fixed point is a loop), connected, and alpha_j alpha_i alpha_j alpha_i = id
// for positions whose dimensions differ by at least 2 (the cycle constraint of the maps it lives
// in). Brute force over involutions, pruned by the cycle constraint: fine up to 8 darts for |<o>|
// <= 2 and 7 darts for |<o>| = 3.
#pragma once
#include <optional>
#include <vector>

#include "checker/smt/rule_verifier.hpp"
#include "model/scheme/rule_scheme.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::smt {
using scheme::OrbitGraph;
using scheme::RuleScheme;

std::vector<OrbitGraph> hook_orbits(const OrbitType& o, unsigned max_darts);

struct SchemeVerifyResult {
  unsigned bound = 0;        // maps of at most `bound` darts
  unsigned orbit_bound = 0;  // hook orbits of at most this many darts
  size_t orbits = 0;         // orbit graphs instantiated
  size_t applicable = 0;     // instantiated rules with an application within the bound
  bool preserves = true;
  std::optional<OrbitGraph> orbit;     // the orbit of the counterexample
  std::optional<Rule> instance;        // its instantiated rule
  std::optional<VerifyResult> result;  // the concrete verdict with the counterexample
  double seconds = 0;
};

// orbit_bound 0: the bound (complete for maps of at most `bound` darts); smaller: only the hook
// orbits of at most orbit_bound darts (said so in the output).
SchemeVerifyResult verify_scheme(const RuleScheme& s, unsigned bound, Engine e,
                                 unsigned orbit_bound = 0, const EncodingOptions& opt = {});

}  // namespace gmr::smt
