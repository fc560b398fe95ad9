// Jerboa rule schemes (thesis Ch. 6, Defs. 86–87).
//
// A rule scheme L -> R of dimension n is parameterised by an orbit type <o> (no `_`). Each side is
// a graph scheme:
//  * nodes, each with a name and a *label*: a generalised orbit type of the same arity as <o>, read
//    positionally (<o> -> <o^v>, Def. 86): position p carries the pattern dimension o[p] into the
//    node's dimension o^v[p], or deletes it when o^v[p] is `_` (OrbitType::kHole). These are the
//    node's *implicit arcs*;
//  * explicit arcs a –i– b, undirected (G-maps), a == b being an i-loop;
//  * an optional list of embedding expressions per node (text in the language of
//    docs/embeddings.md, parsed and typed by model/expr; they only matter on right nodes).
// The embeddings the expressions write are declared once per scheme (name, orbit type, value
// type; thesis Def. 69, the embedding type graph).
// Nodes are preserved when their name occurs on both sides, deleted when only in L, added when only
// in R. Hooks are L nodes (names), one per connected component of L; the first hook is the
// reference hook and its label is normally <o> itself.
//
// The structure is plain data: no invariant is enforced on construction. `validate_structure`
// reports the structural problems that make a scheme unusable (unknown names, out-of-range
// dimensions, wrong arity); the scheme checker (checker/scheme_checker.hpp) reports everything
// else.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/core/orbit_type.hpp"
#include "model/graph/elem_status.hpp"

namespace gmr::scheme {

struct EmbeddingExpression {
  std::string embedding;    // e.g. "position"
  std::string code;         // expression text (docs/embeddings.md); empty when `unsupported`
  std::string jerboa;       // the Jerboa (Java) code it was translated from, when imported
  std::string unsupported;  // why the Jerboa code could not be translated (then code is empty)
  friend bool operator==(const EmbeddingExpression&, const EmbeddingExpression&) = default;
};

// An embedding pi : <o_pi> -> tau_pi (thesis §5.2.2). `type` is the value type's name in the
// expression language ("point", "vector", "scalar", "colour"), checked by model/expr.
struct EmbeddingDeclaration {
  std::string name;
  OrbitType orbit;
  std::string type;
  friend bool operator==(const EmbeddingDeclaration&, const EmbeddingDeclaration&) = default;
};

struct SchemeNode {
  std::string name;
  OrbitType label;
  std::vector<EmbeddingExpression> expressions;
  friend bool operator==(const SchemeNode&, const SchemeNode&) = default;
};

// Undirected explicit arc a –dim– b (indices into the side's node list); a == b is a loop.
struct SchemeArc {
  uint32_t a = 0, b = 0;
  int dim = 0;
  bool is_loop() const { return a == b; }
  friend bool operator==(const SchemeArc&, const SchemeArc&) = default;
};

class GraphScheme {
 public:
  std::vector<SchemeNode> nodes;
  std::vector<SchemeArc> arcs;

  size_t size() const { return nodes.size(); }
  std::optional<uint32_t> find(const std::string& name) const;
  uint32_t add_node(std::string name, OrbitType label);
  // By names; throws Error(Schema) for an unknown name.
  void add_arc(const std::string& a, const std::string& b, int dim);
  // Explicit arcs incident to node v with dimension d (a loop counts once).
  size_t count_explicit(uint32_t v, int d) const;
  // Number of d-arcs at v: explicit ones plus the positions of its label equal to d (the count of
  // Alg. 1 on the core, a loop counting once).
  size_t count_arcs(uint32_t v, int d) const;
  // The other end of the explicit d-arc at v (v itself for a loop), when there is exactly one.
  std::optional<uint32_t> explicit_neighbor(uint32_t v, int d) const;
  // Connected components over explicit arcs: comp[v] in 0..k-1, returns k.
  size_t components(std::vector<uint32_t>& comp) const;

  friend bool operator==(const GraphScheme&, const GraphScheme&) = default;
};

// The role of a scheme node: the node status of a concrete rule (one enum for both).
using NodeRole = graph::ElemStatus;

class RuleScheme {
 public:
  std::string name;
  std::string description;  // free text (Jerboa comment)
  int dimension = 2;        // n: the scheme rewrites n-G-maps
  OrbitType orbit;          // <o>: the parameter of the rule (no `_`)
  GraphScheme left, right;
  std::vector<std::string> hooks;  // names of L nodes; hooks[0] is the reference hook
  std::vector<EmbeddingDeclaration> embeddings;
  // Jerboa precondition / other code, kept as text (never evaluated; the checker warns).
  std::string precondition;

  // Role of a node of the given side by name.
  NodeRole role_left(uint32_t v) const;
  NodeRole role_right(uint32_t v) const;
  // Index on the other side, if the node is preserved.
  std::optional<uint32_t> right_of(uint32_t left_node) const;
  std::optional<uint32_t> left_of(uint32_t right_node) const;
  // Indices (in `left`) of the hooks; throws Error(Schema) for a hook that is not an L node.
  std::vector<uint32_t> hook_nodes() const;
  // The declaration of embedding `name`, or nullptr.
  const EmbeddingDeclaration* find_embedding(const std::string& name) const;

  // Throws Error(Schema) with a location ("L node n1", "R arc 3", "hook 0") for: arity of a label
  // different from |<o>|, dimension outside 0..n (or -1 = `_` in a label), `_` in <o>, unknown or
  // duplicate node name, arc end out of range, hook naming no L node, n outside 0..kMaxDim-1.
  void validate_structure() const;

  friend bool operator==(const RuleScheme&, const RuleScheme&) = default;
};

// "n0 <_,1,2>" (the papers' node label).
std::string node_label_text(const SchemeNode& n);

}  // namespace gmr::scheme
