#include "packing/packing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "analysis/surface.hpp"
#include "util/random.hpp"

namespace orogen {

PackingKind packing_kind_from_name(std::string_view name) {
  if (name == "hexagonal") return PackingKind::Hexagonal;
  if (name == "random_discs") return PackingKind::RandomDiscs;
  if (name == "random_clusters") return PackingKind::RandomClusters;
  throw std::invalid_argument("unknown packing '" + std::string(name) + "'");
}

std::string_view packing_kind_name(PackingKind kind) {
  switch (kind) {
    case PackingKind::Hexagonal: return "hexagonal";
    case PackingKind::RandomDiscs: return "random_discs";
    case PackingKind::RandomClusters: return "random_clusters";
  }
  return "?";
}

Placement placement_from_name(std::string_view name) {
  if (name == "grid") return Placement::Grid;
  if (name == "lattice") return Placement::Lattice;
  if (name == "rain") return Placement::Rain;
  throw std::invalid_argument("unknown placement '" + std::string(name) + "'");
}

std::string_view placement_name(Placement placement) {
  switch (placement) {
    case Placement::Grid: return "grid";
    case Placement::Lattice: return "lattice";
    case Placement::Rain: return "rain";
  }
  return "?";
}

namespace {

// How many times taller than wide a rain's cells are: the particles of one row of the grid
// land spread over that many rows' worth of time, each on the surface the earlier ones built.
constexpr double kRainSpread = 6.0;

// The slots the random particles start in, row by row from the floor up: slot k's centre.
// Grid: square cells of side `cell`. Lattice: a triangular lattice of spacing `cell` (every
// other row shifted by half a cell, rows sqrt(3)/2 cell apart). Rain: the grid's cells
// stretched kRainSpread times upward, the particle at a random height in its cell (drawn here,
// after whatever the caller drew for it).
class Slots {
 public:
  Slots(Placement placement, double length, double cell)
      : placement_(placement), cell_(cell),
        columns_(static_cast<std::size_t>(std::floor((length - (placement == Placement::Lattice ? 0.5 * cell : 0.0)) / cell))) {}

  void centre(std::size_t k, Random& rng, double& x, double& y) const {
    const auto row = static_cast<double>(k / columns_), column = static_cast<double>(k % columns_);
    x = (column + 0.5) * cell_;
    y = (row + 0.5) * cell_;
    if (placement_ == Placement::Lattice) {
      x += (k / columns_) % 2 ? 0.5 * cell_ : 0.0;
      y = (row * std::sqrt(3.0) / 2.0 + 0.5) * cell_;
    } else if (placement_ == Placement::Rain) {
      y = (row * kRainSpread + 0.5) * cell_ + rng.uniform(0.0, (kRainSpread - 1.0) * cell_);
    }
  }

