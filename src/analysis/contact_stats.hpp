#pragma once
// Contact statistics from the current neighbour list and positions.
#include "world/world.hpp"

namespace orogen {

struct ContactStats {
  std::size_t contacts = 0;        // touching disc pairs
  double contacts_per_disc = 0;    // 2 * contacts / discs
  double max_overlap = 0;          // largest overlap of a touching pair
};

ContactStats measure_contacts(const World& world);

}  // namespace orogen
