#pragma once
// Semi-implicit (symplectic) Euler, as in the thesis (MODEL §4): velocities from forces,
// then positions from the new velocities, for free discs and for rigid cluster bodies.
#include <cstddef>
#include <cstdint>

#include "contact/thread_split.hpp"
#include "particles/clusters.hpp"
#include "particles/disc_force.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct BodyForce {
  double gx = 0.0, gy = -1.0;  // gravitational acceleration (tilted for inclined-plane problems)
  double drag = 0.0;           // extra viscous drag rate (1/time), used only while settling
};

// How far the discs of a thread's share moved from their reference positions.
struct Displacement {
  double max2 = 0;              // largest squared distance
  std::int64_t not_finite = 0;  // NaN distances, counted apart so that the max stays a max
  double distance() const;      // sqrt(max2), or infinity if any was NaN
};

// Advances thread t's free discs and cluster bodies (its shares of `split`) by dt under the
// given disc forces, then places their member discs on the bodies; kinematic discs and bodies
// move with their imposed velocity. Returns how far those discs are from their reference
// positions (x_ref, y_ref by disc index, the positions at the last neighbour-list build):
// measured here, where the positions are written anyway, rather than in a pass of its own; the
// step's largest displacement is the max over the threads. For a step run in one thread team
// (World::step_stages); no barrier. Zeroes the force sums of the discs it integrates once used,
// so that they are zero for the next step's force stages.
Displacement integrate_share(Discs& discs, Clusters& clusters, DiscForce* forces, const BodyForce& body,
                             double dt, const double* x_ref, const double* y_ref, const ThreadSplit& split,
                             std::size_t t);

}  // namespace orogen
