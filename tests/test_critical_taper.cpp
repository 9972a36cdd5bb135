// Dahlen's exact critical taper for a dry, non-cohesive wedge (MODEL §9).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/critical_taper.hpp"

namespace orogen {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

TEST(CriticalTaper, ReproducesTheKnownValue) {
  // Internal friction 30 deg, basal 10 deg, flat base: 3.44 deg (MODEL §9).
  EXPECT_NEAR(critical_taper(30 * kRad, 10 * kRad) / kRad, 3.44, 0.005);
}

TEST(CriticalTaper, SatisfiesTheTaperEquationAndItsTrends) {
  const double phi = 35 * kRad, phi_b = 12 * kRad, beta = 3 * kRad;
  const double a = critical_taper(phi, phi_b, beta);
  const double psi_b = 0.5 * (std::asin(std::sin(phi_b) / std::sin(phi)) - phi_b);
  const double psi_0 = 0.5 * (std::asin(std::sin(a) / std::sin(phi)) - a);
  EXPECT_NEAR(a + beta, psi_b - psi_0, 1e-12);
  // A frictionless base needs no taper on a flat base; a stronger base a steeper wedge; a
  // steeper basal dip a shallower surface.
  EXPECT_NEAR(critical_taper(phi, 0.0), 0.0, 1e-12);
  EXPECT_GT(critical_taper(phi, 15 * kRad), critical_taper(phi, 10 * kRad));
  EXPECT_LT(critical_taper(phi, phi_b, 5 * kRad), critical_taper(phi, phi_b, 0.0));
}

TEST(CriticalTaper, RefusesABaseStrongerThanTheWedgeWithAClearMessage) {
  try {
    critical_taper(25 * kRad, 30 * kRad);
    FAIL() << "expected an error";
  } catch (const CriticalTaperError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("basal friction angle 30 deg"), std::string::npos) << msg;
    EXPECT_NE(msg.find("below the internal friction angle 25 deg"), std::string::npos) << msg;
  }
  EXPECT_THROW(critical_taper(25 * kRad, 25 * kRad), CriticalTaperError);
  EXPECT_THROW(critical_taper(0.0, 0.0), CriticalTaperError);
}

}  // namespace
}  // namespace orogen
