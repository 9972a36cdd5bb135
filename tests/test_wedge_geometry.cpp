// Wedge measurements (MODEL §8) on synthetic input with known answers: the upper surface,
// deformation and marker fronts, the peak, the wedge height and both kinds of taper angle.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/surface.hpp"
#include "analysis/wedge_geometry.hpp"
#include "particles/discs.hpp"

namespace orogen {
namespace {

constexpr double kLayerH0 = 10, kDiscR = 0.5;
// Synthetic wedge, one disc of radius 0.5 per integer x on top of a flat layer whose top is at
// h0: the surface (disc tops) rises linearly from 11.7 at x = -16 (the pro front) to 18 at
// x = 2 (the peak) and falls linearly to 11.8 at x = 8 (the retro front).
constexpr double kXp = -16, kXt = 2, kXr = 8, kTopP = 11.7, kTopT = 18, kTopR = 11.8;
constexpr double kSlopeP = (kTopT - kTopP) / (kXt - kXp), kSlopeR = (kTopT - kTopR) / (kXr - kXt);

double wedge_top(double x) {
  if (x < kXp || x > kXr) return kLayerH0;
  return x <= kXt ? kTopP + kSlopeP * (x - kXp) : kTopT - kSlopeR * (x - kXt);
}

Discs flat_layer() {
  Discs d;
  std::int64_t id = 0;
  for (int x = -40; x <= 40; ++x) d.add(id++, x, kLayerH0 - kDiscR, kDiscR);
  return d;
}

Discs wedge_discs() {
  Discs d = flat_layer();
  std::int64_t id = static_cast<std::int64_t>(d.size());
  for (int x = static_cast<int>(kXp); x <= static_cast<int>(kXr); ++x) d.add(id++, x, wedge_top(x) - kDiscR, kDiscR);
  return d;
}

WedgeGeometryInput input_of(const Discs& d, double x_s = 0) {
  return {d.x, d.y, d.radius, kLayerH0, 1.0, 1.5, x_s};
}

// Columns of width 1 centred on the integers.
Surface surface_of(const Discs& d) { return measure_surface(d, -40.5, 40.5, 1.0); }

TEST(WedgeGeometry, SurfaceIsTheTopOfTheHighestDiscPerColumn) {
  const Discs d = wedge_discs();
  const Surface s = surface_of(d);
  ASSERT_EQ(s.height.size(), 81u);
  for (int x = -40; x <= 40; ++x) {
    EXPECT_NEAR(s.at(x), wedge_top(x), 1e-12) << x;
    EXPECT_NEAR(s.column_centre(s.column_of(x + 0.3)), x, 1e-12);
    // The wedge disc (ids from 81 on) is the highest wherever there is one.
    const std::int64_t expected = (x >= kXp && x <= kXr) ? 81 + (x - static_cast<int>(kXp)) : x + 40;
    EXPECT_EQ(s.top[s.column_of(x)], expected) << x;
  }
  // Empty columns are NaN with no top disc; ties go to the smaller id whatever the order.
  Discs e;
  e.add(7, 0.2, 1.0, 0.5);
  e.add(3, 0.8, 1.0, 0.5);
  const Surface t = measure_surface(e, -1.0, 3.0, 1.0);
  ASSERT_EQ(t.height.size(), 4u);
  EXPECT_TRUE(std::isnan(t.height[0]));
  EXPECT_EQ(t.top[0], -1);
  EXPECT_DOUBLE_EQ(t.height[1], 1.5);
  EXPECT_EQ(t.top[1], 3);
}

TEST(WedgeGeometry, FrontsPeakHeightAndTapersOfATriangularWedge) {
  const Discs d = wedge_discs();
  const WedgeGeometry g = measure_wedge(input_of(d), surface_of(d));
  ASSERT_TRUE(g.has_front);
  EXPECT_NEAR(g.h, kTopT - kLayerH0, 1e-12);
  EXPECT_NEAR(g.x_peak, kXt, 1e-12);
  // Deformation fronts: extreme discs with centres above h0 + d_max = 11 (the wedge's toes at
  // 11.2 and 11.3).
  EXPECT_NEAR(g.dp, kXp, 1e-12);
  EXPECT_NEAR(g.dr, kXr, 1e-12);
  // Marker fronts: extreme discs with centres above 1.5 h0 = 15: pro 11.2 + 0.35 (x + 16) > 15
  // first at x = -5; retro 17.5 - 6.2/6 (x - 2) > 15 last at x = 4.
  EXPECT_NEAR(g.mp, -5.0, 1e-12);
  EXPECT_NEAR(g.mr, 4.0, 1e-12);
  // Mean tapers: from each front, at the layer top h0, to the peak.
  EXPECT_NEAR(g.alpha, std::atan(8.0 / 18.0), 1e-12);
  EXPECT_NEAR(g.beta, std::atan(8.0 / 6.0), 1e-12);
  // Least-squares tapers of the surface columns between each front and the peak: exact here
  // because every column centre lies on the straight flanks.
  EXPECT_NEAR(g.alpha_fit, std::atan(kSlopeP), 1e-12);
  EXPECT_NEAR(g.beta_fit, std::atan(kSlopeR), 1e-12);
  EXPECT_NEAR(g.alpha_fit * 180 / std::numbers::pi, 19.2900, 1e-4);
  EXPECT_NEAR(g.beta_fit * 180 / std::numbers::pi, 45.9392, 1e-4);
}

TEST(WedgeGeometry, FittedTaperOfAContinuousWedgeMatchesToTheColumnWidth) {
  // Discs of radius 0.1 every 0.05 along a surface of slope 0.25 from x = -20 to the peak at 0,
  // then -0.5 down to x = 10: the column fit only sees the highest disc of each 0.23-wide column,
  // so it matches the slope to within a column width's rise over the flank.
  Discs d;
  std::int64_t id = 0;
  for (int k = 0; k <= 600; ++k) {
    const double x = -20 + 0.05 * k;
    const double top = x <= 0 ? 15 + 0.25 * x : 15 - 0.5 * x;
    d.add(id++, x, top - 0.1, 0.1);
  }
  const Surface s = measure_surface(d, -25.0, 15.0, 0.23);
  const WedgeGeometry g = measure_wedge({d.x, d.y, d.radius, kLayerH0, 1.0, 1.5, 0.0}, s);
  EXPECT_NEAR(g.x_peak, 0.0, 1e-9);
  EXPECT_NEAR(g.h, 5.0, 1e-9);
  EXPECT_NEAR(std::tan(g.alpha_fit), 0.25, 0.25 * 0.23 / 20);
  EXPECT_NEAR(std::tan(g.beta_fit), 0.5, 0.5 * 0.23 / 10);
  // Fronts: centres above 11 at x > -15.6 (pro) and x < 7.8 (retro), to the disc spacing.
  EXPECT_NEAR(g.dp, -15.6, 0.06);
  EXPECT_NEAR(g.dr, 7.8, 0.06);
  EXPECT_NEAR(std::tan(g.alpha), 5.0 / -g.dp, 1e-12);
  EXPECT_NEAR(std::tan(g.beta), 5.0 / g.dr, 1e-12);
}

TEST(WedgeGeometry, NoFrontGivesTheSPointAndZeroTapers) {
  Discs d = flat_layer();
  // One disc a little above the layer, but below h0 + d_max: not a front.
  d.add(1000, 12.0, kLayerH0 + 0.8, kDiscR);
  const WedgeGeometry g = measure_wedge(input_of(d, 3.5), surface_of(d));
  EXPECT_FALSE(g.has_front);
  EXPECT_EQ(g.dp, 3.5);
  EXPECT_EQ(g.dr, 3.5);
  EXPECT_EQ(g.mp, 3.5);
  EXPECT_EQ(g.mr, 3.5);
  EXPECT_EQ(g.x_peak, 3.5);
  EXPECT_NEAR(g.h, 1.3, 1e-12);
  EXPECT_EQ(g.alpha, 0.0);
  EXPECT_EQ(g.beta, 0.0);
  EXPECT_EQ(g.alpha_fit, 0.0);
  EXPECT_EQ(g.beta_fit, 0.0);
  // No discs at all.
  const Discs none;
  const WedgeGeometry e = measure_wedge(input_of(none, -1.0), measure_surface(none, 0, 10, 1));
  EXPECT_FALSE(e.has_front);
  EXPECT_EQ(e.h, 0.0);
  EXPECT_EQ(e.dp, -1.0);
  EXPECT_EQ(e.x_peak, -1.0);
}

TEST(WedgeGeometry, MarkerFrontsFollowTheMarkerHeight) {
  const Discs d = wedge_discs();
  WedgeGeometryInput in = input_of(d);
  // Centres above 1.2 h0 = 12: pro 11.2 + 0.35 (x + 16) > 12 first at x = -13; retro
  // 17.5 - 6.2/6 (x - 2) > 12 last at x = 7.
  in.marker_height = 1.2;
  WedgeGeometry g = measure_wedge(in, surface_of(d));
  EXPECT_NEAR(g.mp, -13.0, 1e-12);
  EXPECT_NEAR(g.mr, 7.0, 1e-12);
  // Above every disc: no marker front, so the S-point; the deformation fronts stay.
  in.marker_height = 2.0;
  in.x_s = 0.25;
  g = measure_wedge(in, surface_of(d));
  EXPECT_EQ(g.mp, 0.25);
  EXPECT_EQ(g.mr, 0.25);
  EXPECT_NEAR(g.dp, kXp, 1e-12);
}

TEST(WedgeGeometry, FittedSlopeOfALinearSurfaceIsExact) {
  Surface s;
  s.x_lo = -3.1;
  s.width = 0.7;
  s.height.resize(30);
  for (std::size_t k = 0; k < s.height.size(); ++k) s.height[k] = 2.0 - 0.3 * s.column_centre(k);
  s.height[10] = std::numeric_limits<double>::quiet_NaN();  // an empty column is skipped
  EXPECT_NEAR(fitted_slope(s, -3.1, 17.9), std::atan(-0.3), 1e-12);
  // Columns outside [x_lo, x_hi] are ignored, however wild.
  s.height[0] = 100;
  s.height[29] = -100;
  EXPECT_NEAR(fitted_slope(s, -2.0, 16.5), std::atan(-0.3), 1e-12);
  // Fewer than two columns: no slope.
  EXPECT_EQ(fitted_slope(s, 1.0, 1.3), 0.0);
  EXPECT_EQ(fitted_slope(s, 50.0, 60.0), 0.0);
}

// wedge.fronts = surface (issue 36): one disc rolling ahead on the foreland sets the thesis's
// front but not the raised surface's; a raised stretch of h0/2 or more does, wherever it is.
TEST(WedgeGeometry, TheSurfaceFrontIgnoresALooseDiscButNotAStretchOfRaisedSurface) {
  Discs d = wedge_discs();
  std::int64_t id = 1000;
  d.add(id++, -30, kLayerH0 + 1.4, kDiscR);  // a loose disc on the layer, its centre above h0 + d_max
  WedgeGeometryInput in = input_of(d);
  const Surface s0 = surface_of(d);
  EXPECT_EQ(measure_wedge(in, s0).dp, -30);  // the thesis's rule
  in.front_rule = FrontRule::Surface;
  in.min_raised_width = 0.5 * kLayerH0;
  const WedgeGeometry g = measure_wedge(in, s0);
  EXPECT_TRUE(g.has_front);
  EXPECT_EQ(g.dp, kXp);
  EXPECT_EQ(g.dr, kXr);
  // Four more raised columns beside the disc: five in all, h0/2, so they count.
  for (int x = -29; x <= -26; ++x) d.add(id++, x, kLayerH0 + 1.4, kDiscR);
  in.x = d.x; in.y = d.y; in.radius = d.radius;
  EXPECT_EQ(measure_wedge(in, surface_of(d)).dp, -30);
  // Gaps up to max_bridged_gap join a stretch: two raised discs two empty columns ahead of the
  // wedge's front belong to it once gaps of 2.5 columns are bridged, not before.
  Discs near = wedge_discs();
  near.add(id++, kXp - 4, kLayerH0 + 1.4, kDiscR);
  near.add(id++, kXp - 3, kLayerH0 + 1.4, kDiscR);
  WedgeGeometryInput bridged = input_of(near);
  bridged.front_rule = FrontRule::Surface;
  bridged.min_raised_width = 0.5 * kLayerH0;
  EXPECT_EQ(measure_wedge(bridged, surface_of(near)).dp, kXp);
  bridged.max_bridged_gap = 0.25 * kLayerH0;
  EXPECT_EQ(measure_wedge(bridged, surface_of(near)).dp, kXp - 4);
  // Nothing raised: no front, the fronts at the S-point as before.
  const Discs flat = flat_layer();
  WedgeGeometryInput none = input_of(flat, 0.25);
  none.front_rule = FrontRule::Surface;
  none.min_raised_width = 0.5 * kLayerH0;
  const WedgeGeometry g0 = measure_wedge(none, surface_of(flat));
  EXPECT_FALSE(g0.has_front);
  EXPECT_EQ(g0.dp, 0.25);
  EXPECT_EQ(g0.dr, 0.25);
}

}  // namespace
}  // namespace orogen
