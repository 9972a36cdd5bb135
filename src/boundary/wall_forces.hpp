#pragma once
// Forces between discs and walls, added onto the discs after the pair forces.
#include <cstddef>
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_forces.hpp"
#include "contact/thread_split.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Adds wall contact forces and torques to the discs, each disc's in wall order (the sums are
// the same for any thread count and split). Updates each contact's history and flags.
void add_wall_forces(NeighborList& list, const Discs& discs, const std::vector<Wall>& walls, const ContactLaw& law,
                     double dt, std::vector<DiscForce>& forces, const ThreadSplit& split);

// Thread t's share of add_wall_forces (the wall contacts of its discs), for a step run in one
// thread team; no barrier.
void wall_forces_share(NeighborList& list, const Discs& discs, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, DiscForce* forces, const ThreadSplit& split, std::size_t t);

}  // namespace orogen
