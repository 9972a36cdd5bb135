// Exhumation analysis on synthetic data with known answers (docs/exhumation.md): closure-depth
// ages and resets, depths below the local surface, cumulative erosion, removals, jumps and
// the flux steady-state rule.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "exhumation/closure_ages.hpp"
#include "exhumation/exhumation_tracker.hpp"
#include "exhumation/flux_balance.hpp"

using namespace orogen;

namespace {

// h0 = 1, columns of width 1 from x = 0: column c holds x in [c, c+1).
ExhumationParams grid(std::size_t columns, std::vector<double> closure) {
  ExhumationParams p;
  p.h0 = 1;
  p.closure = std::move(closure);
  p.x_lo = 0;
  p.column_width = 1;
  p.n_columns = columns;
  p.mean_radius = 0.1;
  return p;
}

struct Disc {
  std::int64_t id;
  double x, y, r;
};

OutputDiscs output(std::int64_t step, double time, const std::vector<Disc>& discs) {
  OutputDiscs o;
  o.step = step;
  o.time = time;
  for (const auto& d : discs) {
    o.id.push_back(d.id);
    o.x.push_back(d.x);
    o.y.push_back(d.y);
    o.radius.push_back(d.r);
  }
  return o;
}

}  // namespace

TEST(ClosureAges, ResetWhileDeeperAgeWhileShallowerResetTwice) {
  const std::vector<double> h = {0.3};
  ClosureAges a(1);
  const double t[] = {2, 3, 5, 8, 9, 12};
  const double depth[] = {0.1, 0.4, 0.2, 0.05, 0.6, 0.1};
  const double age[] = {0, 0, 2, 5, 0, 3};         // since the last output deeper than 0.3
  const bool unreset[] = {true, false, false, false, false, false};
  const unsigned dips[] = {0, 1, 1, 1, 2, 2};
  const double max_depth[] = {0.1, 0.4, 0.4, 0.4, 0.6, 0.6};
  for (int k = 0; k < 6; ++k) {
    a.observe(t[k], depth[k], h);
    EXPECT_EQ(a.age(0), age[k]) << k;
    EXPECT_EQ(a.unreset(0), unreset[k]) << k;
    EXPECT_EQ(a.dips(0), dips[k]) << k;
    EXPECT_EQ(a.max_depth(), max_depth[k]) << k;
    EXPECT_EQ(a.depth(), depth[k]) << k;
  }
}

TEST(ClosureAges, UnresetParticleAgesFromItsFirstOutput) {
  const std::vector<double> h = {0.5, 0.9};
  ClosureAges a(2);
  a.observe(10, 0.6, h);  // deeper than 0.5 only
  a.observe(14, 0.2, h);
  EXPECT_EQ(a.age(0), 4);
  EXPECT_FALSE(a.unreset(0));
  EXPECT_EQ(a.age(1), 4);  // never below 0.9: ages from its first output, flagged
  EXPECT_TRUE(a.unreset(1));
  a.observe(15, std::nan(""), h);  // no surface above it: only the clock moves
  EXPECT_EQ(a.age(0), 5);
  EXPECT_EQ(a.max_depth(), 0.6);
}

TEST(ExhumationTracker, DepthsBelowTheLocalSurfaceAndSurfaceValues) {
  ExhumationTracker tr(grid(2, {0.5}));
  // Column 0: a stack, top at 3.1 + 0.1 = 3.2; column 1: one disc, top 1.2.
  const auto r = tr.observe(output(0, 0, {{1, 0.5, 3.1, 0.1}, {2, 0.5, 2.0, 0.1}, {3, 0.4, 2.9, 0.1}, {4, 1.5, 1.0, 0.2}}), {});
  EXPECT_DOUBLE_EQ(r.elevation[0], 3.2);
  EXPECT_DOUBLE_EQ(r.elevation[1], 1.2);
  EXPECT_EQ(r.top_id[0], 1);
  EXPECT_EQ(r.top_id[1], 4);
  ASSERT_EQ(r.particle_id.size(), 4u);
  EXPECT_FLOAT_EQ(r.particle_depth[0], 0.1f);  // the top disc: its radius
  EXPECT_FLOAT_EQ(r.particle_depth[1], 1.2f);
  EXPECT_FLOAT_EQ(r.particle_depth[2], 0.3f);
  EXPECT_FLOAT_EQ(r.particle_depth[3], 0.2f);
  // Disc 2 is deeper than 0.5: reset; the others are un-reset.
  EXPECT_EQ(tr.ages_of(2)->dips(0), 1u);
  EXPECT_TRUE(tr.ages_of(1)->unreset(0));
  EXPECT_EQ(r.surface_unreset[0], 1);
}

