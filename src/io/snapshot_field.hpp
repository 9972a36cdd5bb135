#pragma once
// An extra per-disc field of a snapshot (e.g. a wedge's max_rel_disp), documented where it is
// made: the writer stores units and description as the dataset's attributes and refuses empty ones.
#include <string>
#include <vector>

namespace orogen {

struct SnapshotField {
  std::string name;
  std::vector<double> values;  // by disc index
  std::string units, description;
};

}  // namespace orogen
