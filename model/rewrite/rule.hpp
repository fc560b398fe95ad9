// Concrete DPO rules L <- L∩R -> R on D-graphs (thesis §2.2, §3.3.2).
//
// A rule is written as two D-graphs L and R whose nodes are named; a node name occurring on both
// sides is a preserved node (the node component of the partial mono L ⇀ R), a name only in L is a
// deleted node, a name only in R an added node. Arcs are deduced by Assumption 4: an i-arc
// v_s -> v_t present in both L and R (same source name, target name and label) is a preserved arc
// of L∩R; an arc only in L is deleted, only in R added. With parallel arcs (same ends and label,
// possible in non-combinatorial rules), the k-th such arc of L is paired with the k-th of R.
//
// Labels are restricted to a dimension set: 0..n for G-map rules, 1..n for O-map rules (thesis
// Def. 32). Construction validates names (non-empty, unique per side) and labels and throws a
// located Error(Schema); combinatoriality (Def. 35) is NOT required here — the checker reports it,
// and the operations that need it (anchored matching) raise their own located error.
//
// The joint representation κ(L,R) (Def. 36) is a (D ∪ {κ})-graph: nodes V_L ⊔ V_R, arcs
// E_L ⊔ E_R ⊔ one κ-arc i_L(v) -> i_R(v) per preserved node, plus the side flag of every node.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/dgraph.hpp"
#include "model/graph/elem_status.hpp"

namespace gmr::rewrite {
using graph::ArcId;
using graph::DGraph;
using graph::Node;

using graph::ElemStatus;
using graph::Side;

class Rule {
 public:
  // Validates and deduces the interface. Throws Error(Schema) located "left.nodes[k]",
  // "right.arcs[k]" (slot index) ... for empty or duplicate names and labels outside the set.
  Rule(DGraph left, DGraph right, int n, MapKind kind = MapKind::GMap, std::string name = {});

  const std::string& name() const { return name_; }
  int dimension() const { return n_; }
  MapKind kind() const { return kind_; }
  MapSpec spec() const { return {n_, kind_}; }
  int lowest_dim() const { return spec().lowest_dim(); }
  bool has_label(int i) const { return spec().has_dim(i); }
  std::vector<int> labels() const;

  const DGraph& left() const { return L_; }
  const DGraph& right() const { return R_; }
  const DGraph& side(Side s) const { return s == Side::R ? R_ : L_; }

  // Node correspondence of the interface (nullopt: deleted, resp. added).
  std::optional<Node> right_of(Node l) const;
  std::optional<Node> left_of(Node r) const;
  ElemStatus left_node_status(Node l) const {
    return l_to_r_[l] ? ElemStatus::Preserved : ElemStatus::Deleted;
  }
  ElemStatus right_node_status(Node r) const {
    return r_to_l_[r] ? ElemStatus::Preserved : ElemStatus::Added;
  }
  // Arc correspondence (Assumption 4), indexed by arc slot.
  std::optional<ArcId> right_arc_of(ArcId l) const;
  std::optional<ArcId> left_arc_of(ArcId r) const;
  ElemStatus left_arc_status(ArcId l) const {
    return la_to_ra_[l] ? ElemStatus::Preserved : ElemStatus::Deleted;
  }
  ElemStatus right_arc_status(ArcId r) const {
    return ra_to_la_[r] ? ElemStatus::Preserved : ElemStatus::Added;
  }
  ElemStatus arc_status(Side s, ArcId a) const {
    return s == Side::R ? right_arc_status(a) : left_arc_status(a);
  }
  ElemStatus node_status(Side s, Node v) const {
    return s == Side::R ? right_node_status(v) : left_node_status(v);
  }

  std::vector<Node> preserved_nodes() const;  // left ids
  std::vector<Node> deleted_nodes() const;    // left ids
  std::vector<Node> added_nodes() const;      // right ids

  // "a -0-> b" with the side tag, for messages.
  std::string arc_str(Side s, ArcId a) const;

 private:
  void deduce();
  std::string name_;
  int n_;
  MapKind kind_;
  DGraph L_, R_;
  HandleVector<Node, std::optional<Node>> l_to_r_, r_to_l_;
  HandleVector<ArcId, std::optional<ArcId>> la_to_ra_, ra_to_la_;
};

// Joint representation κ(L,R), Def. 36.
inline constexpr int kKappaLabel = -1;
struct JointRepresentation {
  DGraph graph;                         // L nodes first (same ids as in L), then R nodes
  HandleVector<Node, bool> right_side;  // per node
  int n = 0;
  MapKind kind = MapKind::GMap;
  std::string name;
};
JointRepresentation to_joint(const Rule& r);
// Back: drops κ-arcs, splits the nodes by side; an R node reached by a κ-arc takes the name of its
// L node (so joint graphs produced by relabelings round-trip). Throws Error(Schema) when an arc
// crosses sides, a κ-arc goes from R to L, or a node has two κ-arcs.
Rule from_joint(const JointRepresentation& j);

}  // namespace gmr::rewrite
