#include "io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

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

}  // namespace orogen
