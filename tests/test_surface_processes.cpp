// One surface update on a world of discs (surface/surface_processes.hpp): a tower diffused into
// the plain around it loses its top discs (logged eroded_hillslope) and the plain gets sediment
// discs that overlap nothing when laid; the recycled fill of a basin stops at the base level.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "surface/profile_step.hpp"
#include "surface/surface_processes.hpp"

namespace orogen {
namespace {

// A plain of discs of radius 0.5 on the base from x = 0 to 40, with a tower six discs high
// over x in [15, 25).
World tower_on_a_plain() {
  World w;
  for (int k = 0; k < 40; ++k) {
    const double x = 0.5 + k;
    const int high = (x > 15 && x < 25) ? 7 : 1;
    for (int level = 0; level < high; ++level) w.add_disc(x, 0.5 + level, 0.5);
  }
  return w;
}

TEST(SurfaceProcesses, ADiffusedTowerErodesAndItsFootGetsDepositsThatOverlapNothing) {
  World w = tower_on_a_plain();
  const double area_before = disc_area(w);
  SurfaceSpec spec;
  spec.every = 1;
  spec.column_width = 1.0;
  spec.diffusivity = 2.0;
  spec.deposition = true;
  SurfaceProcesses surface(spec, {0.4, 0.45, 0.5}, 7);
  const std::size_t before = w.discs().size();
  surface.update(w, 0.0, 40.0, 1.0);
  const AreaLedger& l = surface.ledger();
  EXPECT_GT(l.eroded[0], 2.0);
  EXPECT_GT(l.deposited, 2.0);
  EXPECT_NEAR(disc_area(w), area_before - l.eroded_total() + l.deposited, 1e-9);
  for (const auto& r : w.removals()) EXPECT_EQ(r.reason, RemovalReason::ErodedHillslope);
  EXPECT_GT(w.removals().size(), 2u);
  // The deposits: at the tower's foot, touching nothing and above the base.
  const auto& d = w.discs();
  std::size_t laid = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (std::isnan(surface.deposition_time(d.id[i]))) continue;
    ++laid;
    EXPECT_GE(d.y[i], d.radius[i]);
    for (std::size_t j = 0; j < d.size(); ++j) {
      if (j == i) continue;
      EXPECT_GE(std::hypot(d.x[i] - d.x[j], d.y[i] - d.y[j]), d.radius[i] + d.radius[j]) << "deposit " << d.id[i];
    }
  }
  EXPECT_GT(laid, 2u);
  EXPECT_LT(laid, before);
}

TEST(SurfaceLaws, TheRecycledFillFillsTheLowestColumnsToOneLevelAndStopsAtTheBaseLevel) {
  std::vector<double> h = {5, 1, 2, 4, 0};
  // 2 units of area into columns 1-3 (dx 1): 1 lifts column 1 to 2, 1 more lifts 1 and 2 to 2.5.
  EXPECT_EQ(fill_to_level(h, 1, 4, 1.0, 2.0, 10.0), 0.0);
  EXPECT_EQ(h, (std::vector<double>{5, 2.5, 2.5, 4, 0}));
  // A level of 3: room for 0.5 + 0.5 only; the rest does not fit.
  EXPECT_NEAR(fill_to_level(h, 1, 4, 1.0, 5.0, 3.0), 4.0, 1e-12);
  EXPECT_EQ(h, (std::vector<double>{5, 3, 3, 4, 0}));
}

TEST(SurfaceLaws, RecyclingFillsEachSidesShareOfItsNetLossIntoThatSide) {
  // A peak eroded by a river draining to the ends; half of each side's loss comes back as fill
  // below the base level, and recycled plus bypassed is that half exactly.
  std::vector<double> h(41);
  for (std::size_t j = 0; j < h.size(); ++j) h[j] = 20.0 - std::fabs(static_cast<double>(j) - 20.0) * 0.5;
  h[2] = h[38] = 5.0;  // a basin on each side, below the base level
  SurfaceSpec spec;
  spec.erodibility = 0.05;
  spec.recycling = 0.5;
  spec.base_level = 10.0;
  const std::vector<double> start = h;
  const ProfileStep step = advance_profile(h, 1.0, 0.0, spec, 10.0);
  double lowered = 0;
  for (double v : step.lowered[1]) lowered += v;
  EXPECT_GT(lowered, 1.0);
  double net_loss = 0;
  for (std::size_t j = 0; j < h.size(); ++j) net_loss += start[j] - h[j];
  EXPECT_NEAR(step.recycled + step.bypassed, 0.5 * (net_loss + step.recycled), 1e-9);
  EXPECT_GT(h[2], 5.0);
  EXPECT_GT(h[38], 5.0);
  EXPECT_LE(h[2], 10.0);
}

TEST(SurfaceLaws, AnOutsideSupplyFillsTheForelandsItNamesAndWhatFindsNoRoomBypasses) {
  // No law: the supply alone, sediment_supply x dt filled into the sides of the highest column
  // (index 3): pro [0, 3), retro [3, 7). Each side's basin holds 1 (two columns of 1 up to 1.5).
  const std::vector<double> start = {2, 1, 1, 3, 1, 1, 2};
  SurfaceSpec spec;
  spec.base_level = 1.5;
  spec.sediment_supply = 0.5;
  spec.supply_to = SupplySide::Pro;
  std::vector<double> h = start;
  ProfileStep step = advance_profile(h, 1.0, 0.0, spec, 2.0);
  EXPECT_EQ(h, (std::vector<double>{2, 1.5, 1.5, 3, 1, 1, 2}));
  EXPECT_EQ(step.supplied, 1.0);
  EXPECT_EQ(step.supply_bypassed, 0.0);
  EXPECT_EQ(step.recycled + step.bypassed, 0.0);

  spec.supply_to = SupplySide::Both;  // half each: both basins full
  h = start;
  step = advance_profile(h, 1.0, 0.0, spec, 4.0);
  EXPECT_EQ(h, (std::vector<double>{2, 1.5, 1.5, 3, 1.5, 1.5, 2}));
  EXPECT_EQ(step.supplied, 2.0);

  spec.supply_to = SupplySide::Retro;  // three times the room: the rest bypasses
  h = start;
  step = advance_profile(h, 1.0, 0.0, spec, 6.0);
  EXPECT_EQ(h, (std::vector<double>{2, 1, 1, 3, 1.5, 1.5, 2}));
  EXPECT_EQ(step.supplied, 1.0);
  EXPECT_EQ(step.supply_bypassed, 2.0);
}

}  // namespace
}  // namespace orogen
