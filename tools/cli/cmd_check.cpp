// `gmr check RULE.json [--json]`: rule schemes are delegated to scheme_check.hpp; for a concrete
// rule, the static consistency conditions of a concrete rule (thesis
// Defs. 33-40, checker/rule_check.hpp) for its model (G-map or O-map of dimension n). Prints every
// diagnostic (stable codes, checker/diagnostic.hpp). Exit 0 if all conditions hold, 1 if one
// fails, 2 on bad input.
#include <iostream>
#include <memory>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "model/rule_io/rule_json.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/scheme_check.hpp"
#include "tools/cli/scheme_check.hpp"  // rule schemes and .jme files
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::rewrite;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

struct CheckArgs {
  std::string input;
  bool json = false;
  bool per_constraint = false;
  bool algorithm3 = false;     // rule schemes: the literal Algorithm 3 (scheme_checker.hpp)
  bool no_embeddings = false;  // rule schemes: the topological conditions only
};

int run_check(const CheckArgs& a) {
  // Rule schemes (.jme files, gmr.rule files of kind "scheme") go to the scheme checker.
  if (auto code = check_scheme_input(a.input, a.json, a.algorithm3, !a.no_embeddings)) return *code;
  // Concrete rules.
  const Rule r = read_rule_file(a.input);
  const CheckReport rep = check_rule(r, !a.per_constraint);
  if (a.json) {
    auto j = to_json(rep);
    j["file"] = a.input;
    print_json(j);
  } else {
    std::cout << a.input << ": " << to_text(rep);
  }
  return rep.ok() ? kExitOk : kExitNegative;
}

}  // namespace

void register_check(CLI::App& app) {
  auto [sub, args] = add_subcommand<CheckArgs>(
      app, "check",
      "Check the consistency conditions of a concrete rule or rule scheme (incident arcs, "
      "non-orientation, cycles); exit 1 if one fails",
      run_check);
  sub->add_option("rule", args->input,
                  "Rule file (gmr.rule JSON, concrete or scheme) or Jerboa .jme file")
      ->required();
  add_json_flag(sub, args->json, "Print JSON (format gmr.check)");
  sub->add_flag("--per-constraint", args->per_constraint,
                "Check C_r on the ij-completion only (the thesis' per-constraint reading), without "
                "the model completion");
  // Rule schemes: a gmr.rule file of kind "scheme", or a Jerboa .jme file (summary table).
  sub->add_flag(
      "--algorithm3", args->algorithm3,
      "Rule schemes: apply the thesis' Algorithm 3 literally (any L arc, not only deleted ones)");
  sub->add_flag("--no-embeddings", args->no_embeddings,
                "Rule schemes: the topological conditions only, without the embedding checks");
}

}  // namespace gmr::cli
