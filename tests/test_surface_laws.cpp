// The surface laws of issue 40 (src/surface/profile_laws.*) against their analytic solutions:
// a diffusing step is the error function, the nonlinear law is the linear one on gentle slopes
// and holds a steady hillslope under uplift at Roering's flux, a stream-power river under
// uniform uplift reaches the steady profile U = K Q^m S^n, and mass is conserved to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "surface/erosion_carry.hpp"
#include "surface/profile_laws.hpp"

namespace orogen {
namespace {

double total(const std::vector<double>& h) { return std::accumulate(h.begin(), h.end(), 0.0); }

std::vector<double> step_profile(std::size_t n, double dx, double amplitude) {
  std::vector<double> h(n);
  for (std::size_t j = 0; j < n; ++j) h[j] = (-50 + (static_cast<double>(j) + 0.5) * dx) < 0 ? amplitude : 0.0;
  return h;
}

TEST(SurfaceLaws, ALinearlyDiffusingStepIsTheErrorFunctionAndKeepsItsArea) {
  const double dx = 0.5, kappa = 1, dt = 0.02, t = 25;
  std::vector<double> h = step_profile(200, dx, 1.0);
  const double area = total(h);
  for (int k = 0; k < static_cast<int>(t / dt); ++k) diffuse_linear(h, dx, kappa, dt, {});
  double worst = 0;
  for (std::size_t j = 0; j < h.size(); ++j) {
    const double x = -50 + (static_cast<double>(j) + 0.5) * dx;
    worst = std::max(worst, std::fabs(h[j] - 0.5 * std::erfc(x / (2 * std::sqrt(kappa * t)))));
  }
  EXPECT_LT(worst, 5e-3);  // backward Euler, O(dt) + O(dx^2)
  EXPECT_NEAR(total(h), area, 1e-12 * area);
}

TEST(SurfaceLaws, NonlinearDiffusionIsLinearOnGentleSlopes) {
  const double dx = 0.5, kappa = 1, dt = 0.5, t = 25;
  std::vector<double> lin = step_profile(200, dx, 0.01), non = lin;
  const double area = total(non);
  for (int k = 0; k < static_cast<int>(t / dt); ++k) {
    diffuse_linear(lin, dx, kappa, dt, {});
    diffuse_nonlinear(non, dx, kappa, 1.0, dt, {});
  }
  double worst = 0;
  for (std::size_t j = 0; j < lin.size(); ++j) worst = std::max(worst, std::fabs(lin[j] - non[j]));
  EXPECT_LT(worst, 2e-4);  // 2 % of the step: the two time schemes apart
  EXPECT_NEAR(total(non), area, 1e-12 * area);
}

// Under uplift U, a hillslope draining to base level at both ends stands steady when each face
// carries the uplift of the columns above it: q = U x, and Roering's law then sets its slope,
// S = (sqrt(kappa^2 + 4 (q / Sc)^2) - kappa) / (2 q / Sc^2). Slopes up to half of Sc: the law's
// nonlinear range.
TEST(SurfaceLaws, ANonlinearHillslopeUnderUpliftStandsAtRoeringsSlope) {
  // Small steps: the uplift is added between them (operator splitting), which the open ends feel.
  const double dx = 1, kappa = 1, sc = 0.6, uplift = 0.4 / 19, dt = 0.05;
  const std::size_t n = 40;
  std::vector<double> h(n, 0.0);
  const ProfileEnds open{true, 0.0};
  for (int k = 0; k < 200000; ++k) {
    for (double& v : h) v += uplift * dt;
    diffuse_nonlinear(h, dx, kappa, sc, dt, open);
  }
  // The divide lies between columns n/2 - 1 and n/2; face k (between columns k - 1 and k) of the
  // left half drains the n/2 - k columns between it and the divide.
  for (std::size_t k = 1; k < n / 2; k += 3) {
    const double q = uplift * dx * static_cast<double>(n / 2 - k);
    const double s = (std::sqrt(kappa * kappa + 4 * q * q / (sc * sc)) - kappa) / (2 * q / (sc * sc));
    const double measured = (h[k] - h[k - 1]) / dx;
    EXPECT_NEAR(measured, s, 3e-3 * s) << "face " << k;
  }
}

struct River {
  std::vector<double> h, discharge;
};

River steady_river(const StreamPower& law, double uplift, const std::vector<double>& rain, double dx) {
  River r{std::vector<double>(rain.size(), 0.0), {}};
  const ProfileEnds open{true, 0.0};
  for (int k = 0; k < 200000; ++k) {
    const std::vector<double> before = r.h;
    for (double& v : r.h) v += uplift * 50.0;
    r.discharge = erode_fluvial(r.h, dx, law, rain, 50.0, open);
    double change = 0;
    for (std::size_t j = 0; j < r.h.size(); ++j) change = std::max(change, std::fabs(r.h[j] - before[j]));
    if (change < 1e-13) break;
  }
  return r;
}

// The receiver of column j at steady state: its lower neighbour, or the base level (0) beyond the end.
double drop_to_receiver(const std::vector<double>& h, std::size_t j) {
  const double left = j > 0 ? h[j - 1] : 0.0, right = j + 1 < h.size() ? h[j + 1] : 0.0;
  return h[j] - std::min(left, right);
}

TEST(SurfaceLaws, AStreamPowerRiverUnderUpliftReachesTheSteadyProfile) {
  const double dx = 1, uplift = 1e-3;
  const std::size_t n = 41;
  const std::vector<double> rain(n, 1.0);
  for (const double slope_exponent : {1.0, 2.0}) {
    SCOPED_TRACE(slope_exponent);
    const StreamPower law{0.01, 0.5, slope_exponent};
    const River r = steady_river(law, uplift, rain, dx);
    const auto divide = static_cast<std::size_t>(std::max_element(r.h.begin(), r.h.end()) - r.h.begin());
    EXPECT_NEAR(static_cast<double>(divide), static_cast<double>(n / 2), 1.0);
    // The divide drains to its lower neighbour (of two equal drops, the left one's).
    const bool divide_drains_left = r.h[divide - 1] <= r.h[divide + 1];
    for (std::size_t j = 0; j < n; ++j) {
      if (j == divide) continue;
      // Discharge: the columns from the divide down to this one, the divide's on its side.
      const double columns = static_cast<double>(j < divide ? divide - j + (divide_drains_left ? 1 : 0)
                                                            : j - divide + (divide_drains_left ? 0 : 1));
      EXPECT_DOUBLE_EQ(r.discharge[j], columns * dx) << j;
      const double slope = drop_to_receiver(r.h, j) / dx;
      EXPECT_NEAR(law.K * std::pow(r.discharge[j], law.m) * std::pow(slope, law.n), uplift, 1e-9) << j;
    }
  }
}

TEST(SurfaceLaws, OrographicRainMakesTheWindwardFlankGentler) {
  const double dx = 1, uplift = 1e-3;
  const std::size_t n = 41;
  std::vector<double> flat(n, 0.0);
  flat[n / 2] = 1;
  const std::vector<double> rain = precipitation_pattern(flat, 1.0, 4.0, true);
  EXPECT_EQ(rain.front(), 4.0);
  EXPECT_EQ(rain.back(), 1.0);
  const StreamPower law{0.01, 0.5, 1.0};
  const River r = steady_river(law, uplift, rain, dx);
  // Each column carries the uplift at its own discharge, U = K Q^m S: four times the rain on the
  // windward flank, gentler slopes there (the divide moves to the leeward side).
  const auto divide = static_cast<std::size_t>(std::max_element(r.h.begin(), r.h.end()) - r.h.begin());
  EXPECT_GT(divide, n / 2);
  double windward = 0, leeward = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (j == divide) continue;
    const double slope = drop_to_receiver(r.h, j) / dx;
    EXPECT_NEAR(law.K * std::sqrt(r.discharge[j]) * slope, uplift, 1e-9) << j;
    (j < divide ? windward : leeward) += slope / static_cast<double>(j < divide ? divide : n - 1 - divide);
  }
  EXPECT_LT(windward, 0.8 * leeward);
}

TEST(SurfaceLaws, TheImplicitRiverNeverCutsBelowItsReceiver) {
  std::vector<double> h = {0.5, 3.0, 7.0, 2.0, 0.2};
  const ProfileEnds open{true, 0.0};
  erode_fluvial(h, 1.0, {1.0, 0.5, 1.0}, std::vector<double>(h.size(), 1.0), 1e6, open);
  for (double v : h) {
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 1e-3);  // an enormous step: everything down to base level
  }
}

