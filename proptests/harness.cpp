#include "proptests/harness.hpp"

#include <cstdlib>
#include <fstream>

namespace gmr::prop {

std::vector<std::string> corpus_lines(const std::string& property) {
  std::vector<std::string> out;
  const char* src = std::getenv("GMR_SOURCE_DIR");
  if (!src) return out;
  std::ifstream in(std::string(src) + "/proptests/corpus/" + property + ".txt");
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

void record_finding(const std::string& property, const std::string& line) {
  if (const char* out = std::getenv("GMR_CORPUS_OUT")) {
    std::ofstream f(out, std::ios::app);
    f << property << " " << line << "\n";
  }
}

}  // namespace gmr::prop
