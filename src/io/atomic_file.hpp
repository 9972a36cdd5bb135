#pragma once
// Atomic file replacement: content goes to a temporary file in the same directory, is
// fsync'ed, then renamed over the final name. A run killed at any moment leaves either
// the old file or the new one, never a half-written file under the final name (at worst
// a stray `NAME.tmp-<pid>` that nothing reads).
#include <filesystem>
#include <string_view>

namespace orogen {

// Replaces `path` with `content` atomically and durably.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Flushes a file's data to disk (also used on HDF5 files after closing them).
void fsync_file(const std::filesystem::path& path);

// For libraries that write a file by name themselves (HDF5): write to temp(), then
// commit(). If commit() is never reached, the destructor removes the temporary file.
class AtomicPath {
 public:
  explicit AtomicPath(std::filesystem::path final_path);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;

  const std::filesystem::path& temp() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  // fsyncs the temporary file, renames it over the final name and fsyncs the directory.
  void commit();

 private:
  std::filesystem::path final_, temp_;
  bool committed_ = false;
};

// The temporary name used for `path`: `path.tmp-<pid>` in the same directory.
std::filesystem::path temp_path_for(const std::filesystem::path& path);

}  // namespace orogen
