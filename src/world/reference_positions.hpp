#pragma once
// The Verlet list's rebuild test: disc and wall-end positions at the last build, and how far
// the walls moved since (the discs' displacement is measured by integration).
#include <vector>

#include "boundary/wall.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Records the disc and wall-end positions of this build.
void record_reference_positions(NeighborList& list, const Discs& discs, const std::vector<Wall>& walls);

// Largest displacement of a wall end since the last build (infinite if the walls changed).
// The list is rebuilt when this plus the largest disc displacement exceeds half the skin.
double wall_displacement(const NeighborList& list, const std::vector<Wall>& walls);

}  // namespace orogen
