#pragma once
// Reads snapshots.h5 back (analysis, tests, restarts from a snapshot). Only groups below
// the root attribute n_outputs are trusted; later ones may be half-written.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/snapshot_writer.hpp"

namespace orogen {

struct Snapshot {
  std::int64_t step = 0;
  double time = 0;
  std::map<std::string, double> attrs;                // extra group attributes (not step, time)
  std::map<std::string, std::vector<double>> fields;  // every 1-D float dataset: x, y, ..., extras
  std::vector<std::int64_t> id, cluster_id;
  std::vector<std::uint8_t> motion;
  std::vector<std::uint8_t> material;  // a run of named materials only (empty otherwise)
  std::vector<std::array<double, 4>> walls;

  std::size_t size() const { return id.size(); }
  // The named float field; throws naming it if absent.
  const std::vector<double>& field(const std::string& name) const;
};

// What an output says of itself, without its data: its step, time and the resolved
// configuration it was written with ("" in files made before outputs carried it).
struct OutputStamp {
  std::int64_t step = 0;
  double time = 0;
  std::string config_toml;
};

class SnapshotReader {
 public:
  // Opens read-only and keeps the file open; checks format and version.
  explicit SnapshotReader(const std::filesystem::path& path);

  std::int64_t count() const { return count_; }  // complete outputs (n_outputs)
  Snapshot read(std::int64_t k) const;           // 0 <= k < count()
  OutputStamp stamp(std::int64_t k) const;       // the attributes of output k alone
  // The data file of output k (DIR/snapshots/output_NNNNNN.h5), for messages.
  std::filesystem::path output_path(std::int64_t k) const;
  const SnapshotMetadata& metadata() const { return meta_; }
  // The extra groups of output k (SnapshotFrame::groups): whether it has one, and a float
  // dataset of it (1-D as rows x 1).
  bool has_group(std::int64_t k, const std::string& group) const;
  h5::Matrix read_group_dataset(std::int64_t k, const std::string& group, const std::string& name) const;

 private:
  void check_index(std::int64_t k) const;  // throws std::out_of_range unless 0 <= k < count()

  std::filesystem::path path_;
  h5::File file_;
  std::int64_t count_ = 0;
  SnapshotMetadata meta_;
};

}  // namespace orogen
