#pragma once
// Fixing particles in space (the thesis's fixed particles: the lowermost particles of the
// slump experiment, the lip of the ledge experiment): flagged discs become kinematic at rest.
#include <cstdint>
#include <span>

#include "world/world.hpp"

namespace orogen {

// Holds the flagged discs (by index) at rest; a flagged cluster disc holds its whole cluster.
// Returns the number of discs held at rest in the world afterwards.
std::size_t hold_at_rest(World& world, std::span<const std::uint8_t> flags);

}  // namespace orogen
