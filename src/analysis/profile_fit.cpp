#include "analysis/profile_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace orogen {
namespace {

// Solves the 3x3 normal equations of the quadratic fit by Cramer's rule (well conditioned
// here because x is centred and scaled first).
std::array<double, 3> quadratic_coefficients(const std::vector<double>& x, const std::vector<double>& y) {
  double s[5] = {0, 0, 0, 0, 0}, t[3] = {0, 0, 0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    double p = 1;
    for (int k = 0; k < 5; ++k) {
      s[k] += p;
      if (k < 3) t[k] += p * y[i];
      p *= x[i];
    }
  }
  auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h, double i) {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  };
  const double D = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
  if (std::fabs(D) < 1e-300) return {0, 0, 0};
  return {det3(t[0], s[1], s[2], t[1], s[2], s[3], t[2], s[3], s[4]) / D,
          det3(s[0], t[0], s[2], s[1], t[1], s[3], s[2], t[2], s[4]) / D,
          det3(s[0], s[1], t[0], s[1], s[2], t[1], s[2], s[3], t[2]) / D};
}

}  // namespace

ProfileFit fit_points(const std::vector<double>& x, const std::vector<double>& y) {
  ProfileFit f;
  f.n = static_cast<int>(x.size());
  if (f.n < 3) return f;
  f.x_lo = *std::min_element(x.begin(), x.end());
  f.x_hi = *std::max_element(x.begin(), x.end());
  const double n = f.n;
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) { sx += x[i]; sy += y[i]; }
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0) { f.n = 0; return f; }
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ss_res = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - (f.intercept + f.slope * x[i]);
    ss_res += r * r;
  }
  f.r2 = syy > 0 ? 1.0 - ss_res / syy : 1.0;
  f.rms = std::sqrt(ss_res / n);
  // Quadratic in the centred, scaled coordinate u = (x - mx) / half, so that u is in [-1, 1].
  const double half = std::max(0.5 * (f.x_hi - f.x_lo), 1e-12);
  std::vector<double> u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) u[i] = (x[i] - mx) / half;
  const auto q = quadratic_coefficients(u, y);
  const double u_lo = (f.x_lo - mx) / half, u_hi = (f.x_hi - mx) / half;
  const double slope_lo = (q[1] + 2 * q[2] * u_lo) / half, slope_hi = (q[1] + 2 * q[2] * u_hi) / half;
  // The upper end is where the line is higher; descent angles are measured downhill from it.
  const double sign = f.slope <= 0 ? -1.0 : 1.0;  // descending to the right: -1
  const double upper = f.slope <= 0 ? slope_lo : slope_hi, lower = f.slope <= 0 ? slope_hi : slope_lo;
  f.concavity = std::atan(sign * upper) - std::atan(sign * lower);
  return f;
}

ProfileFit fit_profile(const Surface& s, double x_lo, double x_hi, double y_lo, double y_hi) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < s.height.size(); ++k) {
    const double xc = s.column_centre(k), h = s.height[k];
    if (xc < x_lo || xc > x_hi || !std::isfinite(h) || h <= y_lo || h >= y_hi) continue;
    x.push_back(xc);
    y.push_back(h);
  }
  return fit_points(x, y);
}

}  // namespace orogen
