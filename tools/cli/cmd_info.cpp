// `gmr info FILE`: kind, dimension, darts, links and cells per dimension, components, Euler
// characteristic, boundary, validity and embeddings of a map file.
#include <iostream>
#include <memory>

#include "model/core/orbit.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {

namespace {

struct InfoArgs {
  std::string input, from;
  bool json = false;
};

int run_info(const InfoArgs& a) {
  const EmbeddedMap f = load_map(a.input, a.from);
  const MapSummary s = summarize(f.map);
  auto value_count = [&](const EmbeddingField& e) {
    size_t k = 0;
    for (Dart rep : orbit_representatives(f.map, e.orbit()))
      if (e.has(rep)) ++k;
    return k;
  };
  if (a.json) {
    nlohmann::ordered_json j;
    j["file"] = a.input;
    add_to_json(j, s);
    nlohmann::ordered_json embs = nlohmann::ordered_json::array();
    for (const auto& e : f.fields)
      embs.push_back({{"name", e.name()}, {"orbit", e.orbit().str()}, {"values", value_count(e)}});
    j["embeddings"] = embs;
    print_json(j);
    return kExitOk;
  }
  const int lo = f.map.lowest_dim();
  std::cout << "file:        " << a.input << "\n"
            << "map:         " << map_name(f.map) << "\n"
            << "darts:       " << s.darts << "\n"
            << "links:       " << per_dimension(s.links, lo) << "\n";
  if (s.cells_known) {
    std::cout << "cells:       " << per_dimension(s.cells, 0) << "\n"
              << "components:  " << s.components << "\n"
              << "euler:       " << s.euler << "\n"
              << "closed:      " << (s.closed ? "yes" : "no") << "\n"
              << "boundary:    " << s.boundary_cells << " boundary " << (s.dimension - 1)
              << "-cell(s)\n";
  } else {
    std::cout << "cells:       not computed (the map is invalid)\n";
  }
  std::cout << "valid:       "
            << (s.valid
                    ? "yes"
                    : "no (" + std::to_string(s.violations) + " violations; see `gmr validate`)")
            << "\n";
  std::cout << "embeddings:  " << (f.fields.empty() ? "none" : std::to_string(f.fields.size()))
            << "\n";
  for (const auto& e : f.fields)
    std::cout << "  " << e.name() << " " << e.orbit().str() << ": " << value_count(e)
              << " value(s)\n";
  return kExitOk;
}

}  // namespace

void register_info(CLI::App& app) {
  auto [sub, args] = add_subcommand<InfoArgs>(
      app, "info", "Describe a map: darts, links, cells, Euler characteristic, validity", run_info);
  add_map_input(sub, args->input, args->from);
  add_json_flag(sub, args->json);
}

}  // namespace gmr::cli
