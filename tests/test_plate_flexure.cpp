// The base's deflection (issue 40, src/isostasy/) against its analytic solutions: a thin elastic
// plate over a fluid under a line load (the deflection, its first zero at 3 pi alpha / 4 and the
// forebulge at pi alpha, e^-pi of the peak high), Airy's local balance, a wide load reaching
// Airy's depth in its middle, and the whole load borne by the mantle. Then the deflecting base:
// the load of discs beyond the reference layer, the move of the nodes over `every` steps, the
// segment walls joined end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "isostasy/isostatic_base.hpp"
#include "isostasy/plate_flexure.hpp"

namespace orogen {
namespace {

constexpr double kPi = std::numbers::pi;

// Hetenyi's line load P on an infinite plate: w(x) = P alpha^3 / (8 D) e^(-|x|/alpha)
// (cos(x/alpha) + sin(|x|/alpha)).
double line_load_deflection(double x, double load, double rigidity, double alpha) {
  const double s = std::fabs(x) / alpha;
  return load * alpha * alpha * alpha / (8 * rigidity) * std::exp(-s) * (std::cos(s) + std::sin(s));
}

struct LineLoad {
  double dx, alpha;
  std::size_t centre;
  std::vector<double> w;
};

LineLoad line_load(double rigidity, double restoring, double load, double per_alpha) {
  const double alpha = flexural_parameter(rigidity, restoring);
  const double dx = alpha / per_alpha;
  const auto half = static_cast<std::size_t>(12 * per_alpha);  // 12 alpha each side: e^-12 at the ends
  std::vector<double> q(2 * half + 1, 0.0);
  q[half] = load / dx;
  return {dx, alpha, half, plate_deflection(q, dx, rigidity, restoring)};
}

TEST(PlateFlexure, ALineLoadBendsThePlateAsHetenyisSolutionWithItsForebulge) {
  const double D = 3000, k = 1.22, P = 50;
  const LineLoad s = line_load(D, k, P, 40);
  const double peak = line_load_deflection(0, P, D, s.alpha);
  double worst = 0;
  for (std::size_t i = 0; i < s.w.size(); ++i) {
    const double x = (static_cast<double>(i) - static_cast<double>(s.centre)) * s.dx;
    worst = std::max(worst, std::fabs(s.w[i] - line_load_deflection(x, P, D, s.alpha)));
  }
  EXPECT_LT(worst, 2e-3 * peak);  // 40 nodes per alpha
  // The forebulge: the highest point beyond the load, at pi alpha, e^-pi of the peak up.
  const auto bulge = std::min_element(s.w.begin() + static_cast<std::ptrdiff_t>(s.centre), s.w.end());
  const double x_bulge = static_cast<double>(bulge - s.w.begin() - static_cast<std::ptrdiff_t>(s.centre)) * s.dx;
  EXPECT_NEAR(x_bulge, kPi * s.alpha, 1.5 * s.dx);
  EXPECT_NEAR(-*bulge, std::exp(-kPi) * peak, 2e-3 * peak);
  // The first zero at 3 pi alpha / 4.
  std::size_t zero = s.centre;
  while (s.w[zero + 1] > 0) ++zero;
  EXPECT_NEAR(static_cast<double>(zero - s.centre) * s.dx, 0.75 * kPi * s.alpha, 1.5 * s.dx);
}

TEST(PlateFlexure, TheMantleBearsTheWholeLoad) {
  const double D = 500, k = 1.5, P = 7;
  const LineLoad s = line_load(D, k, P, 10);
  const double borne = k * std::accumulate(s.w.begin(), s.w.end(), 0.0) * s.dx;
  EXPECT_NEAR(borne, P, 1e-5 * P);  // the clamped ends, 12 alpha away, take the rest
}

TEST(PlateFlexure, CoarseNodesStayCloseToTheSolution) {
  // The wedge's default: segments h0 / 2 long, alpha a few h0; 4 nodes per alpha.
  const double D = 100, k = 1.22, P = 1;
  const LineLoad s = line_load(D, k, P, 4);
  const double peak = line_load_deflection(0, P, D, s.alpha);
  EXPECT_NEAR(s.w[s.centre], peak, 0.03 * peak);
}

TEST(PlateFlexure, AiryBalancesEachColumnOnItsOwn) {
  const std::vector<double> q = {0, 2.5, -1, 0.3};
  const std::vector<double> w = plate_deflection(q, 0.7, 0.0, 1.25);
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_DOUBLE_EQ(w[i], q[i] / 1.25);
}

TEST(PlateFlexure, AWideLoadSinksToAirysDepthInItsMiddle) {
  const double D = 200, k = 1.22, dx = 0.5, q0 = 3;
  const double alpha = flexural_parameter(D, k);
  const auto n = static_cast<std::size_t>(60 * alpha / dx);
  std::vector<double> q(n, 0.0);
  for (std::size_t i = n / 4; i < 3 * n / 4; ++i) q[i] = q0;  // 30 alpha wide
  const std::vector<double> w = plate_deflection(q, dx, D, k);
  EXPECT_NEAR(w[n / 2], q0 / k, 1e-4 * q0 / k);
  EXPECT_NEAR(w[n / 4], 0.5 * q0 / k, 0.03 * q0 / k);  // a step's edge: half of it
}

TEST(PlateFlexure, RefusesAPlateThatCannotFloat) {
  const std::vector<double> q = {1, 2};
  EXPECT_THROW(plate_deflection(q, 1, 1, 0), std::invalid_argument);
  EXPECT_THROW(plate_deflection(q, 1, -1, 1), std::invalid_argument);
  EXPECT_THROW(plate_deflection(q, 0, 1, 1), std::invalid_argument);
}

IsostasySpec airy(std::int32_t every) {
  IsostasySpec s;
  s.model = IsostasyModel::Airy;
  s.mantle_density = 2;
  s.every = every;
  s.segment_length = 2;
  s.airy_width = 0;  // each column on its own
  return s;
}

TEST(IsostaticBase, SinksUnderTheLoadBeyondTheReferenceAndMovesThereOverEverySteps) {
  IsostaticBase base(airy(100), -5, 5, 0.0);
  EXPECT_EQ(base.nodes(), (std::vector<double>{-6, -4, -2, 0, 2, 4, 6}));
  Discs d;
  d.add(0, 0.2, 1, 1.0);   // pi in the column at 0
  d.add(1, 3.2, 1, 0.5);   // pi / 4 in the column at 4
  d.add(2, 20.0, 1, 1.0);  // beyond the nodes: no load
  base.solve(d, -100, 100, 1000);
  const double at0 = -kPi / 2 / 2, at4 = -kPi / 4 / 2 / 2;  // load / dx / restoring
  const auto end = base.heights(1100);
  EXPECT_DOUBLE_EQ(end[3], at0);
  EXPECT_DOUBLE_EQ(end[5], at4);
  EXPECT_DOUBLE_EQ(end[0], 0.0);
  EXPECT_DOUBLE_EQ(base.height(0.0, 1050), 0.5 * at0);  // half way
  EXPECT_DOUBLE_EQ(base.height(1.0, 1100), 0.5 * at0);  // between nodes: linear
  EXPECT_DOUBLE_EQ(base.height(-50.0, 1100), end[0]);   // past the ends: the end node's
  // A column outside the covered stretch has the reference load: no deflection.
  base.solve(d, 1.5, 100, 1100);
  EXPECT_DOUBLE_EQ(base.heights(1100)[3], at0);  // where it was when the move began
  EXPECT_DOUBLE_EQ(base.heights(1200)[3], 0.0);
  EXPECT_DOUBLE_EQ(base.heights(1200)[5], at4);
}

TEST(IsostaticBase, AiryBalancesTheLoadAveragedOverItsWidth) {
  IsostasySpec spec = airy(100);
  spec.airy_width = 6;  // three nodes
  IsostaticBase base(spec, -5, 5, 0.0);
  Discs d;
  d.add(0, 0.2, 1, 1.0);  // pi in the column at 0
  base.solve(d, -100, 100, 0);
  const auto h = base.heights(100);
  for (std::size_t k : {2u, 3u, 4u}) EXPECT_DOUBLE_EQ(h[k], -kPi / 2 / 3 / 2) << k;
  EXPECT_DOUBLE_EQ(h[1], 0.0);
}

TEST(IsostaticBase, ItsSegmentsJoinEndToEndFromThePlateToTheRetroEnd) {
  IsostaticBase base(airy(100), -5, 5, 0.0);
  Wall pro{.name = "pro_base", .surface_speed = 0.1, .mu = 0.2};
  Wall retro{.name = "retro_base", .mu = 0.4};
  const std::vector<Wall> walls = base.segments(pro, retro, 7.5);
  ASSERT_EQ(walls.size(), 6u);
  EXPECT_EQ(walls.front().name, "pro_base_0");
  EXPECT_EQ(walls[2].mu, 0.2);  // -2 .. 0: pro side
  EXPECT_EQ(walls[3].name, "retro_base_3");
  EXPECT_EQ(walls[3].mu, 0.4);
  for (std::size_t k = 0; k + 1 < walls.size(); ++k) EXPECT_EQ(walls[k].bx, walls[k + 1].ax);
  EXPECT_EQ(walls.back().bx, 7.5);
}

}  // namespace
}  // namespace orogen