TEST(ExhumationTracker, ErodedParticleLeavesTheColumnAtItsStepWithItsValues) {
  ExhumationTracker tr(grid(2, {0.5}));
  // Disc 2 below disc 1 (depth 1.0 at output 0); disc 1 is eroded at step 150.
  tr.observe(output(0, 0, {{1, 0.5, 3.0, 0.25}, {2, 0.5, 2.25, 0.25}}), {});
  const std::vector<ErosionEvent> none;
  const auto r1 = tr.observe(output(100, 10, {{1, 0.5, 3.0, 0.25}, {2, 0.5, 2.25, 0.25}}), none);
  EXPECT_EQ(r1.cum_eroded_count[0], 0);
  const std::vector<ErosionEvent> ev = {{.step = 150, .time = 15, .id = 1, .x = 0.5, .y = 3.0}};
  const auto r2 = tr.observe(output(200, 20, {{2, 0.5, 2.25, 0.25}}), ev);
  EXPECT_EQ(r2.cum_eroded_count[0], 1);
  EXPECT_EQ(r2.cum_eroded_count[1], 0);
  EXPECT_DOUBLE_EQ(r2.cum_eroded_area[0], std::numbers::pi * 0.0625);
  EXPECT_EQ(r2.eroded_count, 1);
  EXPECT_EQ(r2.top_id[0], 2);  // the disc below is now the surface
  EXPECT_DOUBLE_EQ(r2.elevation[0], 2.5);
  ASSERT_EQ(tr.eroded().size(), 1u);
  const auto& e = tr.eroded()[0];
  EXPECT_EQ(e.event.id, 1);
  EXPECT_EQ(e.last_output, 1);
  EXPECT_EQ(e.column, 0);
  EXPECT_DOUBLE_EQ(e.depth, 0.25);
  EXPECT_DOUBLE_EQ(e.age[0], 10);  // un-reset, seen from t = 0 to t = 10
  EXPECT_EQ(e.unreset[0], 1);
  EXPECT_EQ(tr.ages_of(1), nullptr);
  // Disc 2 was 1.0 deep at output 1 (reset there) and is now the surface: age 20 - 10.
  EXPECT_DOUBLE_EQ(r2.surface_age[0], 10);
  EXPECT_DOUBLE_EQ(r2.top_max_depth[0], 1.0);
}

TEST(ExhumationTracker, JumpsCountTheFallsOfSurfaceAge) {
  ExhumationTracker tr(grid(1, {0.5}));
  // The surface disc 1 ages (un-reset) from t = 0; disc 2 sits deep below it (reset each
  // output) until disc 1 is eroded; the surface then gets younger: one jump.
  const std::vector<ErosionEvent> none;
  tr.observe(output(0, 0, {{1, 0.5, 3.0, 0.25}, {2, 0.5, 1.0, 0.25}}), none);
  auto r = tr.observe(output(1, 4, {{1, 0.5, 3.0, 0.25}, {2, 0.5, 1.0, 0.25}}), none);
  EXPECT_DOUBLE_EQ(r.surface_age[0], 4);
  EXPECT_EQ(r.jump_count[0], 0);
  const std::vector<ErosionEvent> ev = {{.step = 2, .time = 5, .id = 1, .x = 0.5, .y = 3.0}};
  r = tr.observe(output(3, 6, {{2, 0.5, 1.0, 0.25}}), ev);
  EXPECT_DOUBLE_EQ(r.surface_age[0], 2);  // disc 2 was last deep at t = 4
  EXPECT_EQ(r.jump_count[0], 1);
  EXPECT_DOUBLE_EQ(r.jump_total[0], 2);
  r = tr.observe(output(4, 7, {{2, 0.5, 1.0, 0.25}}), none);  // ageing is no jump
  EXPECT_EQ(r.jump_count[0], 1);
  EXPECT_DOUBLE_EQ(r.surface_age[0], 3);
}

