#pragma once
// Writes the output steps of a run: each output is a file of its own in `snapshots/`, written
// to a temporary name and renamed into place, and `snapshots.h5` is a small index (metadata,
// n_outputs and one external link per output) rewritten the same way after each output.
// A kill at any moment thus leaves complete files only: HDF5 gives no such promise for a file
// changed in place (a killed append could leave a file that cannot even be truncated).
// Readers open the index and see one group per output (see docs/output-files.md).
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/snapshot_field.hpp"
#include "io/xdmf_writer.hpp"
#include "io/snapshot_groups.hpp"
#include "particles/discs.hpp"

namespace orogen {

// One output step as handed to the writers (snapshots.h5 and the .vtp files).
struct SnapshotFrame {
  std::int64_t step = 0;
  double time = 0;
  std::map<std::string, double> attrs;  // extra scalars stored on the group (e.g. "S")
  const Discs* discs = nullptr;
  std::vector<SnapshotField> fields;                                 // extra per-disc fields
  std::vector<std::array<double, 4>> walls;                          // ax, ay, bx, by
  std::vector<SnapshotGroup> groups;  // extra groups beside the disc arrays (contacts, stress, ...)
};

// Caller metadata stored as root attributes (parameters, version strings, ...). The string
// kConfigAttr (the resolved configuration's TOML) is also stored on every output file.
struct SnapshotMetadata {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> strings;
};

inline constexpr const char* kSnapshotFormat = "orogen-snapshots";
inline constexpr std::int64_t kSnapshotVersion = 1;
inline constexpr const char* kConfigAttr = "config_toml";

// A readable HDF5 file that is not an orogen snapshot file, or one of another format version:
// the wrong file given (exit 2), where other h5::Errors are a damaged file (exit 1).
struct SnapshotFormatError : h5::Error {
  using h5::Error::Error;
};

// The per-disc arrays of Discs that a snapshot stores (forces and internals are left out).
inline constexpr std::array<const char*, 13> kSnapshotDiscArrays = {
    "x", "y", "theta", "vx", "vy", "omega", "radius", "id", "cluster_id", "motion", "x0", "y0", "depth0"};

// "output_000042" for k = 42.
std::string snapshot_group_name(std::int64_t k);

class SnapshotWriter {
 public:
  // Starts a new series with no outputs: an empty index at `path` (atomically replacing any
  // old one) and an empty data folder beside it (see data_folder).
  // `storage.deflate` > 0 stores datasets shuffled and deflated at that level.
  explicit SnapshotWriter(std::filesystem::path path, const SnapshotMetadata& meta = {},
                          h5::WriteOptions storage = {.deflate = 1});

  // Continues a series after its first `keep` outputs (a resumed run: the outputs its
  // checkpoint knows). The index is rewritten to list those alone and later data files, and
  // any a killed write left half-done, are deleted. Throws if fewer than `keep` are there.
  static SnapshotWriter reopen(std::filesystem::path path, std::int64_t keep,
                               h5::WriteOptions storage = {.deflate = 1});

  // Writes output count() as its own file, then the index that counts it.
  void append(const SnapshotFrame& frame);

  // Replaces one string of the metadata and rewrites the index (a resume that extends a run
  // stores its new configuration; outputs already written keep theirs).
  void set_metadata_string(const std::string& name, const std::string& value);

  std::int64_t count() const { return count_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  SnapshotWriter(std::filesystem::path path, SnapshotMetadata meta, std::int64_t count, h5::WriteOptions storage);
  void write_index() const;
  void write_sidecar() const;  // snapshots.xmf, after write_index (whose disc_index it reads)
  std::filesystem::path path_;
  std::vector<XdmfOutput> xdmf_;  // the sidecar's outputs (snapshots.xmf)
  SnapshotMetadata meta_;
  std::int64_t count_ = 0;
  h5::WriteOptions storage_;
};

// The folder of per-output files beside an index: "snapshots" for "snapshots.h5".
std::filesystem::path data_folder(const std::filesystem::path& index);

// A self-contained file holding one output (packing.h5): no data folder, so it can be copied
// alone. Readers see the same layout as an index with one output. An XDMF sidecar
// (packing.xmf) is written beside it.
void write_single_snapshot(const std::filesystem::path& path, const SnapshotMetadata& meta, const SnapshotFrame& frame,
                           h5::WriteOptions storage = {.deflate = 1});

// The metadata stored on a snapshot file's root (for reopening an index).
SnapshotMetadata read_snapshot_metadata(const std::filesystem::path& path);

}  // namespace orogen
