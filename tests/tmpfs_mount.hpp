#pragma once
// Small tmpfs mounts for the full-disk and read-only tests (root only: a test skips itself,
// saying so, where mounting is not allowed).
#include <cstdlib>
#include <filesystem>
#include <string>

namespace orogen::testing {

// A tmpfs of `size` (e.g. "600k") mounted at `dir`; false where mounting is not allowed.
inline bool mount_tmpfs(const std::filesystem::path& dir, const std::string& size) {
  std::filesystem::create_directories(dir);
  return std::system(("mount -t tmpfs -o size=" + size + " tmpfs '" + dir.string() + "' 2>/dev/null").c_str()) == 0;
}

inline bool remount(const std::filesystem::path& dir, const std::string& options) {
  return std::system(("mount -o remount," + options + " '" + dir.string() + "' 2>/dev/null").c_str()) == 0;
}

// Unmounts (lazily) when the test ends, however it ends.
struct Unmount {
  std::filesystem::path dir;
  ~Unmount() { std::system(("umount -l '" + dir.string() + "' 2>/dev/null").c_str()); }
};

}  // namespace orogen::testing
