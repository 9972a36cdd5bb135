#pragma once
// A settled slab tile: the particles of a packing, relative to the tile's lower-left corner,
// stamped side by side to build a long layer and to feed new material into a run (thesis 4.2:
// new incoming slab comes from repeating a settled tile, so a run is not limited by the
// length of its initial packing).
#include <cstdint>
#include <filesystem>
#include <limits>
#include <vector>

#include "io/binary_archive.hpp"
#include "world/world.hpp"

namespace orogen {

struct Tile {
  double length = 0, thickness = 0;
  std::vector<double> x, y, radius, theta, depth0;
  std::vector<std::int32_t> group;  // tile-local cluster number, -1 for a free disc
  std::size_t size() const { return x.size(); }
};

// The settled particles of a world (a finished packing) as a tile of the given length.
Tile tile_from_world(const World& world, double length, double thickness);

// Reads packing.h5 (written by a packing run) as a tile.
Tile load_tile(const std::filesystem::path& packing_file);

// The part of a tile between x_lo and x_lo + length (free discs by centre, clusters by the
// mean of their discs), shifted to start at 0. Cutting a tile out of the interior of a wider
// packing avoids the loose layer that a smooth side wall leaves at each edge, which would make
// every seam between stamped copies a weak zone.
Tile cut_tile(const Tile& whole, double x_lo, double length);

// Stamps a copy of the tile with its lower-left corner at (x, 0), each particle lifted by the
// base's height under it: new discs and clusters with fresh ids, at rest, with x0/y0 at their new positions and depth0 from the tile. Copies sit
// exactly one tile length apart; where a new disc would overlap an existing one across a seam,
// its particle (whole cluster) is left out, and so is one that would reach past x_max (a wall
// there would otherwise blast it away at the first step). Returns the index range
// [first, last) of the new discs.
std::pair<std::size_t, std::size_t> stamp_tile(World& world, const Tile& tile, double x,
                                               double x_max = std::numeric_limits<double>::infinity(),
                                               const BaseHeight& base = {});

void save_tile(ArchiveWriter& out, const Tile& tile);
Tile read_tile(const ArchiveReader& in);

}  // namespace orogen
