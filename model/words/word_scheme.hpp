// Graph schemes and rule schemes with (word, dimension) arc labels, and their instantiation on a
// pattern graph (thesis §4.3–4.4, Defs. 44–47).
//
//  * Graph scheme (Def. 44): a (W × D)-graph; an arc n -> n' carries a word w ∈ W and a dimension
//  d.
//    Core π_D (Def. 45) keeps d only.
//  * Instantiation ι(Π,P) = π_D(E_D(P) × Π), used in its operational form (§4.3): nodes (u,n) for
//    every u of P and n of Π, named "u:n"; for every w-arc u -> u' of P and every (w,d)-arc
//    n -> n' of Π, one d-arc (u,n) -> (u',n'). Node (u,n) has id n·|P| + u.
//  * Rule scheme (Def. 46): L, R with shared node names (preserved nodes); an arc is preserved iff
//    an arc with the same ends and the same full (w,d) label exists on the other side (k-th
//    parallel copy paired with k-th, as in model/rewrite/rule.hpp). ι(S,P) (Def. 47) instantiates L
//    and R on the same P and gives a concrete gmr::Rule. Its interface is deduced by Assumption 4
//    on the instantiated arcs, which can pair a deleted arc (from a word w) with an added arc (from
//    w' ≠ w) with the same ends and dimension: the DPO result is the same.
//  * Application at a hook (§4.4): P_v for the hook dart v, ι(S,P_v), match (u,hook) ↦ u propagated
//    along the arcs of ι(L,P_v) (G satisfies I_G, so each step is forced), then DPO
//    (model/rewrite/dpo.hpp). One hook only (one connected component of L): how several hooks with
//    different P_v are instantiated is left open by the thesis.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rewrite/rule.hpp"
#include "model/words/pattern_graph.hpp"
#include "model/words/word_rewriting.hpp"

namespace gmr::words {
using graph::DGraph;
using graph::Node;
using rewrite::MapDerivation;
using rewrite::Rule;

struct WordArc {
  uint32_t src = 0, tgt = 0;
  PathWord word;
  int dim = 0;
  friend bool operator==(const WordArc&, const WordArc&) = default;
};

class WordGraphScheme {
 public:
  std::vector<std::string> nodes;
  std::vector<WordArc> arcs;

  size_t size() const { return nodes.size(); }
  uint32_t add_node(std::string name);  // throws Error(Schema) for an empty or duplicate name
  std::optional<uint32_t> find(const std::string& name) const;
  // By names (Error(Schema) for an unknown name). `word` is parsed with parse_word.
  void add_arc(const std::string& src, const std::string& tgt, const std::string& word, int dim);
  // src -(w,d)-> tgt and tgt -(conj w,d)-> src; a loop whose word is self-conjugate is one arc.
  void add_link(const std::string& a, const std::string& b, const std::string& word, int dim);
  // π_D: the core (node names kept).
  DGraph core() const;
};

// ι(Π,P). Throws Error(Schema) when a word of Π is not in P.words.
DGraph instantiate_word_graph(const WordGraphScheme& S, const PatternGraph& P);
inline Node instance_node(const PatternGraph& P, uint32_t n, Node u) {
  return Node(static_cast<uint32_t>(n * P.size() + u.index()));
}

struct WordRuleScheme {
  std::string name;
  int n = 2;
  MapKind kind = MapKind::GMap;
  WordGraphScheme left, right;
  std::string hook;  // an L node

  // Scheme-level arc status (Def. 46): for each arc of L, the paired arc of R (same end names,
  // same word, same dimension), or nullopt when deleted.
  std::vector<std::optional<uint32_t>> preserved_arcs() const;
  // The core rule π_D(S) (= ι(S, 1_W) when W's words are all in the scheme): a gmr::Rule.
  Rule core() const;
};

// ι(S,P) as a concrete rule on the scheme's dimension and map kind.
Rule instantiate_word_rule(const WordRuleScheme& S, const PatternGraph& P);

// The match of ι(L,P) in G with (u, hook) ↦ P.origin[u], propagated along the arcs of ι(L,P).
// nullopt when propagation fails (a missing arc, conflicting images, non-injective, or an L node
// unreachable from the hook copies).
std::optional<rewrite::NodeMap> propagate_match(const WordRuleScheme& S, const PatternGraph& P,
                                                const Rule& inst, const DGraph& G);

// S instantiated at dart d of g with the word set W: a concrete rule and its match in g, applied
// by rewrite::apply (model/rewrite/dpo.hpp; docs/architecture.md, "Applying rules").
struct WordSchemeInstance {
  PatternGraph pattern;     // P_v, the component of P_(G,W) holding d
  Rule rule;                // ι(S, P_v)
  std::vector<Dart> match;  // per L node of `rule`
};
// Throws Error(Usage) when d is not a dart of g or the propagated match fails.
WordSchemeInstance instantiate_at(const Map& g, const WordRuleScheme& S,
                                  const std::vector<PathWord>& W, Dart d);

}  // namespace gmr::words
