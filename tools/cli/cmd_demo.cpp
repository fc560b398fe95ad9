// `gmr demo`: builds the standard objects (builders.hpp) — the stacked cubes of the inference
// paper (§3.3), a cube read from tools/data/cube.off, a torus grid with computed coordinates, a
// level-2 Menger sponge polycube and the polycube of tools/data/polycube.voxels.json — validates
// them and prints their cell counts. The cube and the torus are also compared (is_isomorphic) with
// make_cube and make_torus. Writes into --out (default out/demo): DOT and SVG drawings of the
// stacked cubes and the cube, OBJ files of the cube and the torus with positions, and gmr.gmap JSON
// files. Exit 1 when an object is invalid or differs from its builder.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>

#include "model/core/builders.hpp"
#include "model/core/signature.hpp"
#include "model/draw/render.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/map_io/face_list.hpp"
#include "model/map_io/map_json.hpp"
#include "model/map_io/obj.hpp"
#include "model/map_io/off.hpp"
#include "model/map_io/voxels.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {
using namespace gmr::io;
using namespace gmr::draw;

namespace {

struct DemoArgs {
  std::string out = "out/demo";
  std::string data;  // empty: default_data_dir()
  bool json = false;
};

// A torus of w x h quads: vertex (x, y) at angles (2 pi x / w, 2 pi y / h) on radii R = 2, r = 0.7,
// faces indexed as in make_torus.
FaceList torus_mesh(size_t w, size_t h) {
  FaceList fl;
  const double R = 2.0, r = 0.7, two_pi = 2 * std::numbers::pi;
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x) {
      const double u = two_pi * double(x) / double(w), v = two_pi * double(y) / double(h);
      fl.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                             (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto id = [&](size_t x, size_t y) { return static_cast<uint32_t>((y % h) * w + (x % w)); };
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x)
      fl.faces.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1), id(x, y + 1)});
  return fl;
}

struct Object {
  std::string name;
  std::string origin;
  Map map;
  std::optional<bool> matches_builder;  // for objects also built by a builder
};

int run_demo(const DemoArgs& a) {
  const std::filesystem::path data(a.data.empty() ? default_data_dir() : a.data), out(a.out);
  constexpr size_t kTorusW = 12, kTorusH = 6;

  const EmbeddedMap cube = read_off_file(data / "cube.off");
  const EmbeddedMap torus = map_from_face_list(torus_mesh(kTorusW, kTorusH));
  std::vector<Object> objects;
  objects.push_back({"stacked cubes", "make_stacked_cubes()", make_stacked_cubes(), std::nullopt});
  objects.push_back(
      {"cube", "tools/data/cube.off", cube.map, is_isomorphic(cube.map, make_cube())});
  objects.push_back({"torus 12x6", "computed mesh", torus.map,
                     is_isomorphic(torus.map, make_torus(kTorusW, kTorusH))});
  objects.push_back({"Menger sponge L2", "make_polycube(menger_voxels(2))",
                     make_polycube(menger_voxels(2)), std::nullopt});
  objects.push_back({"polycube", "tools/data/polycube.voxels.json",
                     make_polycube(read_voxels_json_file(data / "polycube.voxels.json")),
                     std::nullopt});

  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec)
    throw Error(ErrorCode::Io, "cannot create the output directory: " + ec.message(), out.string());
  std::vector<std::string> files;
  auto written = [&](const std::filesystem::path& p) { files.push_back(p.string()); };
  auto draw = [&](const Map& g, const std::string& stem) {
    DotOptions opt;
    opt.name = stem;
    const std::string dot = to_dot(g, opt);
    write_file_atomic(out / (stem + ".dot"), dot);
    written(out / (stem + ".dot"));
    render_dot_file(dot, ImageFormat::Svg, out / (stem + ".svg"));
    written(out / (stem + ".svg"));
  };
  auto save_json = [&](const EmbeddedMap& f, const std::string& stem) {
    write_map_json_file(out / (stem + ".json"), f);
    written(out / (stem + ".json"));
  };
  draw(objects[0].map, "stacked_cubes");
  draw(cube.map, "cube");
  write_obj_file(out / "cube.obj", cube.map, cube.position());
  written(out / "cube.obj");
  write_obj_file(out / "torus.obj", torus.map, torus.position());
  written(out / "torus.obj");
  save_json(EmbeddedMap(objects[0].map), "stacked_cubes");
  save_json(cube, "cube");
  save_json(torus, "torus");
  save_json(EmbeddedMap(objects[4].map), "polycube");

  bool ok = true;
  std::vector<MapSummary> summaries;
  for (const Object& o : objects) {
    summaries.push_back(summarize(o.map));
    ok = ok && summaries.back().valid && o.matches_builder.value_or(true);
  }
  if (a.json) {
    nlohmann::ordered_json j;
    nlohmann::ordered_json objs = nlohmann::ordered_json::array();
    for (size_t k = 0; k < objects.size(); ++k) {
      nlohmann::ordered_json o;
      o["name"] = objects[k].name;
      o["origin"] = objects[k].origin;
      add_to_json(o, summaries[k]);
      if (objects[k].matches_builder) o["isomorphic_to_builder"] = *objects[k].matches_builder;
      objs.push_back(o);
    }
    j["objects"] = objs;
    j["out"] = out.string();
    j["files"] = files;
    j["ok"] = ok;
    print_json(j);
    return ok ? kExitOk : kExitNegative;
  }
  std::cout << std::left << std::setw(18) << "object" << std::setw(9) << "map" << std::right
            << std::setw(7) << "darts"
            << "  " << std::left << std::setw(24) << "cells (0..n)" << std::right << std::setw(6)
            << "euler"
            << "  valid  origin\n";
  for (size_t k = 0; k < objects.size(); ++k) {
    const MapSummary& s = summaries[k];
    std::string cells;
    for (size_t c : s.cells) cells += (cells.empty() ? "" : " ") + std::to_string(c);
    std::string origin = objects[k].origin;
    if (objects[k].matches_builder)
      origin += *objects[k].matches_builder ? " (isomorphic to its builder)"
                                            : " (DIFFERS from its builder)";
    std::cout << std::left << std::setw(18) << objects[k].name << std::setw(9)
              << map_name(objects[k].map) << std::right << std::setw(7) << s.darts << "  "
              << std::left << std::setw(24) << (s.cells_known ? cells : "-") << std::right
              << std::setw(6) << (s.cells_known ? std::to_string(s.euler) : "-") << "  "
              << std::left << std::setw(5) << (s.valid ? "yes" : "NO") << "  " << origin << "\n";
  }
  std::cout << "\nwritten to " << out.string() << ":\n";
  for (const auto& f : files) std::cout << "  " << f << "\n";
  return ok ? kExitOk : kExitNegative;
}

}  // namespace

void register_demo(CLI::App& app) {
  auto [sub, args] = add_subcommand<DemoArgs>(
      app, "demo",
      "Build the standard objects, validate them, print their cells, write drawings and meshes",
      run_demo);
  sub->add_option("--out", args->out, "Output directory")->capture_default_str();
  sub->add_option("--data", args->data,
                  "Directory of the example data files (default: tools/data of the current "
                  "directory when present, "
                  "else of the source tree gmr was built from)");
  add_json_flag(sub, args->json);
}

}  // namespace gmr::cli
