#pragma once
// Extra groups of datasets in an output beside the per-disc arrays (contacts, stress,
// cluster poses: docs/output-files.md), each dataset with its `units` and `description`
// string attributes, so that the file says what it holds.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "io/hdf5_file.hpp"

namespace orogen {

// 1-D, or rows x `columns` stored row-major when columns > 1.
struct SnapshotDataset {
  std::string name, units, description;
  std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::uint8_t>> values;
  std::size_t columns = 1;
};

struct SnapshotGroup {
  std::string name, description;
  std::map<std::string, double> attrs;  // scalars on the group (grid origin, cell size, ...)
  std::vector<SnapshotDataset> datasets;
};

// Throws std::invalid_argument for an empty or duplicate name, a '/' in one, or a value
// count that is not a multiple of the columns.
void validate_snapshot_group(const SnapshotGroup& g);

// Creates the group `g.name` under `parent` and writes its datasets and attributes.
void write_snapshot_group(hid_t parent, const SnapshotGroup& g, h5::WriteOptions storage);

}  // namespace orogen
