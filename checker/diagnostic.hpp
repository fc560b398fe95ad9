// Diagnostics of the static consistency checker for concrete rules (thesis §3.3, digest §3).
//
// Every violation is a Diagnostic with a STABLE code, the condition and dimension(s) it belongs to,
// and its witnesses (nodes, arcs, path). Codes (severity error unless marked note):
//
//   comb-multiple-arcs   Def. 35: a node of L is the source (or target) of two or more i-arcs in L
//                        (no injective match into a combinatorial graph exists).
//   I-preserved-node     Def. 33.1 (w-I_r(i)): a preserved node does not have as many outgoing
//                        (resp. incoming) i-arcs in R as in L (read with multiplicities, as in
//                        Algorithm 1 — see rule_check.hpp).
//   I-added-node         Def. 33.2 (w-I_r(i)): an added node is not the source and the target of
//                        exactly one i-arc in R.
//   I-deleted-node       Def. 34 / Fact 1 (dangling condition): a deleted node is not the source
//                        and the target of exactly one i-arc in L.
//   O-no-reverse         Def. 37 (O_r(i)): a deleted (resp. added) i-arc has no reverse i-arc in L
//                        (resp. R).
//   O-status-mismatch    Def. 37: the unique reverse of a deleted (resp. added) i-arc is not deleted
//                        (resp. added) — e.g. it is preserved.
//   O-several-reverses   Def. 37: a deleted/added i-arc has several reverse i-arcs (non-unique).
//   C-incoherent         Def. 39/40.1 (C_r(i,j)): an (i,j)-optimal path has no coherent optimal path
//                        (same source, target and label word) on the other side.
//   C-ambiguous          Def. 39/40.1: an (i,j)-optimal path has two or more coherent partners.
//   C-preserved-node     Def. 40.2: a preserved node with a deleted i-arc (resp. j-arc) has no
//                        i-arc (resp. j-arc) in R on an ijij-cycle or on an (i,j)-optimal path.
//   C-added-node         Def. 40.3: same for an added node.
//   C-skipped            (note) C_r(i,j) not evaluated: L or R has two i- or j-arcs at a node
//                        (the rule already fails Def. 35 / I_r).
//   C-completed          (note) ij-completion (Assumption 5): a closing arc of an iji-path of L was
//                        added to L∩R before checking C_r(i,j).
//   C-completion-conflict (note) an iji-path of L cannot be closed (its end already has another
//                        j-arc): L never matches a graph satisfying C_G(i,j) — the rule is vacuous.
//   C-O-completed        (note) model completion: the reverse of an arc of L in an involutive
//                        dimension was added to L∩R before checking C_r (rule_check.hpp).
//   C-open-R             (note) an iji-path of R is not closed in R. Not completed (digest erratum 5:
//                        completing R would change the matches); C_r judges it through optimal paths.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/core/gmap.hpp"

namespace gmr::checker {

enum class Severity { Error, Note };

struct Diagnostic {
  std::string code;
  std::string condition;  // "combinatorial", "w-I", "I", "O", "C"
  int i = -1, j = -1;
  Severity severity = Severity::Error;
  std::string message;
  std::vector<std::string> nodes;  // node names (witnesses)
  std::vector<std::string> arcs;   // "a -0-> b (L)"
  std::vector<std::string> path;   // node names along a path (C), with the side in `side`
  std::string side;                // "L", "R" or ""
  std::string condition_str() const;  // "I(2)", "C(0,2)", "combinatorial"
};

struct CheckReport {
  std::string rule_name;
  MapKind kind = MapKind::GMap;
  int n = 0;
  std::vector<Diagnostic> diagnostics;
  std::vector<std::pair<std::string, bool>> conditions;  // in checking order: "combinatorial", "I(0)", ...
  bool ok() const;
  bool holds(const std::string& condition) const;  // false if absent
  size_t count(const std::string& code) const;
};

std::string to_text(const Diagnostic& d);
std::string to_text(const CheckReport& r);
nlohmann::ordered_json to_json(const Diagnostic& d);
nlohmann::ordered_json to_json(const CheckReport& r);

}  // namespace gmr::checker
