// Topological folding (thesis §7.2, Algorithm 6, App. C).
//
// Input: a joint graph J (joint_graph.hpp: a connected G-map, or the joint representation κ(G,H) of
// a before/after pair), an orbit type <o> (no `_`) and a start dart a on side L. Output: a graph
// scheme P with hook h decorated <o> such that ι(P, J<o>(a)) = J with (a,h) ↦ a (thesis Def.
// 88–89), or the named reason why none exists.
//
//  Step 1 (createHook): O = J<o>(a) (Alg. 4, BFS, a gets index 0), h = node <o>, (b,h) = O[b].
//  Step 2.1 (arcExt), for each node m in BFS order and each d in ({0..n} ∪ {κ}) \ dims(m):
//    x = (a,m)@d;
//    - undefined: dimension d is not part of the rule at m — then no (b,m) may have a d-neighbour;
//    - x = (a,m') already: explicit arc m –d– m' (m' = m: an explicit loop); every (b,m) must be
//      d-linked to (b,m'), else INSTANTIATION FAILURE;
//    - x = (c,m'), c != a: ARC FAILURE (no explicit arc, which links (a,m) to (a,m'), and no
//      implicit arc, d not being in dims(m), produces this link);
//    - x unseen: new node v, explicit arc m –d– v, (b,v) = (b,m)@d for every b (a dart already
//      owned is an INSTANTIATION FAILURE), then step 2.2.
//  Step 2.2 (buildOrbType, κ never used): the relabeling of v (relabeling.hpp); if no consistent
//    relabeling exists, RELABELING FAILURE.
// Checks added by App. C for joint representations and selections: all-or-none neighbourhood per
// node and dimension (PARTIAL NEIGHBOURHOOD), and the instantiation must span every link of J
// (NOT SPANNING, checked at the end over every dart, dimension and κ). Two checks this
// implementation adds, named as such: PARTIAL HOOK ORBIT (a dart of J<o>(a) with an undefined
// o_p-neighbour: a case the thesis does not discuss; docs/inference.md) and NOT CONNECTED
// (darts of J the traversal never reached: the thesis assumes J connected).
//
// Cost O(|J|·(n+2)) plus the relabeling choices: linear in the size of J (thesis §7.5).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "inference/joint_graph.hpp"
#include "inference/relabeling.hpp"
#include "model/core/orbit_type.hpp"
#include "model/scheme/rule_scheme.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::inference {
using scheme::GraphScheme;
using scheme::OrbitGraph;

enum class FoldFailureKind {
  None,
  ArcFailure,            // step 2.1: (a,m) –d– (c,m'), c != a
  InstantiationFailure,  // step 2.1: an arc m –d– m' chosen from (a,m) is not instantiated at some
                         // b
  RelabelingFailure,     // step 2.2: no injective relabeling passes the check
  PartialNeighbourhood,  // App. C: some (b,m) has a d-neighbour and some has none
  NotSpanning,           // App. C: a link of J that ι(P, O) does not produce
  PartialHookOrbit,      // a dart of the hook orbit with an undefined o_p-neighbour (added check)
  NotConnected,          // J has darts the traversal never reached (added check)
};
const char* to_string(FoldFailureKind k);  // "arc failure", ...

// No node of the fold (its nodes are those of the graph scheme it builds: n0, n1, ...).
inline constexpr uint32_t kNoFoldNode = UINT32_MAX;
inline constexpr int kNoDimension = -2;

struct FoldFailure {
  FoldFailureKind kind = FoldFailureKind::None;
  uint32_t node = kNoFoldNode;  // node at which it was found (name "n<node>")
  int dim = kNoDimension;       // the dimension (0..n, or kKappa)
  int position = -1;            // relabeling failure / partial hook orbit: the position p of <o>
  std::vector<uint32_t> darts;  // joint-graph darts involved
  std::string message;          // full sentence, darts described as users see them
};

struct FoldNode {
  OrbitType label;  // positional relabeling of <o> (kHole = `_`)
  Side side = Side::L;
  std::vector<uint32_t> darts;  // darts[b] = (b, node): the dart of J standing for orbit dart b
};

// Undirected explicit arc; dim in 0..n or kKappa. a == b is a loop.
struct FoldArc {
  uint32_t a = 0, b = 0;
  int dim = 0;
};

struct FoldOptions {
  LoopPolicy loops;
  // Plurality of answers (thesis §7.6): when set, every node built after the hook records how many
  // consistent relabelings it has (FoldResult::alternatives, in the order of
  // enumerate_relabelings), and node k takes the choices[k-1]-th of them (0, the documented default
  // choice, for nodes beyond the vector). fold_all walks every combination.
  bool record_alternatives = false;
  std::vector<uint32_t> choices;
};

struct FoldResult {
  OrbitType orbit;
  uint32_t start = 0;
  OrbitGraph hook_orbit;        // O = J<o>(a): darts = origin ids of the hook's darts, nb table
  std::vector<FoldNode> nodes;  // node 0 is the hook; on failure, the nodes built so far
  std::vector<FoldArc> arcs;
  FoldFailure failure;
  bool ok() const { return failure.kind == FoldFailureKind::None; }
  // With FoldOptions::record_alternatives: alternatives[k-1] = number of consistent relabelings of
  // node k (k >= 1, nodes built before the end or the failure).
  std::vector<uint32_t> alternatives;
};

// Scratch space of folds on one joint graph: the (node, index) owner of every dart, reset after
// each fold through the list of darts it touched, so that a fold that fails early costs what it
// visited and not |J| (the driver runs up to |J|/|O| folds per orbit type).
class FoldWorkspace {
 public:
  explicit FoldWorkspace(size_t darts) : node_of(darts, UINT32_MAX), index_of(darts, UINT32_MAX) {}
  std::vector<uint32_t> node_of, index_of, touched;
};

// Algorithm 6. Throws Error(Usage) when <o> has `_`, repeats a dimension or exceeds n, when the
// start dart is out of range or on side R. Failure is a result, never an exception. `ws` (optional)
// must have been made for j.
FoldResult fold(const JointGraph& j, const OrbitType& o, uint32_t start,
                const FoldOptions& opt = {}, FoldWorkspace* ws = nullptr);

// Every successful fold over all combinations of consistent relabelings (the default choice first),
// at most `limit` folds run. Each result carries its choices in FoldResult::alternatives' order.
struct FoldAll {
  std::vector<FoldResult> folds;
  std::vector<std::vector<uint32_t>> choices;  // choices[i]: the choice vector of folds[i]
  size_t runs = 0;
  bool truncated = false;  // the limit was reached
};
FoldAll fold_all(const JointGraph& j, const OrbitType& o, uint32_t start,
                 const FoldOptions& opt = {}, size_t limit = 1000, FoldWorkspace* ws = nullptr);

// "n<k>".
std::string node_name(uint32_t k);

// The graph scheme of a successful fold of a single map (all nodes on side L, no κ): nodes n0, n1,
// ... in creation order, labels and explicit arcs as folded. Throws Error(Usage) otherwise.
GraphScheme to_graph_scheme(const FoldResult& f);

}  // namespace gmr::inference
