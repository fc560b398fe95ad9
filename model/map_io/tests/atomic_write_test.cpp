// Atomic file writes (model/atomic_write.hpp): content replaced whole, no temporary file left,
// nothing created on failure.
#include "model/map_io/atomic_write.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "model/core/error.hpp"
#include "model/map_io/read_file.hpp"

using namespace gmr;
using namespace gmr::io;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("gmr_atomic_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  size_t entries() const {
    return static_cast<size_t>(
        std::distance(fs::directory_iterator(path), fs::directory_iterator()));
  }
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

TEST(AtomicWrite, SymbolicLinkIsWrittenThrough) {
  TempDir dir;
  write_file_atomic(dir.path / "target.txt", "old");
  fs::create_symlink("target.txt", dir.path / "link.txt");
  write_file_atomic(dir.path / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir.path / "link.txt"));
  EXPECT_EQ(read_text_file(dir.path / "target.txt"), "new");
  // A dangling link creates its target.
  fs::create_symlink("later.txt", dir.path / "dangling.txt");
  write_file_atomic(dir.path / "dangling.txt", "made");
  EXPECT_TRUE(fs::is_symlink(dir.path / "dangling.txt"));
  EXPECT_EQ(read_text_file(dir.path / "later.txt"), "made");
  EXPECT_EQ(dir.entries(), 4u);
}

TEST(AtomicWrite, SpecialFileIsWrittenInPlace) {
  TempDir dir;
  const fs::path fifo = dir.path / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read_text_file(fifo); });
  write_file_atomic(fifo, "through the pipe");
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_EQ(fs::status(fifo).type(), fs::file_type::fifo);
  EXPECT_EQ(dir.entries(), 1u);
  EXPECT_NO_THROW(write_file_atomic("/dev/null", "discarded"));
  EXPECT_EQ(fs::status("/dev/null").type(), fs::file_type::character);
}

TEST(AtomicWrite, TerminationDuringAWriteLeavesNoTemporary) {
  TempDir dir;
  const fs::path out = dir.path / "big.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporaries_on_signal();
    const std::string content(size_t{1} << 27, 'x');  // long enough to be interrupted
    write_file_atomic(out, content);
    ::_exit(0);
  }
  // Wait for the temporary file to appear, then terminate the writer.
  auto temporary_exists = [&] {
    for (const auto& e : fs::directory_iterator(dir.path))
      if (e.path().filename().string().rfind(".big.txt.tmp.", 0) == 0) return true;
    return false;
  };
  bool seen = false;
  for (int k = 0; k < 20000 && !seen; ++k) {
    seen = temporary_exists();
    if (!seen) ::usleep(500);
  }
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(seen);
  if (fs::exists(out)) GTEST_SKIP() << "the write finished before the signal arrived";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_EQ(dir.entries(), 0u);
}
