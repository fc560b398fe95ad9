// Direct derivations G =(r,m)=> H for concrete rules (thesis Defs. 24–25).
//
// The match must be a monomorphism (Assumption 1); the gluing condition then reduces to the
// dangling condition: no arc of G outside m(L) may be incident to the image of a deleted node.
// `dangling_arcs` names every such arc; the derivations throw Error(Usage) naming the first one.
//
// `derive` is the definition on D-graphs (the semantics the other applications are tested
// against); `apply` applies a concrete rule to a map at one match and returns the result as a new
// map (docs/architecture.md, "Applying rules"). Each is computed by one of two independent
// constructions (`Construction`), kept and tested against each other:
//  * Categorical — the pushout complement D (G minus the images of the deleted nodes and arcs, as
//    a new graph with the inclusion D -> G), then the pushout H of D <- L∩R -> R (D ⊔ (R \ L∩R)
//    glued along L∩R), with the comatch m': R -> H; on maps, through to_dgraph/to_map;
//  * Rewriting — editing a copy of G: remove the matched deleted arcs, append the added nodes and
//    arcs, then compact the deleted nodes away by moving the last node into each hole. On maps the
//    links of a copy are rewritten directly (Jerboa style) in phases: check the match (injective,
//    arcs present) and the gluing condition, take fresh darts for added nodes, remove the deleted
//    L arcs and write the added R arcs, check incident arcs on every touched dart, remove the
//    deleted darts.
// Both give isomorphic H with the same comatch (`same_derivation` checks the bijection induced by
// the two tracks G -> H and R -> H). H node names: G nodes keep theirs; added nodes are named
// "<R name>'" (a prime per application). On maps both throw Error(InvalidMap) when H is not
// combinatorial (the dart and dimension are named) — other constraints of H (O, C) are left to
// validity.hpp.
#pragma once
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/rewrite/match.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::rewrite {

struct DanglingArc {
  Node l_node;  // the deleted node of L
  ArcId g_arc;  // the arc of G incident to its image and not in m(L)
  std::string describe(const Rule& r, const DGraph& G) const;
};
std::vector<DanglingArc> dangling_arcs(const Rule& r, const DGraph& G, const Match& m);
inline bool satisfies_gluing(const Rule& r, const DGraph& G, const Match& m) {
  return dangling_arcs(r, G, m).empty();
}

// Throws Error(Usage) when m is not an injective label-preserving morphism L -> G.
void check_match(const Rule& r, const DGraph& G, const Match& m);

struct Derivation {
  DGraph D;                         // pushout complement (categorical construction only)
  HandleVector<Node, Node> d_to_g;  // D node -> G node (categorical construction only)
  DGraph H;
  HandleVector<Node, Node> g_to_h;         // G node -> H node; kNoNode for deleted nodes
  HandleVector<Node, Node> comatch;        // R node -> H node
  HandleVector<ArcId, ArcId> comatch_arc;  // R arc slot -> H arc (kNoArc for dead slots)
};

// The two constructions of a direct derivation (see above). Neither changes its input.
enum class Construction {
  Categorical,  // pushout complement, then pushout
  Rewriting,    // a copy of G edited
};

// The direct derivation of G by r at m (Def. 25).
Derivation derive(const Rule& r, const DGraph& G, const Match& m,
                  Construction c = Construction::Categorical);

// True iff the map  H1 -> H2  defined by  g_to_h1[g] |-> g_to_h2[g]  and  comatch1[v] |->
// comatch2[v] is a well-defined label-preserving graph isomorphism (arc multiplicities included)
// that also sends comatch_arc1 to arcs with the same ends as comatch_arc2. `why` gets the first
// difference.
bool same_derivation(const Derivation& a, const Derivation& b, std::string* why = nullptr);

struct MapDerivation {
  Map H{0};
  std::vector<Dart> g_to_h;   // dart of G -> dart of H (kNoDart for deleted darts)
  std::vector<Dart> comatch;  // R node -> dart of H
};
// Matches are node maps L node -> dart.
std::vector<std::vector<Dart>> find_map_matches(const Rule& r, const Map& g,
                                                size_t limit = SIZE_MAX);
// r applied to g at `match` (L node -> dart); g is unchanged.
MapDerivation apply(const Rule& r, const Map& g, const std::vector<Dart>& match,
                    Construction c = Construction::Rewriting);

}  // namespace gmr::rewrite
