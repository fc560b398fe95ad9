// Static detection of topological events (Gaide et al. 2023, §3): from a rule scheme alone, for
// every orbit type <o> and every pattern orbit, the events the rule causes on the orbits it
// matches, each certain or possible (to be confirmed at application time on the instance pairs it
// lists). This is the static pass of the paper's Defs. 3.1.1–3.4.2 made executable; the paper has
// no pseudo-code. docs/events.md lists the readings chosen where the paper is silent or wrong.
//
// Per <o>, with L<o>- and R<o>-pattern orbits (pattern_orbit.hpp), P = preserved nodes:
//  * creation (Def./Prop. 3.1.1): an R pattern orbit of created nodes only. Certain.
//  * deletion (Def./Prop. 3.4.1): an L pattern orbit of deleted nodes only. Certain.
//  * explicit split (Def. 3.2.1a): the preserved nodes of an L pattern orbit C fall in several R
//    pattern orbits. Certain when one of these R pattern orbits is complete: its instance is then a
//    whole H-orbit holding no dart of the others, while the same-b darts of C are in one G-orbit.
//    The paper asks for C complete (Prop. 3.2.1), which is not needed, and claims the R pattern
//    orbits are then complete too (proof of Prop. 3.2.1), which is false when a preserved node of
//    another, incomplete L pattern orbit joins one of them; so the R side is tested.
//  * implicit split along position k (Def. 3.2.1b), per pair (C, D) of an L pattern orbit and an R
//    pattern orbit holding some of its preserved nodes: some node of C has λ^L_k in <o> and no node
//    of D has λ^R_k in <o>. Always possible, never certain: the paper gives the complete case as
//    static (§3.2, Table 1), but the two linked instances may end up in one H-orbit or be one dart
//    (an i-loop of the hook orbit); the border-edge deletion is the counterexample (a named test).
//  * explicit and implicit merges (Def. 3.3.1a/b): the same with L and R exchanged. An explicit
//    merge is certain when one of the merged L pattern orbits is complete (Prop. 3.3.1.1).
//  * otherwise (an L pattern orbit with preserved nodes and no flag): non-modification when its R
//    pattern orbit has the same nodes, the same explicit <o>-arcs and, at every node, the same
//    label value at every position whose value is in <o> on either side (Def. 3.4.2, compared on
//    the positions that matter for <o>: the paper's example n0 <0,1> -> <0,_> is not modified on
//    <0>); else modification (§3.4.3, the residual class). Both are static.
// Splits are confirmed on H (after the rewrite), merges on G (before it); the paper says "on G" for
// both (Props. 3.2.1, 3.3.1), which cannot confirm a split.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "checker/events/pattern_orbit.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::events {

enum class PatternEventKind {
  Creation,
  Deletion,
  ExplicitSplit,
  ImplicitSplit,
  ExplicitMerge,
  ImplicitMerge,
  Modification,
  NonModification,
};
const char* to_string(PatternEventKind k);
bool is_split(PatternEventKind k);
bool is_merge(PatternEventKind k);

enum class Certainty { Certain, Possible };
const char* to_string(Certainty c);

// Two instance darts to compare at run time: the darts of L nodes `a` and `b` (both preserved;
// indices in L) at the same orbit index b (position < 0) or at indices b and b⊕position. Splits
// compare them on H, merges on G; the event holds at an instance when they lie in different orbits.
struct InstancePair {
  uint32_t a = 0, b = 0;
  int position = -1;
};

struct PatternEvent {
  PatternEventKind kind = PatternEventKind::Modification;
  Certainty certainty = Certainty::Certain;
  std::vector<uint32_t> left;       // L pattern orbits (indices) involved
  std::vector<uint32_t> right;      // R pattern orbits involved
  std::vector<uint32_t> positions;  // implicit events: the positions k (0-based)
  std::vector<InstancePair> pairs;  // split / merge: the instance pairs that confirm it
};

struct OrbitTypeEvents {
  OrbitType orbit;
  PatternOrbits left, right;
  std::vector<PatternEvent> events;
  // Per L pattern orbit with preserved nodes: what its instances undergo when no flagged split or
  // merge is confirmed there (NonModification or Modification).
  std::vector<PatternEventKind> residual;
};

struct StaticEvents {
  std::string rule;
  int dimension = 0;
  std::vector<OrbitTypeEvents> orbits;
  // Per L node, its R node (the preserved node of the same name), or kDeletedNode: read at every
  // application (event_log.hpp), so resolved once per rule.
  std::vector<uint32_t> right_of;
  static constexpr uint32_t kDeletedNode = UINT32_MAX;
};

// The 2^(n+1) orbit types over 0..n, by increasing size then lexicographically (<>, <0>, <1>, ...).
std::vector<OrbitType> all_orbit_types(int n);

// The static events of `s` for each orbit type of `types` (all of them when empty). Throws
// gmr::Error(Schema) for a malformed scheme (RuleScheme::validate_structure) and Error(Range) for
// an orbit type with `_` or a dimension above the scheme's.
StaticEvents analyse(const scheme::RuleScheme& s, const std::vector<OrbitType>& types = {});

// "L<0,1>(n0)": a pattern orbit named by its first node.
std::string pattern_orbit_name(const scheme::RuleScheme& s, const OrbitTypeEvents& t, Side side,
                               uint32_t c);

}  // namespace gmr::events
