// `gmr signature FILE`: the minimal BFS-word signature of a map (model/signature.hpp); two maps are
// isomorphic iff their signatures are equal. --flags NAME appends per-dart flags taken from the
// embedding NAME: its distinct values are ranked by their JSON text (1, 2, ...; 0 for a dart
// without value), so equal signatures mean isomorphic maps with equal values.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>

#include "model/core/signature.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {

namespace {

struct SignatureArgs {
  std::string input, from, flags;
  bool json = false;
};

std::vector<uint32_t> flags_from(const EmbeddedMap& f, const std::string& name) {
  const EmbeddingField* e = f.find(name);
  if (!e) {
    std::string names;
    for (const auto& x : f.fields) names += (names.empty() ? "" : ", ") + x.name();
    throw Error(ErrorCode::Usage,
                "no embedding \"" + name +
                    "\" in the map (embeddings: " + (names.empty() ? "none" : names) + ")",
                "--flags");
  }
  std::map<std::string, uint32_t> rank;
  f.map.for_each_dart([&](Dart d) {
    if (e->has(d)) rank.emplace(e->value_json(d).dump(), 0);
  });
  uint32_t next = 1;
  for (auto& [text, r] : rank) r = next++;
  std::vector<uint32_t> flags(f.map.capacity(), 0);
  f.map.for_each_dart([&](Dart d) {
    if (e->has(d)) flags[d] = rank.at(e->value_json(d).dump());
  });
  return flags;
}

int run_signature(const SignatureArgs& a) {
  const EmbeddedMap f = load_map(a.input, a.from);
  std::vector<uint32_t> flags;
  if (!a.flags.empty()) flags = flags_from(f, a.flags);
  const Signature s = signature(f.map, a.flags.empty() ? nullptr : &flags);
  if (a.json) {
    nlohmann::ordered_json j;
    j["file"] = a.input;
    j["map"] = map_name(f.map);
    if (!a.flags.empty()) j["flags"] = a.flags;
    j["components"] = s.components.size();
    j["signature"] = s.str();
    print_json(j);
  } else {
    std::cout << s.str() << "\n";
  }
  return kExitOk;
}

}  // namespace

void register_signature(CLI::App& app) {
  auto [sub, args] = add_subcommand<SignatureArgs>(
      app, "signature", "Print the minimal signature of a map (equal iff isomorphic)",
      run_signature);
  add_map_input(sub, args->input, args->from);
  sub->add_option("--flags", args->flags, "Embedding whose values flag the darts (e.g. position)");
  add_json_flag(sub, args->json);
}

}  // namespace gmr::cli
