// The README's tour, run verbatim: every `gmr ...` line of the shell blocks of its "A short tour"
// section, in order, from a scratch directory that sees the checkout's folders (as the checkout's
// root does) and with the built binary first on the path. A line's expected exit code is the
// "exit N" of its comment, else 0.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "tools/tests/cli_fixture.hpp"

using namespace gmr::cli_test;

namespace {

struct TourLine {
  std::string command;
  int expected_exit = 0;
};

std::vector<TourLine> tour_commands(const std::string& readme) {
  const size_t begin = readme.find("\n## A short tour");
  const size_t end = readme.find("\n## ", begin + 1);
  std::istringstream in(readme.substr(begin, end - begin));
  std::vector<TourLine> lines;
  bool in_shell = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      in_shell = !in_shell && line == "```sh";
      continue;
    }
    if (!in_shell || line.rfind("gmr ", 0) != 0) continue;
    TourLine t;
    const size_t comment = line.find(" #");
    t.command = line.substr(0, comment);
    std::smatch m;
    const std::string note = comment == std::string::npos ? "" : line.substr(comment);
    if (std::regex_search(note, m, std::regex("exit ([0-9])"))) t.expected_exit = std::stoi(m[1]);
    lines.push_back(t);
  }
  return lines;
}

}  // namespace

TEST_F(Cli, ReadmeTourRunsAsWritten) {
  const std::vector<TourLine> lines =
      tour_commands(gmr::io::read_text_file(source_dir() / "README.md"));
  ASSERT_GE(lines.size(), 8u);
  const fs::path root = fs::absolute(source_dir());
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory() && entry.path().filename().string()[0] != '.' &&
        entry.path().filename() != "build" && entry.path().filename() != "out")
      fs::create_directory_symlink(entry.path(), dir / entry.path().filename());
  const std::string path = fs::path(gmr_bin()).parent_path().string();
  for (const TourLine& t : lines) {
    const std::string cmd = "cd " + q(dir) + " && PATH=" + q(path) + ":\"$PATH\" " + t.command +
                            " >" + q(dir / "stdout") + " 2>" + q(dir / "stderr");
    const int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == t.expected_exit)
        << t.command << "\nexit " << WEXITSTATUS(status) << ", expected " << t.expected_exit << "\n"
        << gmr::io::read_text_file(dir / "stderr");
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "quad.svg"));
  EXPECT_TRUE(fs::is_regular_file(dir / "inferred" / "summary.txt"));
}
