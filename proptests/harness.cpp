#include "proptests/harness.hpp"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace gmr::prop {

static bool parse_family(const std::string& s, Generator& out) {
  for (Generator g : {Generator::GluedPolygons, Generator::Polycube, Generator::SewSequence})
    if (s == to_string(g)) {
      out = g;
      return true;
    }
  return false;
}

std::vector<MapCase> corpus_cases(const std::string& property) {
  std::vector<MapCase> out;
  const char* src = std::getenv("GMR_SOURCE_DIR");
  if (!src) return out;
  std::ifstream in(std::string(src) + "/proptests/corpus/" + property + ".txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string fam;
    MapCase c;
    if (ss >> fam >> c.n >> c.size >> c.seed && parse_family(fam, c.family)) out.push_back(c);
    else std::cerr << "corpus " << property << ": ignoring malformed line: " << line << "\n";
  }
  return out;
}

bool check_map_property(const std::string& property, const rc::Gen<MapCase>& gen, const MapProperty& body) {
  for (const MapCase& c : corpus_cases(property)) {
    const bool ok = rc::check(property + " (corpus " + c.str() + ")", [&] {
      const MapCase fixed = *rc::gen::just(c);
      body(fixed);
    });
    if (!ok) return false;
  }
  MapCase last_failure;
  bool failed_once = false;
  const bool ok = rc::check(property, [&] {
    const MapCase c = *gen;
    try {
      body(c);
    } catch (...) {
      last_failure = c;  // the last failing evaluation is the shrunk counterexample
      failed_once = true;
      throw;
    }
  });
  if (!ok && failed_once) {
    std::cerr << "shrunk counterexample: " << last_failure.str() << "\n";
    if (const char* out = std::getenv("GMR_CORPUS_OUT")) {
      std::ofstream f(out, std::ios::app);
      f << property << " " << to_string(last_failure.family) << " " << last_failure.n << " "
        << last_failure.size << " " << last_failure.seed << "\n";
    }
  }
  return ok;
}

}  // namespace gmr::prop