// A pit holds water up to the rim it spills over, and the sea stands at the base level: a river
// cuts down to the water's surface, never to a pit's floor or below the base level, the columns
// under water keep their height, and all the rain leaves by the outlets. (Cut to pit floors,
// a rough granular surface was lowered pit by pit to the model's base.)
TEST(SurfaceLaws, ARiverCutsDownToTheWaterInAPitNotToItsFloor) {
  //                      0    1    2    3    4    5    6    7
  std::vector<double> h = {1.0, 0.3, 2.0, 4.0, 2.5, 0.5, 1.5, 0.8};
  const std::vector<double> start = h;
  const ProfileEnds open{true, 0.9};
  const std::vector<double> q = erode_fluvial(h, 1.0, {1.0, 0.5, 1.0}, std::vector<double>(h.size(), 1.0), 1e6, open);
  // Under water (below the base level at the ends, or in the pit behind column 6): untouched.
  for (const std::size_t j : {1u, 5u, 7u}) EXPECT_EQ(h[j], start[j]) << j;
  // The rest cut down, in an enormous step, to the water they drain into: the sea at 0.9 (the
  // pit at 5 spills over column 6, which is cut down to the sea, so the pit's water falls to
  // it too), nowhere below.
  for (const std::size_t j : {0u, 2u, 3u, 4u, 6u}) {
    EXPECT_GE(h[j], 0.9) << j;
    EXPECT_LT(h[j], 0.9 + 1e-3) << j;
  }
  // The divide (3) drains left, over the pit at 1: each outlet carries its side's rain.
  EXPECT_DOUBLE_EQ(q[0], 4.0);
  EXPECT_DOUBLE_EQ(q[7], 4.0);
  EXPECT_DOUBLE_EQ(q[5], 2.0);  // the pit passes its own water and 4's on to its spill (6)
}

