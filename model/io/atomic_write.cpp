#include "model/io/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "model/core/error.hpp"

namespace gmr::io {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

// Creates "<dir>/.<name>.tmp.<pid>.<k>" with O_EXCL (mode 0666 before umask, like a plain
// ofstream), retrying on a name clash.
int create_temp(const std::filesystem::path& path, std::filesystem::path& tmp) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  for (int attempt = 0; attempt < 100; ++attempt) {
    tmp = dir / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                 std::to_string(counter++));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST)
      throw Error(ErrorCode::Io, "cannot create a temporary file in " + dir.string() + ": " + errno_text(errno),
                  path.string());
  }
  throw Error(ErrorCode::Io, "cannot find a free temporary file name in " + dir.string(), path.string());
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  if (path.empty()) throw Error(ErrorCode::Io, "empty output path");
  if (!path.has_filename()) throw Error(ErrorCode::Io, "output path names a directory", path.string());
  std::filesystem::path tmp;
  const int fd = create_temp(path, tmp);
  auto fail = [&](const std::string& what, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, what + ": " + errno_text(err), path.string());
  };
  const char* p = content.data();
  size_t left = content.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      fail("write failed", errno);
    }
    p += w;
    left -= static_cast<size_t>(w);
  }
  if (::fsync(fd) != 0) fail("fsync failed", errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, "close failed: " + errno_text(err), path.string());
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, "cannot rename the temporary file into place: " + errno_text(err), path.string());
  }
}

}  // namespace gmr::io
