#pragma once
// An exclusive advisory lock (flock) on one file, held while the object lives. The kernel drops
// it when the process dies, even by kill -9, so a killed command never leaves a folder locked.
#include <filesystem>
#include <string>

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
  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&&) = delete;

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

// The lock file `path` of a command that owns a folder (a sweep, an ensemble), held until the
// returned lock ends; throws std::runtime_error when the file cannot be created or another
// `what` ("sweep") already holds it: two would start the same runs twice.
FileLock lock_command_folder(const std::filesystem::path& path, const std::string& what);

}  // namespace orogen
