#include "render/colormap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace orogen {

namespace {

struct Stop {
  double t;
  Rgb c;
};

constexpr Rgb rgb8(int r, int g, int b) { return {r / 255.0, g / 255.0, b / 255.0}; }

// viridis sampled at 9 even points (matplotlib's values), enough for linear interpolation.
constexpr std::array<Stop, 9> kViridis{{
    {0.000, rgb8(68, 1, 84)},     {0.125, rgb8(71, 45, 123)},  {0.250, rgb8(59, 82, 139)},
    {0.375, rgb8(44, 114, 142)},  {0.500, rgb8(33, 144, 140)}, {0.625, rgb8(39, 173, 129)},
    {0.750, rgb8(93, 200, 99)},   {0.875, rgb8(170, 220, 50)}, {1.000, rgb8(253, 231, 37)},
}};

// "hot": black -> red -> yellow -> white, each channel ramping in turn.
constexpr std::array<Stop, 4> kHot{{
    {0.000, {0.0, 0.0, 0.0}},
    {0.375, {1.0, 0.0, 0.0}},
    {0.750, {1.0, 1.0, 0.0}},
    {1.000, {1.0, 1.0, 1.0}},
}};

constexpr std::array<Stop, 4> kForce{{
    {0.000, rgb8(250, 200, 120)},
    {0.350, rgb8(235, 110, 40)},
    {0.700, rgb8(170, 20, 20)},
    {1.000, rgb8(30, 0, 0)},
}};

Rgb interpolate(std::span<const Stop> stops, double t) {
  t = std::clamp(t, 0.0, 1.0);
  std::size_t k = 1;
  while (k + 1 < stops.size() && stops[k].t < t) ++k;
  const Stop& a = stops[k - 1];
  const Stop& b = stops[k];
  const double u = (t - a.t) / (b.t - a.t);
  return {a.c.r + u * (b.c.r - a.c.r), a.c.g + u * (b.c.g - a.c.g), a.c.b + u * (b.c.b - a.c.b)};
}

// Alternating light/dark earth tones so that neighbouring bands always contrast:
// sand, dark brown, ochre, slate green.
constexpr std::array<Rgb, kMaxHorizonColors> kHorizon{{
    rgb8(230, 200, 140),
    rgb8(115, 77, 51),
    rgb8(204, 128, 64),
    rgb8(89, 102, 84),
}};

double percentile(const std::vector<double>& sorted, double pct) {
  const double pos = std::clamp(pct, 0.0, 100.0) / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  if (i + 1 >= sorted.size()) return sorted.back();
  const double u = pos - static_cast<double>(i);
  return sorted[i] + u * (sorted[i + 1] - sorted[i]);
}

}  // namespace

Rgb colormap_sample(Colormap map, double t) {
  if (std::isnan(t)) return {0.5, 0.5, 0.5};
  switch (map) {
    case Colormap::Hot: return interpolate(kHot, t);
    case Colormap::Force: return interpolate(kForce, t);
    case Colormap::Viridis: break;
  }
  return interpolate(kViridis, t);
}

ValueRange robust_range(std::span<const double> values, double lo_pct, double hi_pct) {
  std::vector<double> v;
  v.reserve(values.size());
  for (double a : values)
    if (std::isfinite(a)) v.push_back(a);
  if (v.empty()) return {0.0, 1.0};
  std::sort(v.begin(), v.end());
  ValueRange r{percentile(v, lo_pct), percentile(v, hi_pct)};
  if (!(r.hi > r.lo)) {
    // A constant field: centre it so it still gets a colour from the middle of the map.
    const double pad = std::max(std::abs(r.lo) * 1e-6, 1e-12);
    r.lo -= pad;
    r.hi += pad;
  }
  return r;
}

Rgb horizon_color(double depth0, double band, int n_colors, bool pro_side) {
  if (!std::isfinite(depth0) || !(band > 0)) return {0.6, 0.6, 0.6};
  const int n = std::clamp(n_colors, 2, kMaxHorizonColors);
  const auto k = static_cast<long long>(std::floor(std::max(depth0, 0.0) / band));
  const Rgb c = kHorizon[static_cast<std::size_t>(k % n)];
  return pro_side ? lighten(c, 0.45) : c;
}

Rgb cluster_color(std::int64_t cluster_id) {
  if (cluster_id < 0) return {0.82, 0.82, 0.82};
  // splitmix64 finaliser: neighbouring ids land far apart in hue.
  auto z = static_cast<std::uint64_t>(cluster_id) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  const double h = static_cast<double>(z & 0xffff) / 65536.0 * 6.0;
  const double s = 0.55 + 0.35 * static_cast<double>((z >> 16) & 0xff) / 255.0;
  const double v = 0.70 + 0.25 * static_cast<double>((z >> 24) & 0xff) / 255.0;
  // HSV to RGB.
  const double c = v * s;
  const double x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  const double m = v - c;
  Rgb out;
  switch (static_cast<int>(h)) {
    case 0: out = {c, x, 0}; break;
    case 1: out = {x, c, 0}; break;
    case 2: out = {0, c, x}; break;
    case 3: out = {0, x, c}; break;
    case 4: out = {x, 0, c}; break;
    default: out = {c, 0, x}; break;
  }
  return {out.r + m, out.g + m, out.b + m};
}

Rgb lighten(Rgb c, double amount) {
  const double a = std::clamp(amount, 0.0, 1.0);
  return {c.r + a * (1.0 - c.r), c.g + a * (1.0 - c.g), c.b + a * (1.0 - c.b)};
}

Rgb darken(Rgb c, double factor) {
  const double f = std::clamp(factor, 0.0, 1.0);
  return {c.r * f, c.g * f, c.b * f};
}

}  // namespace orogen
