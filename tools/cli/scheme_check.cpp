#include "tools/cli/scheme_check.hpp"

#include <algorithm>
#include <iostream>
#include <map>

#include "checker/check_format.hpp"
#include "checker/scheme_checker.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/read_file.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "tools/cli/cli.hpp"

namespace gmr::cli {
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

// "C-cycle-word x2, I-deleted-node" — the distinct error/warning codes of a report.
std::string code_summary(const CheckReport& r) {
  std::map<std::string, size_t> n;
  std::vector<std::string> order;
  for (const auto& d : r.diagnostics) {
    if (d.severity == Severity::Note) continue;
    if (n[d.code]++ == 0) order.push_back(d.code);
  }
  std::string s;
  for (const auto& c : order)
    s += (s.empty() ? "" : ", ") + c + (n[c] > 1 ? " x" + std::to_string(n[c]) : "");
  return s.empty() ? "-" : s;
}

}  // namespace

std::optional<int> check_scheme_input(const std::string& path, bool json, bool algorithm3_strict,
                                      bool embeddings) {
  SchemeCheckOptions opt;
  opt.algorithm3_strict = algorithm3_strict;
  opt.embeddings = embeddings;
  const bool jme = path.size() > 4 && path.substr(path.size() - 4) == ".jme";
  if (!jme) {
    const std::string text = read_text_file(path);
    const nlohmann::json doc = parse_json(text, path);
    if (rule_document_kind(doc, path) != "scheme") return std::nullopt;
    const RuleScheme s = scheme_from_json(doc, path);
    const CheckReport rep = check_scheme(s, opt);
    if (json) {
      auto j = to_json(rep);
      j["file"] = path;
      print_json(j);
    } else {
      std::cout << path << ": " << to_text(rep);
    }
    return rep.ok() ? kExitOk : kExitNegative;
  }
  const JmeModeler m = read_jme_file(path);
  std::vector<CheckReport> reps;
  size_t accepted = 0;
  for (const auto& r : m.rules) {
    reps.push_back(check_scheme(r, opt));
    accepted += reps.back().ok();
  }
  // Jerboa expressions translated into gmr's language (model/rule_io/jme_expression.hpp).
  size_t expressions = 0, translated = 0;
  for (const auto& r : m.rules)
    for (const auto& n : r.right.nodes)
      for (const auto& x : n.expressions) {
        ++expressions;
        translated += x.unsupported.empty();
      }
  if (json) {
    nlohmann::ordered_json j = check_document("modeler", accepted == m.rules.size());
    j["file"] = path;
    j["modeler"] = m.name;
    j["n"] = m.dimension;
    j["rules"] = m.rules.size();
    j["accepted"] = accepted;
    j["rejected"] = m.rules.size() - accepted;
    j["expressions"] = expressions;
    j["expressions_translated"] = translated;
    j["reports"] = nlohmann::ordered_json::array();
    for (const auto& r : reps) {
      // Each report is the body of a "scheme" document, without the document header.
      nlohmann::ordered_json body = to_json(r);
      for (const char* k : {"format", "version", "subject"}) body.erase(k);
      j["reports"].push_back(std::move(body));
    }
    print_json(j);
  } else {
    size_t w = 4;
    for (const auto& r : m.rules) w = std::max(w, r.name.size());
    auto pad = [](std::string s, size_t n) {
      return s + std::string(n > s.size() ? n - s.size() : 0, ' ');
    };
    std::cout << path << ": Jerboa modeler " << m.name << ", dimension " << m.dimension << ", "
              << m.rules.size() << " rules\n";
    std::cout << pad("rule", w) << "  " << pad("verdict", 8) << "  errors  warnings  diagnostics\n";
    for (size_t k = 0; k < reps.size(); ++k)
      std::cout << pad(m.rules[k].name, w) << "  " << pad(reps[k].ok() ? "accepted" : "rejected", 8)
                << "  " << pad(std::to_string(reps[k].errors()), 6) << "  "
                << pad(std::to_string(reps[k].warnings()), 8) << "  " << code_summary(reps[k])
                << "\n";
    std::cout << accepted << " accepted, " << m.rules.size() - accepted << " rejected\n";
    std::cout << "expressions: " << translated << " of " << expressions
              << " translated into gmr's language (the others: E-unsupported, by rule and node)\n";
    for (size_t k = 0; k < reps.size(); ++k)
      if (!reps[k].ok()) std::cout << "\n" << to_text(reps[k]);
  }
  return accepted == m.rules.size() ? kExitOk : kExitNegative;
}

}  // namespace gmr::cli
