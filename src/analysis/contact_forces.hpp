#pragma once
// The contacts of the current state with their forces, for output: the same laws as the force
// stages (contact_lane, wall_contact_force) on copies of the stored histories, so the list
// holds bitwise the forces the next step applies and the world is left as it was.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "world/world.hpp"

namespace orogen {

// Contact k: body a acts on body b with force f (b feels f, a feels -f). A pair: a and b are
// discs, a the one with the lower stable id. A wall contact: a is the wall, b the disc.
struct ContactList {
  std::vector<std::uint8_t> is_wall;
  std::vector<std::int64_t> id_a, id_b;        // stable disc ids; a wall's id_a is its row among the enabled walls
  std::vector<std::int64_t> index_a, index_b;  // disc indices in the current arrays (-1 for a wall)
  std::vector<double> x, y;                    // contact point: the middle of the overlap
  std::vector<double> nx, ny;                  // unit normal from a to b
  std::vector<double> fn, ft;                  // force on b along n and along t = (-ny, nx)
  std::vector<double> fx, fy;                  // the same force in x and y
  std::vector<double> overlap;
  std::vector<std::uint8_t> at_limit;          // tangential force on the Coulomb limit

  std::size_t size() const { return is_wall.size(); }
};

// Touching pairs in neighbour-list order, then wall contacts in wall, then disc order. A list
// the next step would rebuild is rebuilt on a copy first (without re-ordering the discs).
ContactList measure_contact_forces(const World& world);

}  // namespace orogen
