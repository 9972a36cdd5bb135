#pragma once
// Positions of every disc at the last three output steps, by stable id, and the per-disc
// fields computed from them (MODEL §11): the maximum displacement relative to touching
// neighbours since the previous output (the thesis's fault-finding colouring, Figs 3.20,
// 4.5c) and each disc's displacement over the last three outputs (Fig 5.11). Every
// experiment that stores these fields keeps one tracker and calls remember() after each output.
#include <string>
#include <utility>
#include <vector>

#include "io/binary_archive.hpp"
#include "io/snapshot_field.hpp"
#include "world/world.hpp"

namespace orogen {

class DisplacementTracker {
 public:
  // Called after each output step: shifts the stored positions back by one output.
  void remember(const World& world);
  // max_rel_disp, disp3_x, disp3_y, by disc index (NaN where a disc did not exist then).
  std::vector<SnapshotField> fields(const World& world) const;

  void save(ArchiveWriter& out, const std::string& prefix) const;
  void load(const ArchiveReader& in, const std::string& prefix);

 private:
  std::vector<double> prev_x_[3], prev_y_[3];
};

}  // namespace orogen
