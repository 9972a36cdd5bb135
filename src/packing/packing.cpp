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

namespace {

void add_box(World& w, const PackingSpec& s) {
  const double top = 4.0 * s.thickness + 20.0;
  Wall floor{.name = std::string(kBoxFloor), .ax = -1.0, .ay = 0.0, .bx = s.length + 1.0, .by = 0.0,
             .friction = WallFriction::Rough, .mu = s.mu_wall};
  Wall left{.name = std::string(kBoxLeft), .ax = 0.0, .ay = -1.0, .bx = 0.0, .by = top};
  Wall right{.name = std::string(kBoxRight), .ax = s.length, .ay = -1.0, .bx = s.length, .by = top};
  std::vector<Wall> walls = w.walls;
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
  // Cells wider than a disc, with random offsets, so that discs do not fall in stacked
  // columns (which settle into a loose, column-jammed packing).
  const double cell = s.d_max * 1.25;
  const auto columns = static_cast<std::size_t>(std::floor(s.length / cell));
  for (std::size_t k = 0; k < count; ++k) {
    const double r = 0.5 * rng.uniform(s.d_min, s.d_max);
    const double play = 0.5 * cell - r;
    const double x = (static_cast<double>(k % columns) + 0.5) * cell + rng.uniform(-play, play);
    const double y = (static_cast<double>(k / columns) + 0.5) * cell + rng.uniform(-play, play);
    w.add_disc(x, y, r);
  }
}

// Random rigid clusters of three discs touching pairwise, randomly oriented, one per cell.
void place_random_clusters(World& w, const PackingSpec& s, Random& rng) {
  const double d_mean = 0.5 * (s.d_min + s.d_max);
  const double cluster_area = 3.0 * std::numbers::pi * d_mean * d_mean / 4.0;
  constexpr double kSolidFraction = 0.80;
  const auto count = static_cast<std::size_t>(s.length * s.thickness * s.overfill * kSolidFraction / cluster_area);
  const double cell = 2.3 * s.d_max;  // a cluster fits in a circle of radius < 1.1 d_max
  const auto columns = static_cast<std::size_t>(std::floor(s.length / cell));
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
    const double cx = (static_cast<double>(k % columns) + 0.5) * cell;
    const double cy = (static_cast<double>(k / columns) + 0.5) * cell;
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
  return w.remove_above(thickness - mean_radius(w.discs), RemovalReason::Other);
}

void record_initial_state(World& w, double x_lo, double x_hi, double column_width) {
  const Surface s = measure_surface(w.discs, x_lo, x_hi, column_width);
  auto& d = w.discs;
  for (std::size_t i = 0; i < d.size(); ++i) {
    d.x0[i] = d.x[i];
    d.y0[i] = d.y[i];
    const double top = s.at(d.x[i]);
    d.depth0[i] = std::isfinite(top) ? std::max(0.0, top - d.y[i]) : 0.0;
  }
}

}  // namespace orogen
