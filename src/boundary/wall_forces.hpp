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

// The discs' slip for weakening walls (a world of materials; else both null): the slip at the
// step's start, which sets each wall's coefficient, and the slip the step adds to.
struct WallSlip {
  const double* at_start = nullptr;
  double* slip = nullptr;
};

// Adds the wall contact forces and torques of thread t's discs (World::step_stages), each
// disc's in wall order (the sums are the same for any thread count and split). Updates each
// contact's history and flags. No barrier.
void wall_forces_share(WallContacts& contacts, const Discs& discs, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, const WallSlip& slip, DiscForce* forces, const ThreadSplit& split, std::size_t t);

}  // namespace orogen
