#pragma once
// Forces between discs and walls, added onto the discs after the pair forces.
#include <cstddef>
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/contact_store.hpp"
#include "contact/thread_split.hpp"
#include "particles/clusters.hpp"
#include "particles/disc_force.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Adds the wall contact forces and torques of thread t's discs (World::step_stages), each
// disc's in wall order (the sums are the same for any thread count and split). Updates each
// contact's history and flags. No barrier.
void wall_forces_share(WallContacts& contacts, const Discs& discs, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, DiscForce* forces, const ThreadSplit& split, std::size_t t);

}  // namespace orogen
