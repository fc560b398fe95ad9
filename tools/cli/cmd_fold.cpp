// `gmr fold MAP --orbit "<0,1,2>" --dart D [--json] [--explicit-loops 2,3]`:
// topological folding of the connected component of dart D (thesis Alg. 6, inference/fold.hpp).
// Prints the graph scheme (nodes "n3 <2,1>", their darts, explicit arcs) or the named failure (arc
// failure, instantiation failure, relabeling failure, partial neighbourhood, instantiation not
// spanning all links, ...) with the darts and dimension involved. Exit 0 when the map folds, 1 when
// it does not, 2 on bad input.
#include <iostream>
#include <memory>

#include "inference/fold.hpp"
#include "inference/inference_format.hpp"
#include "model/core/error.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/inference_args.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {

namespace {

struct FoldArgs {
  std::string input, from, orbit, explicit_loops;
  long long dart = 0;
  bool json = false;
};

int run_fold(const FoldArgs& a) {
  using namespace gmr::inference;
  const EmbeddedMap f = load_map(a.input, a.from);
  const OrbitType o = parse_orbit_option(a.orbit, "--orbit");
  if (a.dart < 0 || a.dart > UINT32_MAX || !f.map.alive(static_cast<Dart>(a.dart)))
    throw Error(ErrorCode::Usage, std::to_string(a.dart) + " is not a dart of the map", "--dart");
  JointIndex index;
  const JointGraph j = joint_from_component(f.map, static_cast<Dart>(a.dart), &index);
  FoldOptions opt;
  opt.loops.explicit_loops =
      parse_dimension_list(a.explicit_loops, f.map.dimension(), "--explicit-loops");
  const FoldResult r = fold(j, o, index.before[static_cast<Dart>(a.dart)], opt);
  if (a.json) {
    nlohmann::ordered_json out{{"map", a.input}};
    const nlohmann::ordered_json body = to_json(r, j);
    for (const auto& [k, v] : body.items()) out[k] = v;
    print_json(out);
  } else {
    std::cout << to_text(r, j);
  }
  return r.ok() ? kExitOk : kExitNegative;
}

}  // namespace

void register_fold(CLI::App& app) {
  auto [sub, args] =
      add_subcommand<FoldArgs>(app, "fold",
                               "Fold a connected G-map into a graph scheme on an orbit type from a "
                               "start dart (thesis Alg. 6); exit 1 with the named failure",
                               run_fold);
  add_map_input(sub, args->input, args->from, "map", "Map file (.json, .off, .obj)");
  sub->add_option("--orbit", args->orbit, "Orbit type, e.g. \"<1,2>\" or \"<>\"")->required();
  sub->add_option("--dart", args->dart, "Start dart")->required();
  sub->add_option("--explicit-loops", args->explicit_loops,
                  "Dimensions whose loops are always explicit arcs (conservative), e.g. 2 or 0,2 "
                  "(default: implicit first)");
  add_json_flag(sub, args->json);
}

}  // namespace gmr::cli
