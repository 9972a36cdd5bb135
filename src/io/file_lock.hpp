#pragma once
// An exclusive advisory lock (flock) on one file, held while the object lives. The kernel drops
// it when the process dies, even by kill -9, so a killed command never leaves a folder locked.
#include <filesystem>

namespace orogen {

class FileLock {
 public:
  // File: a lock file, created if missing. Folder: the folder itself (nothing is written, so
  // a command that reads a folder can hold it without leaving a trace).
  enum class On { File, Folder };
  // Opens `path` and takes the lock without waiting: see locked() and open_error().
  explicit FileLock(std::filesystem::path path, On on = On::File);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  bool locked() const { return fd_ >= 0; }
  // errno of a failed open (a read-only or missing folder); 0 when it opened and another
  // process holds the lock, or when it is locked.
  int open_error() const { return open_error_; }
  const std::filesystem::path& path() const { return path_; }

  // Drops the lock and removes the lock file (a command that leaves nothing behind; not for
  // a folder).
  void release_and_remove();

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  int open_error_ = 0;
};

}  // namespace orogen
