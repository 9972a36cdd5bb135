#include "surface/profile_laws.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace orogen {

void diffuse_linear(std::vector<double>& h, double dx, double kappa, double dt, const ProfileEnds& ends) {
  const std::size_t n = h.size();
  if (n == 0 || kappa <= 0 || dt <= 0) return;
  const double r = kappa * dt / (dx * dx);
  // The tridiagonal system -r h[j-1] + (1 + 2r) h[j] - r h[j+1] = old h[j]; a closed end has no
  // face beyond it, an open one a face to the base level. Thomas's algorithm.
  std::vector<double> diag(n, 1 + 2 * r), rhs(h);
  if (ends.open) {
    rhs.front() += r * ends.base_level;
    rhs.back() += r * ends.base_level;
  } else {
    diag.front() -= r;
    diag.back() -= r;
  }
  std::vector<double> upper(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const double pivot = diag[j] - (j > 0 ? -r * upper[j - 1] : 0.0);
    upper[j] = -r / pivot;
    rhs[j] = (rhs[j] - (j > 0 ? -r * rhs[j - 1] : 0.0)) / pivot;
  }
  for (std::size_t j = n - 1; j-- > 0;) rhs[j] -= upper[j] * rhs[j + 1];
  h = std::move(rhs);
}

void diffuse_nonlinear(std::vector<double>& h, double dx, double kappa, double critical_slope, double dt,
                       const ProfileEnds& ends) {
  const std::size_t n = h.size();
  if (n == 0 || kappa <= 0 || dt <= 0) return;
  // Flux through face k, between columns k - 1 and k (faces 0 and n: the ends), and the largest
  // slope ratio s = |S| / Sc of the faces, which sets the sub-step.
  std::vector<double> flux(n + 1, 0.0);
  double s_top = 0;
  auto face_flux = [&](double left, double right) {
    const double slope = (right - left) / dx;
    const double s = std::min(std::fabs(slope) / critical_slope, kMaxSlopeRatio);
    s_top = std::max(s_top, s);
    return -kappa * std::copysign(s * critical_slope, slope) / (1 - s * s);
  };
  for (double done = 0; done < dt;) {
    s_top = 0;
    for (std::size_t k = 1; k < n; ++k) flux[k] = face_flux(h[k - 1], h[k]);
    if (ends.open) {
      flux[0] = face_flux(ends.base_level, h.front());
      flux[n] = face_flux(h.back(), ends.base_level);
    }
    // Explicit: stable for tau <= dx^2 / (2 D), D = kappa (1 + s^2) / (1 - s^2)^2 the law's
    // diffusivity on the steepest face.
    const double diffusivity = kappa * (1 + s_top * s_top) / ((1 - s_top * s_top) * (1 - s_top * s_top));
    const double tau = std::min(dt - done, 0.4 * dx * dx / diffusivity);
    for (std::size_t j = 0; j < n; ++j) h[j] -= tau * (flux[j + 1] - flux[j]) / dx;
    done += tau;
  }
}

namespace {

constexpr std::ptrdiff_t kOutside = -1;  // drains out of the profile, to the base level
constexpr std::ptrdiff_t kNone = -2;     // a pit or a flat: no receiver

// Each column's receiver: the neighbour (or, at an open end, the base level beyond it) of the
// largest drop below it; none where no neighbour is lower.
std::vector<std::ptrdiff_t> receivers(const std::vector<double>& h, const ProfileEnds& ends) {
  const auto n = static_cast<std::ptrdiff_t>(h.size());
  std::vector<std::ptrdiff_t> out(h.size(), kNone);
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    double best = 0;
    auto consider = [&](std::ptrdiff_t to, double height) {
      if (h[static_cast<std::size_t>(j)] - height > best) {
        best = h[static_cast<std::size_t>(j)] - height;
        out[static_cast<std::size_t>(j)] = to;
      }
    };
    if (j > 0) consider(j - 1, h[static_cast<std::size_t>(j - 1)]);
    else if (ends.open) consider(kOutside, ends.base_level);
    if (j + 1 < n) consider(j + 1, h[static_cast<std::size_t>(j + 1)]);
    else if (ends.open) consider(kOutside, ends.base_level);
  }
  return out;
}

}  // namespace

std::vector<double> erode_fluvial(std::vector<double>& h, double dx, const StreamPower& law,
                                  const std::vector<double>& precipitation, double dt, const ProfileEnds& ends) {
  const std::size_t n = h.size();
  std::vector<double> discharge(n, 0.0);
  if (n == 0) return discharge;
  const std::vector<std::ptrdiff_t> to = receivers(h, ends);
  // Lowest first (ties by column): every receiver comes before the columns draining into it.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] < h[b]; });
  for (std::size_t j = 0; j < n; ++j) discharge[j] = precipitation[j] * dx;
  for (auto it = order.rbegin(); it != order.rend(); ++it)
    if (to[*it] >= 0) discharge[static_cast<std::size_t>(to[*it])] += discharge[*it];
  if (law.K <= 0 || dt <= 0) return discharge;
  for (const std::size_t j : order) {
    if (to[j] == kNone) continue;
    const double base = to[j] == kOutside ? ends.base_level : h[static_cast<std::size_t>(to[j])];
    const double c = law.K * std::pow(discharge[j], law.m) * dt / std::pow(dx, law.n);
    const double old = h[j];
    if (law.n == 1) {
      h[j] = (old + c * base) / (1 + c);
      continue;
    }
    // Newton on g(z) = z - old + c (z - base)^n over z > base, from the old height down.
    double z = old;
    for (int k = 0; k < 50; ++k) {
      const double drop = z - base;
      const double g = z - old + c * std::pow(drop, law.n);
      const double slope = 1 + c * law.n * std::pow(drop, law.n - 1);
      const double next = std::max(base + 1e-12 * std::max(1.0, std::fabs(base)), z - g / slope);
      if (std::fabs(next - z) <= 1e-14 * std::max(1.0, std::fabs(z))) {
        z = next;
        break;
      }
      z = next;
    }
    h[j] = z;
  }
  return discharge;
}

std::vector<double> precipitation_pattern(const std::vector<double>& h, double rate, double windward_factor,
                                          bool windward_is_left) {
  std::vector<double> p(h.size(), rate);
  if (h.empty() || windward_factor == 1) return p;
  const auto divide = static_cast<std::size_t>(std::max_element(h.begin(), h.end()) - h.begin());
  for (std::size_t j = 0; j < h.size(); ++j)
    if (windward_is_left ? j < divide : j > divide) p[j] = rate * windward_factor;
  return p;
}

}  // namespace orogen
