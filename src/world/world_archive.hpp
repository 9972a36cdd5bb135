#pragma once
// Saves and restores the whole dynamic state of a World (particles, walls, neighbour list
// with contact history, clock) so that a resumed run continues bit for bit.
#include "io/binary_archive.hpp"
#include "world/world.hpp"

namespace orogen {

void save_world(ArchiveWriter& out, World& world);
void load_world(const ArchiveReader& in, World& world);

}  // namespace orogen
