#pragma once
// Semi-implicit (symplectic) Euler, as in the thesis (MODEL §4): velocities from forces,
// then positions from the new velocities, for free discs and for rigid cluster bodies.
#include "contact/pair_forces.hpp"
#include "contact/thread_split.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct BodyForce {
  double gx = 0.0, gy = -1.0;  // gravitational acceleration (tilted for inclined-plane problems)
  double drag = 0.0;           // extra viscous drag rate (1/time), used only while settling
};

// Advances free discs and cluster bodies by dt under the given disc forces, then places member
// discs on their bodies. Kinematic discs and bodies move with their imposed velocity.
// Returns the largest distance of a disc from its reference position (x_ref, y_ref by disc
// index, the positions at the last neighbour-list build): measured here, where the positions
// are written anyway, rather than in a pass of its own. Discs and bodies are cut between
// threads by `split`.
double integrate(Discs& discs, Clusters& clusters, const DiscForce* forces, const BodyForce& body, double dt,
                 const double* x_ref, const double* y_ref, const ThreadSplit& split);

}  // namespace orogen