 private:
  Placement placement_;
  double cell_;
  std::size_t columns_;
};

void add_box(World& w, const PackingSpec& s) {
  const double top = 4.0 * s.thickness + 20.0;
  Wall floor{.name = std::string(kBoxFloor), .ax = -1.0, .ay = 0.0, .bx = s.length + 1.0, .by = 0.0,
             .friction = WallFriction::Rough, .mu = s.mu_wall};
  Wall left{.name = std::string(kBoxLeft), .ax = 0.0, .ay = -1.0, .bx = 0.0, .by = top};
  Wall right{.name = std::string(kBoxRight), .ax = s.length, .ay = -1.0, .bx = s.length, .by = top};
  std::vector<Wall> walls = w.walls();
  walls.insert(walls.end(), {floor, left, right});
  w.set_walls(std::move(walls));
}

// Regular hexagonal rows of unit discs, touching without overlap.
void place_hexagonal(World& w, const PackingSpec& s) {
  const double d = s.d_max, r = 0.5 * d;
  const double row_height = d * std::sqrt(3.0) / 2.0;
  const int rows = static_cast<int>(std::ceil((s.thickness * s.overfill - d) / row_height)) + 1;
  for (int row = 0; row < rows; ++row) {
    const double shift = (row % 2) ? r : 0.0;
    for (double x = r + shift; x + r <= s.length; x += d) w.add_disc(x, r + row * row_height, r);
  }
}

// Random discs, one per grid cell of side d_max (no overlap), enough to fill the target.
void place_random_discs(World& w, const PackingSpec& s, Random& rng) {
  const double d_mean = 0.5 * (s.d_min + s.d_max);
  const double disc_area = std::numbers::pi * d_mean * d_mean / 4.0;
  constexpr double kSolidFraction = 0.82;  // of a settled random polydisperse 2-D packing
  const auto count = static_cast<std::size_t>(s.length * s.thickness * s.overfill * kSolidFraction / disc_area);
  // Grid and rain: cells wider than a disc, with random offsets, so that discs do not fall in
  // stacked columns (which settle into a loose, column-jammed packing). Lattice: the lattice
  // points themselves, d_max apart.
  const bool lattice = s.placement == Placement::Lattice;
  const double cell = lattice ? s.d_max : s.d_max * 1.25;
  const Slots slots(s.placement, s.length, cell);
  for (std::size_t k = 0; k < count; ++k) {
    const double r = 0.5 * rng.uniform(s.d_min, s.d_max);
    const double play = lattice ? 0.0 : 0.5 * cell - r;
    double x, y;
    slots.centre(k, rng, x, y);
    x += rng.uniform(-play, play);
    y += rng.uniform(-play, play);
    w.add_disc(x, y, r);
  }
}

// Random rigid clusters of three discs touching pairwise, randomly oriented, one per cell.
void place_random_clusters(World& w, const PackingSpec& s, Random& rng) {
  const double d_mean = 0.5 * (s.d_min + s.d_max);
  const double cluster_area = 3.0 * std::numbers::pi * d_mean * d_mean / 4.0;
  constexpr double kSolidFraction = 0.80;
  const auto count = static_cast<std::size_t>(s.length * s.thickness * s.overfill * kSolidFraction / cluster_area);
  const Slots slots(s.placement, s.length, 2.3 * s.d_max);  // a cluster fits in a circle of radius < 1.1 d_max
  for (std::size_t k = 0; k < count; ++k) {
    const double r1 = 0.5 * rng.uniform(s.d_min, s.d_max);
    const double r2 = 0.5 * rng.uniform(s.d_min, s.d_max);
    const double r3 = 0.5 * rng.uniform(s.d_min, s.d_max);
    // Disc 1 at the origin, disc 2 on +x touching it, disc 3 touching both (law of cosines).
    const double a = r1 + r2, b = r1 + r3, c = r2 + r3;
    const double cos1 = (a * a + b * b - c * c) / (2 * a * b);
    const double px[3] = {0.0, a, b * cos1};
    const double py[3] = {0.0, 0.0, b * std::sqrt(std::max(0.0, 1 - cos1 * cos1))};
    const double m[3] = {r1 * r1, r2 * r2, r3 * r3};
    const double msum = m[0] + m[1] + m[2];
    const double gx = (m[0] * px[0] + m[1] * px[1] + m[2] * px[2]) / msum;
    const double gy = (m[0] * py[0] + m[1] * py[1] + m[2] * py[2]) / msum;
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double cs = std::cos(angle), sn = std::sin(angle);
    double cx, cy;
    slots.centre(k, rng, cx, cy);
    const double radii[3] = {r1, r2, r3};
    std::size_t idx[3];
    for (int q = 0; q < 3; ++q) {
      const double ux = px[q] - gx, uy = py[q] - gy;
      idx[q] = w.add_disc(cx + cs * ux - sn * uy, cy + sn * ux + cs * uy, radii[q]);
    }
    w.add_cluster(idx);
  }
}

}  // namespace

void place_packing(World& w, const PackingSpec& s) {
  if (!(s.d_min > 0 && s.d_min <= s.d_max)) throw std::invalid_argument("need 0 < d_min <= d_max");
  // The grids below need one cell across the box (2.3 d_max for clusters) and a finite count;
  // the configuration checks this with key names first (layer.length >= 3, the particle limit).
  if (!(s.length >= 2.3 * s.d_max && s.thickness > 0 && s.length * s.thickness <= 1e12))
    throw std::invalid_argument("a packing needs length >= 2.3 d_max and a finite, positive area");
  add_box(w, s);
  Random rng(s.seed);
  switch (s.kind) {
    case PackingKind::Hexagonal: place_hexagonal(w, s); break;
    case PackingKind::RandomDiscs: place_random_discs(w, s, rng); break;
    case PackingKind::RandomClusters: place_random_clusters(w, s, rng); break;
  }
}

std::size_t trim_to_thickness(World& w, double thickness) {
  return w.remove_above(thickness - mean_radius(w.discs()), RemovalReason::Other);
}

void record_initial_state(World& w, double x_lo, double x_hi, double column_width) {
  const Surface s = measure_surface(w.discs(), x_lo, x_hi, column_width);
  const auto& d = w.discs();
  for (std::size_t i = 0; i < d.size(); ++i) {
    w.set_start_position(i, d.x[i], d.y[i]);
    const double top = s.at(d.x[i]);
    w.set_initial_depth(i, std::isfinite(top) ? std::max(0.0, top - d.y[i]) : 0.0);
  }
}

}  // namespace orogen
