#include "io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <stdexcept>
#include <utility>

namespace orogen {

FileLock::FileLock(std::filesystem::path path, On on) : path_(std::move(path)) {
  const int flags = on == On::Folder ? O_RDONLY | O_DIRECTORY | O_CLOEXEC : O_RDWR | O_CREAT | O_CLOEXEC;
  const int fd = ::open(path_.c_str(), flags, 0644);
  if (fd < 0) {
    open_error_ = errno;
    return;
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return;
  }
  fd_ = fd;
}

FileLock::FileLock(FileLock&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)), open_error_(other.open_error_) {}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);  // closing drops the lock
}

void FileLock::release_and_remove() {
  if (fd_ < 0) return;
  std::error_code ec;
  std::filesystem::remove(path_, ec);  // still ours: nobody else can hold it while we do
  ::close(fd_);
  fd_ = -1;
}

FileLock lock_command_folder(const std::filesystem::path& path, const std::string& what) {
  FileLock lock(path);
  if (lock.open_error() != 0) throw std::runtime_error(fmt::format("cannot create {}", path.string()));
  if (!lock.locked())
    throw std::runtime_error(fmt::format("another {} is running in {}", what, path.parent_path().string()));
  return lock;
}

}  // namespace orogen
