// `gmr query-replace PATTERNS_DIR MAP -o OUT`: replaces the interior of every face (--cells 2) or
// volume (--cells 3) whose boundary signature matches a pattern of the folder (Damiand & Nivoliers
// 2022; docs/query-replace.md). Cells that match no pattern are left untouched and counted.
// Options: --oriented (start darts in D+ only), --split-edges K (the e-pattern: every edge split in
// K first), --flag-all (flag every input dart: the corners of a polyhedral input).
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <memory>

#include "model/replace/edge_split.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/query_replace.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {

namespace {

struct QueryReplaceArgs {
  std::string patterns, input, from, output, to;
  int cells = 2;
  unsigned split_edges = 1;
  bool oriented = false, flag_all = false, json = false;
};

int run_query_replace(const QueryReplaceArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const replace::Mode mode = a.oriented ? replace::Mode::Oriented : replace::Mode::Unoriented;
  replace::PatternStore store(mode);
  for (auto& p : replace::load_patterns(a.patterns)) store.add(std::move(p));
  const Format out_format = output_format(a.output, a.to);
  replace::FlaggedMap m = replace::flagged_map(load_map(a.input, a.from), a.input);
  if (a.flag_all) m.flag.assign(m.map.capacity(), 1);
  size_t split = 0;
  if (a.split_edges > 1) {
    // The arrays grow once: room for the split edges and the replacements (a size beyond the
    // dart limit is left to split_edges to refuse).
    const double room =
        double(m.map.capacity()) + double(m.map.size()) * (a.split_edges - 1) +
        (a.cells <= m.map.dimension() ? double(replace::replacement_room(m.map, store, a.cells))
                                      : 0);
    if (room < double(kNoDart)) m.reserve(static_cast<size_t>(room));
    const std::vector<Dart> edges = orbit_representatives(m.map, cell_type(m.map, 1));
    replace::split_edges(m, edges, a.split_edges);
    split = edges.size();
  }
  std::function<void(size_t, size_t)> progress;
  if (isatty(STDERR_FILENO) != 0)  // progress on a terminal only, quiet when piped
    progress = [](size_t k, size_t n) {
      if (n < 4096) return;
      std::cerr << "\rgmr query-replace: " << k << "/" << n << " cells" << std::flush;
      if (k == n) std::cerr << "\n";
    };
  const auto t1 = std::chrono::steady_clock::now();
  const replace::QueryReplaceReport r = replace::query_replace(m, store, a.cells, {}, progress);
  const auto t2 = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  const double read_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  save_map(replace::to_embedded_map(m), a.output, out_format);
  const char* cell = a.cells == 2 ? "faces" : "volumes";
  if (a.json) {
    nlohmann::ordered_json j;
    j["mode"] = replace::to_string(mode);
    j["cells"] = cell;
    j["edges_split"] = split;
    j["examined"] = r.cells;
    j["replaced"] = r.replaced();
    nlohmann::ordered_json per = nlohmann::ordered_json::object();
    for (size_t i = 0; i < r.matched.size(); ++i) per[store.patterns()[i].name] = r.matched[i];
    j["matched"] = per;
    j["unmatched"] = r.unmatched.size();
    j["unmatched_darts"] = r.unmatched;
    j["ambiguous_keys"] = r.ambiguous_keys;
    nlohmann::ordered_json amb = nlohmann::ordered_json::array();
    for (size_t i = 0; i < r.matched.size(); ++i)
      if (store.entry(i).ambiguous) amb.push_back(store.patterns()[i].name);
    j["ambiguous_patterns"] = amb;
    j["darts"] = m.map.size();
    j["time_ms"] = ms;             // query and replace
    j["read_split_ms"] = read_ms;  // reading the patterns and the map, splitting edges
    j["output"] = a.output;
    print_json(j);
    return kExitOk;
  }
  std::cout << "query-replace (" << replace::to_string(mode) << "): " << r.cells << " " << cell
            << ", " << r.replaced() << " replaced, " << r.unmatched.size() << " unmatched";
  if (split) std::cout << " (" << split << " edges split in " << a.split_edges << " first)";
  std::cout << "; " << m.map.size() << " darts; " << ms << " ms (reading and splitting: " << read_ms
            << " ms)\n";
  for (size_t i = 0; i < r.matched.size(); ++i)
    std::cout << "  " << store.patterns()[i].name << ": " << r.matched[i]
              << (store.entry(i).ambiguous
                      ? " (ambiguous: a boundary symmetry its interior lacks; tie-break applied)"
                      : "")
              << "\n";
  if (!r.unmatched.empty()) {
    std::cout << "  unmatched " << cell << " (a dart of each):";
    for (size_t i = 0; i < r.unmatched.size() && i < 20; ++i) std::cout << " " << r.unmatched[i];
    if (r.unmatched.size() > 20) std::cout << " ... (" << r.unmatched.size() - 20 << " more)";
    std::cout << "\n";
  }
  if (r.ambiguous_keys)
    std::cout << "  " << r.ambiguous_keys
              << " matches had several patterns for one signature: the first was used\n";
  return kExitOk;
}

}  // namespace

void register_query_replace(CLI::App& app) {
  auto [sub, args] = add_subcommand<QueryReplaceArgs>(
      app, "query-replace", "Replace the cells whose boundary matches a pattern (signatures)",
      run_query_replace);
  sub->add_option("patterns", args->patterns,
                  "Folder of pattern files (gmr.gmap JSON, flags as the embedding \"flag\")")
      ->required();
  sub->add_option("map", args->input, "Map file (.json, .off, .obj)")->required();
  sub->add_option("-o,--output", args->output, "Output map")->required();
  sub->add_option("--from", args->from, std::string("Input format (") + kInputFormats + ")");
  sub->add_option("--to", args->to, std::string("Output format (") + kOutputFormats + ")");
  sub->add_option("--cells", args->cells, "Cells to replace: 2 (faces) or 3 (volumes)")
      ->check(CLI::IsMember({2, 3}));
  sub->add_flag("--oriented", args->oriented,
                "Oriented mode: start darts in one orientation class only");
  sub->add_option("--split-edges", args->split_edges, "Split every edge in K first (e-pattern)")
      ->check(CLI::Range(1u, 1000u));
  sub->add_flag("--flag-all", args->flag_all, "Flag every dart of the input (its corners)");
  add_json_flag(sub, args->json, "Print the summary as JSON");
}

}  // namespace gmr::cli
