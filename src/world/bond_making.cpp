// World::make_bonds: the bonds a world's bonding materials make (docs/materials.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "util/random.hpp"
#include "world/world.hpp"

namespace orogen {
namespace {

// The bond two materials make, or none (both must bond): the weaker of each property, so that
// a bond across a boundary is never stronger than either side's own.
struct PairBond {
  bool bonds = false;
  BondProperties p;
};

PairBond pair_bond(const Material& m1, const Material& m2) {
  if (!m1.bond.bonds() || !m2.bond.bonds()) return {};
  const BondProperties &a = m1.bond, &b = m2.bond;
  return {true,
          {.tensile_strength = std::min(a.tensile_strength, b.tensile_strength),
           .shear_strength = std::min(a.shear_strength, b.shear_strength),
           .stiffness = std::min(a.stiffness, b.stiffness),
           .radius_factor = std::min(a.radius_factor, b.radius_factor),
           .strength_scatter = std::max(a.strength_scatter, b.strength_scatter),
           .gap = std::min(a.gap, b.gap)}};
}

// A standard normal number from the generator (Box-Muller: the same on every platform, as
// Random's uniforms are).
double standard_normal(Random& rng) {
  const double u1 = 1.0 - rng.uniform();  // in (0, 1]
  const double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// The generator of one bond: from the run's seed and the two ids alone.
std::uint64_t bond_seed(std::uint64_t seed, std::int64_t id_a, std::int64_t id_b) {
  std::uint64_t h = seed ^ 0x9e3779b97f4a7c15ULL;
  for (std::uint64_t v : {static_cast<std::uint64_t>(id_a), static_cast<std::uint64_t>(id_b)}) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ULL;
  }
  return h;
}

}  // namespace

std::size_t World::make_bonds(std::size_t first, std::size_t last, std::uint64_t seed) {
  if (!discs_.has_materials || !materials_.any_bonds() || first >= last) return 0;
  double r_max = 0, gap_max = 0;
  for (std::size_t i = 0; i < discs_.size(); ++i) r_max = std::max(r_max, discs_.radius[i]);
  for (const auto& m : materials_.list) gap_max = std::max(gap_max, m.bond.gap);
  // Cells as wide as the farthest a bonding pair can be apart: each pair is in neighbouring cells.
  const double cell = 2 * r_max + gap_max;
  // A cell's key: its two indices packed in unsigned arithmetic (no shift of a negative number).
  auto cell_key = [](std::int64_t gx, std::int64_t gy) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(gx) << 32) ^ (static_cast<std::uint64_t>(gy) & 0xffffffffULL));
  };
  auto key = [&](double x, double y) {
    return cell_key(static_cast<std::int64_t>(std::floor(x / cell)), static_cast<std::int64_t>(std::floor(y / cell)));
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < discs_.size(); ++i)
    if (materials_.list[discs_.material[i]].bond.bonds()) grid[key(discs_.x[i], discs_.y[i])].push_back(i);
  const double ks_ratio = law_.kn > 0 ? law_.ks / law_.kn : 0.0;
  // The pairs bonded already (a disc of an earlier call beside the new ones).
  std::unordered_set<std::uint64_t> bonded;
  auto pair_key = [](std::int64_t a, std::int64_t b) {
    return static_cast<std::uint64_t>(a) * 0x9e3779b97f4a7c15ULL ^ static_cast<std::uint64_t>(b);
  };
  for (std::size_t k = 0; k < bonds_.size(); ++k) bonded.insert(pair_key(bonds_.id_a[k], bonds_.id_b[k]));
  std::size_t made = 0;
  for (std::size_t i = first; i < last; ++i) {
    const Material& mi = materials_.list[discs_.material[i]];
    if (!mi.bond.bonds()) continue;
    const auto cx = static_cast<std::int64_t>(std::floor(discs_.x[i] / cell));
    const auto cy = static_cast<std::int64_t>(std::floor(discs_.y[i] / cell));
    // The candidates in index order, so that the bonds are made in the same order every time.
    std::vector<std::size_t> near;
    for (std::int64_t gx = cx - 1; gx <= cx + 1; ++gx)
      for (std::int64_t gy = cy - 1; gy <= cy + 1; ++gy)
        if (auto it = grid.find(cell_key(gx, gy)); it != grid.end())
          near.insert(near.end(), it->second.begin(), it->second.end());
    std::sort(near.begin(), near.end());
    for (const std::size_t j : near) {
      if (j == i || (j >= first && j < last && j < i)) continue;  // a pair of new discs once
      if (discs_.cluster[i] >= 0 && discs_.cluster[i] == discs_.cluster[j]) continue;  // one body
      const PairBond pb = pair_bond(mi, materials_.list[discs_.material[j]]);
      if (!pb.bonds) continue;
      const double gap = std::hypot(discs_.x[j] - discs_.x[i], discs_.y[j] - discs_.y[i]) - discs_.radius[i] - discs_.radius[j];
      if (gap > pb.p.gap) continue;
      const std::size_t a = discs_.id[i] < discs_.id[j] ? i : j, b = a == i ? j : i;
      if (!bonded.empty() && bonded.contains(pair_key(discs_.id[a], discs_.id[b]))) {
        // The key may collide: a collision is a pair bonded already only if the ids match.
        bool same = false;
        for (std::size_t k = 0; k < bonds_.size() && !same; ++k)
          same = bonds_.id_a[k] == discs_.id[a] && bonds_.id_b[k] == discs_.id[b];
        if (same) continue;
      }
      Random rng(bond_seed(seed, discs_.id[a], discs_.id[b]));
      auto scattered = [&](double mean) {
        return std::max(0.0, mean * (1.0 + pb.p.strength_scatter * standard_normal(rng)));
      };
      const double kn_bond = pb.p.stiffness * law_.kn;  // per unit area: contact.kn / d^2, d = 1
      add_bond(bonds_, discs_.id[a], discs_.id[b], static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b),
               {.kn = kn_bond, .ks = kn_bond * ks_ratio,
                .radius = pb.p.radius_factor * std::min(discs_.radius[i], discs_.radius[j]),
                .tensile = scattered(pb.p.tensile_strength), .shear = scattered(pb.p.shear_strength)});
      ++made;
    }
  }
  // New bonds are acting or not and out of order: the next step sorts them (prepare_bond_scratch),
  // whether or not the list is rebuilt first (the biaxial test bonds without adding discs).
  if (made > 0) bond_scratch_.activity_build = ~std::uint64_t{0};
  return made;
}

}  // namespace orogen