TEST(ExhumationTracker, ParticleStrideKeepsEveryNthId) {
  ExhumationParams p = grid(1, {0.5});
  p.particle_stride = 2;
  ExhumationTracker tr(p);
  const auto r = tr.observe(output(0, 0, {{1, 0.5, 1, 0.2}, {2, 0.5, 2, 0.2}, {4, 0.5, 3, 0.2}}), {});
  EXPECT_EQ(r.particle_id, (std::vector<std::int64_t>{2, 4}));
  EXPECT_EQ(r.particle_age.size(), 2u);
}

TEST(FluxBalance, SteadyStateRuleFindsTheKnownStep) {
  // Nothing eroded until output 20, then exactly the incoming flux: averaged over 5
  // intervals the ratio is 0.2, 0.4, ... and first reaches 0.9 (1.0) at output 24.
  const double flux_in = 2.5, dt = 4;
  std::vector<double> t, area;
  for (int k = 0; k < 40; ++k) {
    t.push_back(k * dt);
    area.push_back(k >= 20 ? flux_in * dt : 0.0);
  }
  const FluxBalance f = flux_balance(t, area, flux_in, 5, 0.9);
  EXPECT_EQ(f.steady_output, 24);
  EXPECT_DOUBLE_EQ(f.ratio[23], 0.8);
  EXPECT_DOUBLE_EQ(f.ratio[24], 1.0);
  EXPECT_DOUBLE_EQ(f.flux_out[30], flux_in);
  EXPECT_TRUE(std::isnan(f.flux_out[0]));
  EXPECT_TRUE(std::isnan(f.ratio[4]));  // fewer than 5 intervals
  EXPECT_EQ(flux_balance(t, area, flux_in, 5, 1.1).steady_output, -1);
}

// Deposits (a run with surface.deposition): each column's sediment thickness is its deposits'
// area over the column width, its age their area-weighted mean age; the kept particles carry
// their deposition time (NaN: crust).
TEST(ExhumationTracker, SedimentInEachColumnWithItsAge) {
  ExhumationTracker tracker(grid(3, {0.5}));
  OutputDiscs o = output(10, 100.0, {{1, 0.5, 0.1, 0.1}, {2, 1.5, 0.1, 0.1}, {3, 1.6, 0.3, 0.2}, {4, 2.5, 0.1, 0.1}});
  o.deposition_time = {std::nan(""), 90.0, 60.0, std::nan("")};
  const OutputRecord r = tracker.observe(o, {});
  const double a2 = std::numbers::pi * 0.01, a3 = std::numbers::pi * 0.04;
  EXPECT_DOUBLE_EQ(r.deposit_thickness[0], 0.0);
  EXPECT_DOUBLE_EQ(r.deposit_thickness[1], a2 + a3);
  EXPECT_DOUBLE_EQ(r.deposit_age[1], (a2 * 10 + a3 * 40) / (a2 + a3));
  EXPECT_TRUE(std::isnan(r.deposit_age[2]));
  ASSERT_EQ(r.particle_deposition_time.size(), 4u);
  EXPECT_EQ(r.particle_deposition_time[2], 60.0);
  EXPECT_TRUE(std::isnan(r.particle_deposition_time[0]));
}
