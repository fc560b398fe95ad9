#include "tools/cli/rule_gate.hpp"

#include <iostream>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "checker/scheme_checker.hpp"

namespace gmr::cli {
using namespace gmr::checker;

namespace {

struct Verdict {
  std::string rule;
  size_t errors = 0;
  std::string first_error;
};

Verdict verdict_of(const RuleInput& in, bool embeddings) {
  Verdict v;
  const std::vector<Diagnostic>* diagnostics = nullptr;
  CheckReport concrete;
  CheckReport scheme;
  if (in.is_scheme()) {
    scheme = check_scheme(*in.scheme, {.embeddings = embeddings});
    v.rule = in.scheme->name;
    diagnostics = &scheme.diagnostics;
  } else {
    concrete = check_rule(*in.concrete);
    v.rule = in.concrete->name();
    diagnostics = &concrete.diagnostics;
  }
  for (const Diagnostic& d : *diagnostics) {
    if (d.severity != Severity::Error) continue;
    if (v.errors++ == 0) v.first_error = to_text(d);
  }
  return v;
}

}  // namespace

std::optional<int> gate_rule(const RuleInput& in, const std::string& path, bool force,
                             bool embeddings) {
  if (in.is_scheme() && !in.scheme->precondition.empty())
    std::cerr << "gmr: warning: rule \"" << in.scheme->name
              << "\" has a Jerboa precondition; gmr does not evaluate it (the rule is applied as "
                 "if it held)\n";
  const Verdict v = verdict_of(in, embeddings);
  if (v.errors == 0) return std::nullopt;
  if (force) {
    std::cerr << "gmr: warning: applying rule \"" << v.rule << "\", which the checker rejects ("
              << v.errors << " error(s)), because of --force\n";
    return std::nullopt;
  }
  std::cerr << "gmr: rule \"" << v.rule << "\" is rejected by the checker (" << v.errors
            << " error(s)); its application may break the map. First error:\n  " << v.first_error
            << "\n`gmr check " << path
            << "` lists every diagnostic; --force applies the rule anyway.\n";
  return 1;
}

}  // namespace gmr::cli
