#pragma once
// Forces between discs and walls, added onto the discs after the pair forces.
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_forces.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Adds wall contact forces and torques to the discs, in wall-contact order (serial, so the
// sums are the same for any thread count). Updates each contact's history and flags.
void add_wall_forces(NeighborList& list, const Discs& discs, const std::vector<Wall>& walls, const ContactLaw& law,
                     double dt, std::vector<DiscForce>& forces);

}  // namespace orogen
