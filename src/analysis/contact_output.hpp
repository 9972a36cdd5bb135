#pragma once
// The optional output groups of an output step (docs/output-files.md): the contact list with
// forces (`output.contacts`), the Love-Weber stress per disc (`output.stress`) and on a grid
// (`output.stress_grid`), and the cluster bodies' poses (always, when a run has clusters).
// Built from the current state without changing it.
#include <vector>

#include "io/snapshot_groups.hpp"
#include "world/world.hpp"

namespace orogen {

struct ContactOutputOptions {
  bool contacts = false;
  bool stress = false;
  double stress_grid = 0;  // cell size [d], 0 = no grid
};

std::vector<SnapshotGroup> contact_output_groups(const World& world, const ContactOutputOptions& options);

}  // namespace orogen
