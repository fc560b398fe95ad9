// The `gmr` binary run as a user would, for the CLI tests: the binary's path comes from the build
// (GMR_BIN), the data files from GMR_SOURCE_DIR; each test gets a fresh directory with an `out/`
// folder whose entries (temporary files included) can be counted.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "model/map_io/read_file.hpp"
#include "model/testing/scratch_dir.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::cli_test {
namespace fs = std::filesystem;

inline std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

inline std::string gmr_bin() { return gmr::testing::build_artifact("GMR_BIN"); }
inline fs::path source_dir() { return gmr::testing::source_path("."); }
inline fs::path test_data(const std::string& name) {
  return source_dir() / "model/map_io/tests/data" / name;
}
inline fs::path tools_data(const std::string& name) { return source_dir() / "tools/data" / name; }

struct Result {
  int code;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = gmr::testing::scratch_path("gmr_" + std::string(test->test_suite_name()) + "_" +
                                     test->name());
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
  }
  void TearDown() override { fs::remove_all(dir); }

  Result run(const std::string& args, const std::string& stdin_file = "") {
    const std::string cmd = q(gmr_bin()) + " " + args + " >" + q(dir / "stdout") + " 2>" +
                            q(dir / "stderr") +
                            (stdin_file.empty() ? " </dev/null" : " <" + q(stdin_file));
    const int status = std::system(cmd.c_str());
    Result r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, gmr::io::read_text_file(dir / "stdout"),
             gmr::io::read_text_file(dir / "stderr")};
    return r;
  }
  // Entries of the output directory (temporary files included).
  size_t outputs() const {
    return static_cast<size_t>(
        std::distance(fs::directory_iterator(dir / "out"), fs::directory_iterator()));
  }
  void expect_bad_input(const std::string& args, const std::string& location,
                        const std::string& what = "") {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("gmr: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(location), std::string::npos)
        << "expected location " << location << " in: " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "expected " << what << " in: " << r.err;
  }
  fs::path dir;
};

}  // namespace gmr::cli_test
