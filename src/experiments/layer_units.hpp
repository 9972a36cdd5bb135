#pragma once
// The incoming section of a layered crust (docs/materials.md): the discs of a settled layer
// take the material of the unit ([[layer.units]]) at their height, and the bonding materials
// bond their touching discs. Nothing happens in a world without materials.
#include <cstddef>
#include <cstdint>

#include "world/world.hpp"

namespace orogen {

// Gives the discs [first, last), settled on a base at y = 0, the material of the unit at their
// height, then bonds them (World::make_bonds, strengths scattered from `seed`). Returns the
// number of bonds made.
std::size_t apply_units(World& world, std::size_t first, std::size_t last, std::uint64_t seed);

}  // namespace orogen
