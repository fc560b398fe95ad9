// Atomic file writes (model/atomic_write.hpp): content replaced whole, no temporary file left,
// nothing created on failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "model/io/atomic_write.hpp"
#include "model/core/error.hpp"
#include "model/io/read_file.hpp"

using namespace gmr;
using namespace gmr::io;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("gmr_atomic_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

}  // namespace

TEST(AtomicWrite, WritesAndReplaces) {
  TempDir dir;
  const fs::path p = dir.path / "out.txt";
  write_file_atomic(p, "first");
  EXPECT_EQ(read_text_file(p), "first");
  write_file_atomic(p, std::string(100000, 'x'));
  EXPECT_EQ(read_text_file(p).size(), 100000u);
  write_file_atomic(p, "");
  EXPECT_EQ(read_text_file(p), "");
  EXPECT_EQ(dir.entries(), 1u);  // no temporary left behind
}

TEST(AtomicWrite, FailureLeavesNothing) {
  TempDir dir;
  try {
    write_file_atomic(dir.path / "missing" / "out.txt", "x");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.location(), (dir.path / "missing" / "out.txt").string());
  }
  // The destination is a directory: rename fails, the temporary file is removed.
  fs::create_directories(dir.path / "sub");
  EXPECT_THROW(write_file_atomic(dir.path / "sub", "x"), Error);
  EXPECT_EQ(dir.entries(), 1u);
  EXPECT_TRUE(fs::is_directory(dir.path / "sub"));
  EXPECT_TRUE(fs::is_empty(dir.path / "sub"));
}

TEST(ReadFile, MissingFileIsAnIoError) {
  try {
    read_text_file("/nonexistent/gmr/file.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_EQ(e.location(), "/nonexistent/gmr/file.json");
  }
}
