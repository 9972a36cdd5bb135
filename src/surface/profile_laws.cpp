#include "surface/profile_laws.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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
constexpr std::ptrdiff_t kNone = -2;     // a flat with no lower neighbour: no receiver

// Where water stands: the lowest rim each column's water must climb to leave the profile by
// each end (the highest column between it and the end, and at least the base level at an open
// end; a closed end lets none out). Below the lower of its two rims a column lies under water (a
// lake, or the sea below the base level), which stands at that rim.
struct Rims {
  std::vector<double> left, right;
  double level(std::size_t j) const { return std::min(left[j], right[j]); }
};

Rims rims_of(const std::vector<double>& h, const ProfileEnds& ends) {
  const std::size_t n = h.size();
  const double outlet = ends.open ? ends.base_level : std::numeric_limits<double>::infinity();
  Rims r{std::vector<double>(n), std::vector<double>(n)};
  double rim = outlet;
  for (std::size_t j = 0; j < n; ++j) r.left[j] = rim = std::max(rim, h[j]);
  rim = outlet;
  for (std::size_t j = n; j-- > 0;) r.right[j] = rim = std::max(rim, h[j]);
  return r;
}

// Each column's receiver: under water, the neighbour towards the lower rim (where the lake
// spills); above it, the neighbour (or, at an open end, the base level beyond it) whose water
// surface lies lowest below it; none on a flat with no lower neighbour.
std::vector<std::ptrdiff_t> receivers(const std::vector<double>& h, const Rims& rims, const ProfileEnds& ends) {
  const auto n = static_cast<std::ptrdiff_t>(h.size());
  std::vector<std::ptrdiff_t> out(h.size(), kNone);
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    const auto u = static_cast<std::size_t>(j);
    if (rims.level(u) > h[u]) {
      if (rims.left[u] <= rims.right[u]) out[u] = j > 0 ? j - 1 : kOutside;
      else out[u] = j + 1 < n ? j + 1 : kOutside;
      continue;
    }
    double best = 0;
    auto consider = [&](std::ptrdiff_t to, double height) {
      if (h[u] - height > best) {
        best = h[u] - height;
        out[u] = to;
      }
    };
    if (j > 0) consider(j - 1, rims.level(u - 1));
    else if (ends.open) consider(kOutside, ends.base_level);
    if (j + 1 < n) consider(j + 1, rims.level(u + 1));
    else if (ends.open) consider(kOutside, ends.base_level);
  }
  return out;
}

// The columns, every receiver before the columns that drain into it: from the outlets and the
// flats, up each chain of donors (one or two a column).
std::vector<std::size_t> receivers_first(const std::vector<std::ptrdiff_t>& to) {
  const std::size_t n = to.size();
  std::vector<std::array<std::ptrdiff_t, 2>> donors(n, {-1, -1});
  std::vector<std::size_t> order;
  order.reserve(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (to[j] < 0) {
      order.push_back(j);
      continue;
    }
    auto& d = donors[static_cast<std::size_t>(to[j])];
    (d[0] < 0 ? d[0] : d[1]) = static_cast<std::ptrdiff_t>(j);
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    for (const std::ptrdiff_t d : donors[order[k]])
      if (d >= 0) order.push_back(static_cast<std::size_t>(d));
  return order;
}

}  // namespace

std::vector<double> erode_fluvial(std::vector<double>& h, double dx, const StreamPower& law,
                                  const std::vector<double>& precipitation, double dt, const ProfileEnds& ends) {
  const std::size_t n = h.size();
  std::vector<double> discharge(n, 0.0);
  if (n == 0) return discharge;
  const Rims rims = rims_of(h, ends);
  const std::vector<std::ptrdiff_t> to = receivers(h, rims, ends);
  const std::vector<std::size_t> order = receivers_first(to);
  for (std::size_t j = 0; j < n; ++j) discharge[j] = precipitation[j] * dx;
  for (auto it = order.rbegin(); it != order.rend(); ++it)
    if (to[*it] >= 0) discharge[static_cast<std::size_t>(to[*it])] += discharge[*it];
  if (law.K <= 0 || dt <= 0) return discharge;
  // The water surface after the step: a lake stands at its rim as the rim is cut down, and
  // never below its floor; a river cuts down to the surface of what it drains into.
  std::vector<double> surface(n);
  for (const std::size_t j : order) {
    const double base = to[j] == kOutside ? ends.base_level
                        : to[j] == kNone   ? h[j]
                                           : surface[static_cast<std::size_t>(to[j])];
    if (to[j] == kNone || rims.level(j) > h[j]) {  // a flat, or under water: no river cuts here
      surface[j] = std::max(h[j], base);
      continue;
    }
    const double c = law.K * std::pow(discharge[j], law.m) * dt / std::pow(dx, law.n);
    const double old = h[j];
    if (old <= base) {
      surface[j] = base;
      continue;
    }
    if (law.n == 1) {
      h[j] = (old + c * base) / (1 + c);
      surface[j] = h[j];
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
    surface[j] = z;
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
