#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace orogen {
namespace {

[[noreturn]] void throw_errno(const std::string& what, const std::filesystem::path& path) {
  throw std::system_error(errno, std::generic_category(), what + " '" + path.string() + "'");
}

// Owns a POSIX descriptor so every error path closes it.
class Fd {
 public:
  Fd(const std::filesystem::path& path, int flags, mode_t mode = 0) : fd_(::open(path.c_str(), flags, mode)) {
    if (fd_ < 0) throw_errno("cannot open", path);
  }
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void close(const std::filesystem::path& path) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw_errno("cannot close", path);
  }

 private:
  int fd_;
};

void fsync_fd(const Fd& fd, const std::filesystem::path& path) {
  if (::fsync(fd.get()) != 0) throw_errno("cannot fsync", path);
}

// A rename is durable only once the directory entry itself is on disk.
void fsync_directory(const std::filesystem::path& file) {
  std::filesystem::path dir = file.parent_path();
  if (dir.empty()) dir = ".";
  Fd fd(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  fsync_fd(fd, dir);
}

}  // namespace

std::filesystem::path temp_path_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid());
  return tmp;
}

void fsync_file(const std::filesystem::path& path) {
  Fd fd(path, O_RDONLY | O_CLOEXEC);
  fsync_fd(fd, path);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  AtomicPath out(path);
  {
    Fd fd(out.temp(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const char* p = content.data();
    std::size_t left = content.size();
    while (left > 0) {
      const ssize_t n = ::write(fd.get(), p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw_errno("cannot write", out.temp());
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    fsync_fd(fd, out.temp());
    fd.close(out.temp());
  }
  out.commit();
}

AtomicPath::AtomicPath(std::filesystem::path final_path)
    : final_(std::move(final_path)), temp_(temp_path_for(final_)) {}

AtomicPath::~AtomicPath() {
  if (!committed_) {
    std::error_code ec;  // best effort: a destructor must not throw
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicPath::commit() {
  fsync_file(temp_);
  if (::rename(temp_.c_str(), final_.c_str()) != 0) throw_errno("cannot rename onto", final_);
  committed_ = true;
  fsync_directory(final_);
}

}  // namespace orogen
