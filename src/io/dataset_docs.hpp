#pragma once
// Units and descriptions of the datasets Orogen's snapshot files store, in one table, so that
// every dataset carries them as attributes (`units`, `description`) and docs/output-files.md
// can be checked against the files. Extra per-disc fields bring their own (SnapshotField).
// Units are the model's (docs/model.md): lengths in d (the largest disc diameter), time in
// sqrt(d/g), "-" for counts, ids, flags and other numbers without a unit.
#include <string_view>

namespace orogen {

struct DatasetDoc {
  std::string_view name, units, description;
};

// The documentation of a dataset the snapshot writer itself stores (the per-disc arrays of
// kSnapshotDiscArrays and `walls`), or nullptr for any other name.
const DatasetDoc* find_dataset_doc(std::string_view name);

// Attribute names on every dataset.
inline constexpr const char* kUnitsAttr = "units";
inline constexpr const char* kDescriptionAttr = "description";

}  // namespace orogen
