// The application of a symbolic rule (symbolic_rule.hpp) on a symbolic map (map_encoding.hpp):
// derivation_encoding.hpp with the rule's nodes, statuses and arcs as formulas (docs/verify.md,
// "Symbolic rules").
//   match       the L nodes are the slots 0..|V_L|-1 (the family's symmetry breaking); slot x of L
//               is sent to dart x (the second symmetry breaking, as derivation_encoding.hpp's fixed
//               match): x is an active dart, and every L-arc x -i-> y gives alpha_i(x) = y.
//   dangling    a deleted slot's outgoing and incoming i-arcs in G are images of L-arcs.
//   H           nodes: the live darts (active, not the image of a deleted slot) and the numeral
//               k + x of every added slot x; the H node of an R slot x is x when x is in L, k + x
//               otherwise. Candidate arcs as in derivation_encoding.hpp, with presence conditions
//               over the rule's variables.
//   violation   looked for at the touched nodes only (the H nodes of the R slots), as the local
//               encoding of derivation_encoding.hpp, whose argument holds for every rule.
#pragma once
#include <z3++.h>

#include <string>
#include <vector>

#include "checker/smt/map_encoding.hpp"
#include "checker/smt/symbolic_rule.hpp"

namespace gmr::smt {

class SymbolicDerivation {
 public:
  // `prefix` names the functions h_i (one derivation per map in a context).
  SymbolicDerivation(const MapEncoding& map, const SymbolicRule& rule, const std::string& prefix);

  // m sends each L slot x to dart x, label-preserving.
  z3::expr match() const;
  z3::expr dangling_condition() const;
  z3::expr_vector h_definitions() const;
  // Some touched node of H breaks a constraint of the model.
  z3::expr breaks_model_local() const;
  // Consistency semantics (rule_verifier.hpp): the match fails the gluing condition or H is not a
  // map.
  z3::expr breaks_consistency() const { return !dangling_condition() || breaks_model_local(); }

 private:
  struct Candidate {
    z3::expr present;
    z3::expr end;
  };
  z3::expr dart(int x) const { return map_.dart(static_cast<unsigned>(x)); }
  z3::expr h_node(int x) const;
  z3::expr alive_dart(const z3::expr& X) const;
  z3::expr alive(unsigned x) const;
  std::vector<Candidate> arcs(const z3::expr& X, int i, bool incoming) const;
  z3::expr exactly_one(const std::vector<Candidate>& cs) const;

  const MapEncoding& map_;
  const SymbolicRule& rule_;
  std::vector<z3::func_decl> h_;
};

}  // namespace gmr::smt
