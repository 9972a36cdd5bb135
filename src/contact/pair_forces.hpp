#pragma once
// Disc-disc contact forces over the Verlet list.
#include <cstdint>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Per-pair scratch for the multi-threaded path.
struct PairScratch {
  std::vector<double> fx, fy, ft;
  std::vector<std::uint8_t> touching;
};

// Sets discs' force and torque to the sum of their contact forces. With one thread the forces
// are scattered straight onto the discs in pair order; with more, each pair's force goes to
// scratch (parallel over pairs) and every disc sums its pairs in the same ascending pair
// order. Both paths add the same terms in the same order, so the results are bitwise equal.
void compute_pair_forces(NeighborList& list, Discs& discs, const ContactLaw& law, double dt,
                         PairScratch& scratch);

}  // namespace orogen
