#pragma once
// The force and torque summed on a disc in one step: what the force stages (pair forces,
// wall forces) add up and the integrator uses and zeroes. A type of its own, so that the
// integrator and the wall forces need not include the pair-force loops for it.

namespace orogen {

// One cache line holds a disc's sums.
struct DiscForce {
  double fx, fy, torque;
};

}  // namespace orogen
