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

// Per-step scratch of the force stages: the packed discs, and the force and torque summed on
// each disc (by disc index) that integration then uses.
struct PairScratch {
  std::vector<ContactDisc> discs;
  std::vector<DiscForce> forces;
};

// Packs the discs for the force loop and returns the largest displacement of a disc since the
// last neighbour-list build (infinite when the list does not match the discs): one pass over
// the positions serves both.
double pack_discs(const Discs& discs, const NeighborList& list, PairScratch& scratch);

// Sets discs' force and torque to the sum of their contact forces, chunk by chunk (see
// NeighborList::chunk_start): bitwise the same result for any number of threads.
// Uses the packed discs of the scratch; forces start from zero.
void compute_pair_forces(NeighborList& list, const ContactLaw& law, double dt, PairScratch& scratch);

}  // namespace orogen
