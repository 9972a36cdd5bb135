#pragma once
// Packings (MODEL §10, thesis 3.2, Fig 3.3): regular hexagonal, random single discs and
// random rigid 3-disc clusters, placed without overlap in a box (on a grid, a lattice or as a
// rain) and then settled under gravity (experiments/packing_experiment.hpp).
#include <cstdint>
#include <string_view>

#include "world/world.hpp"

namespace orogen {

enum class PackingKind { Hexagonal, RandomDiscs, RandomClusters };

PackingKind packing_kind_from_name(std::string_view name);
std::string_view packing_kind_name(PackingKind kind);

// Where the random particles start (particles.placement): one per square cell with random
// offsets; on a triangular lattice; or a dilute rain (the grid stretched upward).
enum class Placement { Grid, Lattice, Rain };

Placement placement_from_name(std::string_view name);
std::string_view placement_name(Placement placement);

struct PackingSpec {
  PackingKind kind = PackingKind::RandomDiscs;
  Placement placement = Placement::Grid;
  double length = 100;     // box width (d)
  double thickness = 10;   // target settled layer thickness h0 (d)
  double d_min = 0.7, d_max = 1.0;
  std::uint64_t seed = 1;
  double mu_wall = 0.3;    // friction of the rough floor
  double overfill = 1.06;  // material placed relative to the target, trimmed after settling
};

// Names of the walls of the box that place_packing adds (World::wall and the other wall methods).
inline constexpr std::string_view kBoxFloor = "floor", kBoxLeft = "left", kBoxRight = "right";

// Adds the box (rough floor at y = 0, smooth side walls at x = 0 and x = length) and places
// the particles above the floor without overlap. Enough material is placed to settle to
// slightly more than the target thickness.
void place_packing(World& world, const PackingSpec& spec);

// Removes every particle (a whole cluster, by its mean elevation) whose centre lies above
// the target thickness less a mean radius, so that the layer's top is near `thickness`.
std::size_t trim_to_thickness(World& world, double thickness);

// Records each disc's settled position and its depth below the settled surface (x0, y0,
// depth0), using surface columns of width column_width.
void record_initial_state(World& world, double x_lo, double x_hi, double column_width);

}  // namespace orogen
