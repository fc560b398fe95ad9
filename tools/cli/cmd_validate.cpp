// `gmr validate FILE`: every violation of the G-map / O-map constraints (validity.hpp), located by
// dart, and for a valid map the orbits whose embedding values are missing or inconsistent
// (Embedding::check). Exit 1 when anything is reported.
#include <iostream>
#include <memory>

#include "model/core/position.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/validity_report.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {

namespace {

struct ValidateArgs {
  std::string input, from;
  size_t limit = 1000;
  bool json = false;
};

// Orbits without one consistent value; for the "position" embedding, also values that are not
// [x, y, z] (model/core/position.hpp).
std::vector<EmbeddingIssue> embedding_issues(const Map& g, const EmbeddingField& e) {
  std::vector<EmbeddingIssue> issues = e.check(g);
  if (e.name() != kPositionName) return issues;
  for (Dart rep : orbit_representatives(g, e.orbit()))
    if (e.has(rep))
      if (auto problem = position_value_problem(e.value_json(rep)))
        issues.push_back({rep, *problem});
  return issues;
}

int run_validate(const ValidateArgs& a) {
  const EmbeddedMap f = load_map(a.input, a.from);
  const ValidityReport r = check_validity(f.map, a.limit);
  struct Issue {
    std::string embedding;
    EmbeddingIssue issue;
  };
  std::vector<Issue> issues;
  if (r.ok())  // orbits of an invalid map do not describe cells: embeddings are checked on valid
               // maps
    for (const auto& e : f.fields)
      for (auto& i : embedding_issues(f.map, e)) issues.push_back({e.name(), i});
  const bool valid = r.ok() && issues.empty();
  if (a.json) {
    nlohmann::ordered_json j;
    j["file"] = a.input;
    j["map"] = map_name(f.map);
    j["valid"] = valid;
    j["violations"] = io::violations_json(r);
    j["truncated"] = r.truncated;
    nlohmann::ordered_json es = nlohmann::ordered_json::array();
    for (const Issue& i : issues)
      es.push_back(
          {{"embedding", i.embedding}, {"dart", i.issue.dart}, {"problem", i.issue.problem}});
    j["embedding_issues"] = es;
    print_json(j);
    return valid ? kExitOk : kExitNegative;
  }
  if (valid) {
    std::cout << a.input << ": valid " << map_name(f.map) << " (" << f.map.size() << " darts)\n";
    return kExitOk;
  }
  if (!r.ok()) {
    std::cout << a.input << ": invalid " << map_name(f.map) << ": " << r.total()
              << " violation(s)\n";
    print_violations(r);
  } else {
    std::cout << a.input << ": valid " << map_name(f.map) << ", but " << issues.size()
              << " embedding issue(s)\n";
    for (const Issue& i : issues)
      std::cout << "  embedding '" << i.embedding << "' at dart " << i.issue.dart << ": "
                << i.issue.problem << "\n";
  }
  return kExitNegative;
}

}  // namespace

void register_validate(CLI::App& app) {
  auto [sub, args] = add_subcommand<ValidateArgs>(
      app, "validate",
      "Check the G-map/O-map constraints and the embeddings; list every violation (exit 1 if any)",
      run_validate);
  add_map_input(sub, args->input, args->from);
  sub->add_option("--limit", args->limit, "Maximum number of violations listed")
      ->check(non_negative_integer())
      ->capture_default_str();
  add_json_flag(sub, args->json);
}

}  // namespace gmr::cli
