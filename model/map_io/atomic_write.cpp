#include "model/map_io/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#include "model/core/error.hpp"

namespace gmr::io {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

// The temporary files being written, for removal on SIGINT/SIGTERM. A fixed table of C strings:
// the signal handler may only use async-signal-safe calls (unlink, signal, raise).
constexpr size_t kPendingSlots = 32;
constexpr size_t kPathBytes = 4096;
enum SlotState : int { kFree, kClaimed, kArmed };  // kArmed: the path is complete
std::array<std::atomic<int>, kPendingSlots> pending_state{};
std::array<std::array<char, kPathBytes>, kPendingSlots> pending_path{};

extern "C" void remove_temporaries_and_reraise(int sig) {
  for (size_t k = 0; k < kPendingSlots; ++k)
    if (pending_state[k].load() == kArmed) ::unlink(pending_path[k].data());
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// A temporary file path registered for removal on a signal, armed before the file is created
// (so that no signal finds the file unregistered) and disarmed on destruction.
class PendingTemporary {
 public:
  PendingTemporary() = default;
  ~PendingTemporary() { disarm(); }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

  void arm(const std::filesystem::path& tmp) {
    disarm();
    const std::string& s = tmp.native();
    if (s.size() >= kPathBytes) return;
    for (size_t k = 0; k < kPendingSlots; ++k) {
      int expected = kFree;
      if (!pending_state[k].compare_exchange_strong(expected, kClaimed)) continue;
      std::memcpy(pending_path[k].data(), s.c_str(), s.size() + 1);
      pending_state[k].store(kArmed);
      slot_ = k;
      return;
    }
  }
  void disarm() {
    if (slot_ < kPendingSlots) pending_state[slot_].store(kFree);
    slot_ = kPendingSlots;
  }

 private:
  size_t slot_ = kPendingSlots;
};

// Creates "<dir>/.<name>.tmp.<pid>.<k>" with O_EXCL (mode 0666 before umask, like a plain
// ofstream), retrying on a name clash.
int create_temp(const std::filesystem::path& path, std::filesystem::path& tmp,
                PendingTemporary& pending) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  for (int attempt = 0; attempt < 100; ++attempt) {
    tmp = dir / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                 std::to_string(counter++));
    pending.arm(tmp);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    pending.disarm();
    if (errno != EEXIST)
      throw Error(ErrorCode::Io,
                  "cannot create a temporary file in " + dir.string() + ": " + errno_text(errno),
                  path.string());
  }
  throw Error(ErrorCode::Io, "cannot find a free temporary file name in " + dir.string(),
              path.string());
}

// Writes all of `content` to `fd`; false with errno set on failure.
bool write_all(int fd, std::string_view content) {
  const char* p = content.data();
  size_t left = content.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    left -= static_cast<size_t>(w);
  }
  return true;
}

// A destination that is not a regular file (a FIFO, a terminal, /dev/null, ...): written in
// place, since renaming over it would replace the special file by a regular one.
void write_special(const std::filesystem::path& path, std::string_view content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0)
    throw Error(ErrorCode::Io, "cannot open for writing: " + errno_text(errno), path.string());
  if (!write_all(fd, content)) {
    const int err = errno;
    ::close(fd);
    throw Error(ErrorCode::Io, "write failed: " + errno_text(err), path.string());
  }
  if (::close(fd) != 0)
    throw Error(ErrorCode::Io, "close failed: " + errno_text(errno), path.string());
}

// The file a write to `path` lands in: symbolic links are followed (the link stays a link and
// its target gets the content), dangling ones included.
std::filesystem::path resolve_links(const std::filesystem::path& path) {
  std::filesystem::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
    const std::filesystem::path target = std::filesystem::read_symlink(p, ec);
    if (ec)
      throw Error(ErrorCode::Io, "cannot read the symbolic link: " + ec.message(), path.string());
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  throw Error(ErrorCode::Io, "too many levels of symbolic links", path.string());
}

}  // namespace

void remove_temporaries_on_signal() {
  std::signal(SIGINT, remove_temporaries_and_reraise);
  std::signal(SIGTERM, remove_temporaries_and_reraise);
}

void write_file_atomic(const std::filesystem::path& requested, std::string_view content) {
  if (requested.empty()) throw Error(ErrorCode::Io, "empty output path");
  const std::filesystem::path path = resolve_links(requested);
  if (!path.has_filename())
    throw Error(ErrorCode::Io, "output path names a directory", requested.string());
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode))
      throw Error(ErrorCode::Io, "output path names a directory", requested.string());
    if (!S_ISREG(st.st_mode)) return write_special(path, content);
  }
  std::filesystem::path tmp;
  PendingTemporary pending;
  const int fd = create_temp(path, tmp, pending);
  auto fail = [&](const std::string& what, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, what + ": " + errno_text(err), requested.string());
  };
  if (!write_all(fd, content)) fail("write failed", errno);
  if (::fsync(fd) != 0) fail("fsync failed", errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, "close failed: " + errno_text(err), requested.string());
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(ErrorCode::Io, "cannot rename the temporary file into place: " + errno_text(err),
                requested.string());
  }
}

}  // namespace gmr::io
