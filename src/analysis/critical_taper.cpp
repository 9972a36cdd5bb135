#include "analysis/critical_taper.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace orogen {

double critical_taper(double phi, double phi_b, double beta) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  if (!(phi > 0 && phi < std::numbers::pi / 2))
    throw CriticalTaperError(fmt::format("internal friction angle {:.4g} deg must be in (0, 90) deg", phi * kDeg));
  if (!(phi_b >= 0 && phi_b < phi))
    throw CriticalTaperError(fmt::format(
        "basal friction angle {:.4g} deg must be at least 0 and below the internal friction angle {:.4g} deg: "
        "a base as strong as the wedge has no critical taper (the wedge fails internally instead of sliding)",
        phi_b * kDeg, phi * kDeg));
  const double psi_b = 0.5 * (std::asin(std::sin(phi_b) / std::sin(phi)) - phi_b);
  auto residual = [&](double alpha) {
    const double psi_0 = 0.5 * (std::asin(std::sin(alpha) / std::sin(phi)) - alpha);
    return alpha + beta - psi_b + psi_0;
  };
  double lo = -phi * (1 - 1e-12), hi = phi * (1 - 1e-12);
  if (residual(lo) > 0 || residual(hi) < 0)
    throw CriticalTaperError(fmt::format("no critical taper for phi = {:.4g} deg, phi_b = {:.4g} deg, basal dip "
                                         "{:.4g} deg: the dip is outside what the wedge can sustain",
                                         phi * kDeg, phi_b * kDeg, beta * kDeg));
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace orogen
