#pragma once
// Appends output steps to `snapshots.h5`, one group per output. Crash safety: the root
// attribute `n_outputs` is written last, after the new group is complete and flushed to
// disk, and readers trust only groups below it (see docs/output-files.md).
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5_file.hpp"
#include "particles/discs.hpp"

namespace orogen {

// One output step as handed to the writers (snapshots.h5 and the .vtp files).
struct SnapshotFrame {
  std::int64_t step = 0;
  double time = 0;
  std::map<std::string, double> attrs;  // extra scalars stored on the group (e.g. "S")
  const Discs* discs = nullptr;
  std::vector<std::pair<std::string, std::vector<double>>> fields;  // extra per-disc fields
  std::vector<std::array<double, 4>> walls;                          // ax, ay, bx, by
};

// Caller metadata stored as root attributes (parameters, version strings, ...).
struct SnapshotMetadata {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> strings;
};

inline constexpr const char* kSnapshotFormat = "orogen-snapshots";
inline constexpr std::int64_t kSnapshotVersion = 1;

// The per-disc arrays of Discs that a snapshot stores (forces and internals are left out).
inline constexpr std::array<const char*, 13> kSnapshotDiscArrays = {
    "x", "y", "theta", "vx", "vy", "omega", "radius", "id", "cluster_id", "motion", "x0", "y0", "depth0"};

// "output_000042" for k = 42.
std::string snapshot_group_name(std::int64_t k);

class SnapshotWriter {
 public:
  // Creates a new file with no outputs (atomically replacing any old one).
  // `storage.deflate` > 0 stores datasets shuffled and deflated at that level.
  explicit SnapshotWriter(std::filesystem::path path, const SnapshotMetadata& meta = {},
                          h5::WriteOptions storage = {.deflate = 1});

  // Continues an existing file after its last complete output; groups a killed run left
  // beyond `n_outputs` are deleted.
  static SnapshotWriter reopen(std::filesystem::path path, h5::WriteOptions storage = {.deflate = 1});

  // Adds group output_<count()>; the file is open only during this call.
  void append(const SnapshotFrame& frame);

  std::int64_t count() const { return count_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  struct Reopened {};
  SnapshotWriter(Reopened, std::filesystem::path path, std::int64_t count, h5::WriteOptions storage);
  std::filesystem::path path_;
  std::int64_t count_ = 0;
  h5::WriteOptions storage_;
};

// Keeps outputs 0..k-1 (for a resumed run): sets n_outputs = k, then deletes later groups.
void truncate_snapshots(const std::filesystem::path& path, std::int64_t k);

}  // namespace orogen