// The carry: a law lowering a column by 0.3 of a particle per update removes a particle every
// 3-4 updates, 30 in 100 (rounding each update would remove none), each named after the law that
// accrued most of it; a rising column owes a deposit instead, and the signed area accrued is the
// area removed plus the area still due, to round-off.
TEST(SurfaceLaws, TheCarryRemovesWholeParticlesAtTheLawsRateAndLosesNoArea) {
  const double width = 1.0, particle = 0.5;
  ErosionCarry carry;
  double accrued = 0, removed_area = 0;
  std::size_t removed = 0;
  std::int64_t next_id = 0;
  for (int update = 0; update < 100; ++update) {
    const double lowering = 0.3 * particle / width;
    const std::vector<double> before = {5.0, 5.0}, after = {5.0 - lowering, 5.0 + 0.1};
    // Two thirds of column 0's lowering by the river, one third by the hillslope.
    const std::array<std::vector<double>, kSurfaceLaws> by_law = {
        std::vector<double>{lowering / 3, 0.0}, std::vector<double>{2 * lowering / 3, 0.0}, std::vector<double>{}};
    accrue_change(carry, 0, before, after, width, by_law);
    accrued += 0.3 * particle - 0.1 * width;
    const auto gone = pay_erosion(carry, {{0, particle, next_id++}, {1, particle, next_id++}});
    removed += gone.size();
    removed_area += particle * static_cast<double>(gone.size());
    for (const auto& r : gone) {
      EXPECT_EQ(r.id % 2, 0) << "the rising column owes nothing";
      EXPECT_EQ(r.law, SurfaceLaw::Fluvial);
    }
  }
  EXPECT_EQ(removed, 30u);
  EXPECT_NEAR(accrued, removed_area + carry.due[0] + carry.due[1], 1e-12);
  EXPECT_NEAR(carry.due[1], -10.0, 1e-12) << "a deposit of 0.1 x 100 still to fill";
  EXPECT_LT(carry.due[0], particle);
}

// A column owed two particles by one law pays them in two passes of one update, both named
// after that law (the first payment used to clear the shares, and the second was named after
// the first law in the list, the hillslope).
TEST(SurfaceLaws, EveryParticleAColumnPaysIsNamedAfterTheLawThatLoweredIt) {
  ErosionCarry carry;
  const std::array<std::vector<double>, kSurfaceLaws> by_law = {std::vector<double>{0.0}, std::vector<double>{1.2},
                                                                std::vector<double>{}};
  accrue_change(carry, 0, {5.0}, {3.8}, 1.0, by_law);
  for (int pass = 0; pass < 2; ++pass) {
    const auto gone = pay_erosion(carry, {{0, 0.5, pass}});
    ASSERT_EQ(gone.size(), 1u) << pass;
    EXPECT_EQ(gone[0].law, SurfaceLaw::Fluvial) << pass;
  }
  EXPECT_NEAR(carry.due[0], 0.2, 1e-12);
}

}  // namespace
}  // namespace orogen
