// Diagnostics of the static consistency checker for concrete rules (thesis §3.3) and, with the
// same Diagnostic and Severity, of the scheme checker (scheme_checker.hpp). Their text and JSON
// (docs/check-format.md) are written by check_format.hpp.
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
//   O-status-mismatch    Def. 37: the unique reverse of a deleted (resp. added) i-arc is not
//   deleted
//                        (resp. added) — e.g. it is preserved.
//   O-several-reverses   Def. 37: a deleted/added i-arc has several reverse i-arcs (non-unique).
//   C-incoherent         Def. 39/40.1 (C_r(i,j)): an (i,j)-optimal path has no coherent optimal
//   path
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
//   C-open-R             (note) an iji-path of R is not closed in R. Not completed (completing R
//                        would change the matches); C_r judges it through optimal paths.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/core/constraint_violation.hpp"
#include "model/core/map.hpp"
#include "model/graph/elem_status.hpp"

namespace gmr::checker {
using graph::Side;

// One severity for the concrete-rule and the scheme checker: an error makes the rule fail; a
// warning (schemes: an unevaluated precondition, an ignored expression) and a note do not.
enum class Severity { Error, Warning, Note };
const char* to_string(Severity s);

// A word of dimensions in the thesis' notation: the letters side by side ("021"), ε when empty.
std::string word_text(const std::vector<int>& w);

// One diagnostic of either checker: the rule-level reading of a constraint violation
// (model/core/constraint_violation.hpp). Its condition is a constraint of the model named by its
// symbol ("I", "O", "C": the rule conditions I_r, O_r, C_r that preserve I_G, O_G, C_G,
// Thms. 2–3) or a condition of rules only ("combinatorial", "w-I", "embeddings", ...); on top of
// the violation's dimensions, witnesses and message, it adds a stable code, a severity and the
// rule side the witnesses live on, named by the rule's node names. Build it with designated
// initializers:
//   Diagnostic{.code = "I-added-node", .condition = symbol(Constraint::IncidentArcs), .i = 2,
//              .side = Side::R, .message = ...}.
struct Diagnostic {
  std::string code{};  // stable, listed above and in scheme_checker.hpp
  Severity severity = Severity::Error;
  // Concrete rules: "combinatorial", "w-I", "I", "O", "C", the dimension(s) in i and j.
  // Schemes: "structure", "hooks" or the full condition ("I(2)", "C(0,2)"), i = j = -1.
  std::string condition{};
  int i = -1, j = -1;
  std::optional<Side> side{};        // the rule side the witnesses live on, when there is one
  std::vector<std::string> nodes{};  // node names (witnesses)
  std::vector<std::string> arcs{};   // concrete "a -0-> b (L)", scheme "n0 -1- n2"
  std::vector<std::string> path{};   // node names along a path or cycle, on `side`
  std::string message{};
  std::string side_str() const;  // "L", "R" or ""
};

// What a report is about: a concrete rule (check_rule, rule_check.hpp) or a rule scheme
// (check_scheme, scheme_checker.hpp). Both checkers fill the same report; its text and JSON
// (check_format.hpp) follow the subject.
enum class CheckSubject : uint8_t { Rule, Scheme };

struct CheckReport {
  CheckSubject subject = CheckSubject::Rule;
  std::string rule;              // the rule's name
  MapKind kind = MapKind::GMap;  // concrete rules: the kind and dimension of the maps
  int n = 0;
  std::vector<Diagnostic> diagnostics;
  // In checking order. Concrete rules: "combinatorial", "I(0)", ..., "O(0)", ..., "C(0,2)", ...;
  // schemes: "structure", "hooks", "I(0)", "O(0)", "C(0,2)", ...
  std::vector<std::pair<std::string, bool>> conditions;
  bool ok() const;  // no error
  size_t errors() const;
  size_t warnings() const;
  bool holds(const std::string& condition) const;  // false if absent
  size_t count(const std::string& code) const;
};

}  // namespace gmr::checker
