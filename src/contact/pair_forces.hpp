#pragma once
// Disc-disc contact forces over the Verlet list.
#include <cstdint>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/discs.hpp"

namespace orogen {

// What the contact kernel reads of a disc, packed so that a pair touches two cache lines
// instead of a dozen (one array per field).
struct ContactDisc {
  double x, y, vx, vy, omega, radius;
};

// Force and torque summed on a disc, packed likewise.
struct DiscForce {
  double fx, fy, torque;
};

// Scratch of the force loop: packed discs and their force sums.
struct PairScratch {
  std::vector<ContactDisc> discs;
  std::vector<DiscForce> forces;
};

// Sets discs' force and torque to the sum of their contact forces, chunk by chunk (see
// NeighborList::chunk_start): bitwise the same result for any number of threads.
void compute_pair_forces(NeighborList& list, Discs& discs, const ContactLaw& law, double dt,
                         PairScratch& scratch);

}  // namespace orogen
