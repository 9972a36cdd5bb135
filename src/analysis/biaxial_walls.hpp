#pragma once
// Forces a sample exerts on its walls, for the stress-controlled walls of the biaxial test.
// Only the elastic part of each wall contact (k_n times the overlap, at the current positions)
// is summed: the dashpot part reacts to the wall's own velocity within a step, which would
// make a velocity servo that reads it unstable at any useful gain, and in a quasi-static test
// it averages to nothing.
#include <vector>

#include "world/world.hpp"

namespace orogen {

struct WallForce {
  double fx = 0, fy = 0;  // force on the wall [code units: density-1 disc mass * g]
};

// One entry per wall of the world, in wall order, from the neighbour list's wall contacts.
std::vector<WallForce> elastic_wall_forces(const World& world);

}  // namespace orogen
