#include "surface/profile_step.hpp"

#include <algorithm>
#include <numeric>

#include "surface/profile_laws.hpp"

namespace orogen {
namespace {

void record_lowering(std::vector<double>& lowered, const std::vector<double>& before,
                     const std::vector<double>& after) {
  lowered.assign(before.size(), 0.0);
  for (std::size_t j = 0; j < before.size(); ++j) lowered[j] = std::max(before[j] - after[j], 0.0);
}

}  // namespace

double fill_to_level(std::vector<double>& h, std::size_t first, std::size_t last, double dx, double area,
                     double level) {
  if (area <= 0 || first >= last) return std::max(area, 0.0);
  std::vector<std::size_t> order(last - first);
  std::iota(order.begin(), order.end(), first);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] < h[b]; });
  // Raise the lowest k columns together to the height of the (k+1)-th (or the level), until
  // the area is spent.
  double surface = h[order[0]];
  std::size_t k = 1;
  while (area > 0 && surface < level) {
    const double next = std::min(k < order.size() ? h[order[k]] : level, level);
    const double room = (next - surface) * static_cast<double>(k) * dx;
    if (room >= area) {
      surface += area / (static_cast<double>(k) * dx);
      area = 0;
      break;
    }
    area -= room;
    surface = next;
    if (k < order.size() && h[order[k]] <= surface) ++k;
  }
  for (std::size_t i = 0; i < k; ++i) h[order[i]] = std::max(h[order[i]], surface);
  return area;
}

ProfileStep advance_profile(std::vector<double>& h, double dx, double x_lo, const SurfaceSpec& spec, double dt) {
  ProfileStep out;
  const std::vector<double> start = h;
  const ProfileEnds closed{false, spec.base_level}, open{true, spec.base_level};
  std::vector<double> before;
  if (spec.diffusivity > 0) {
    before = h;
    if (spec.critical_slope > 0) diffuse_nonlinear(h, dx, spec.diffusivity, spec.critical_slope, dt, closed);
    else diffuse_linear(h, dx, spec.diffusivity, dt, closed);
    record_lowering(out.lowered[static_cast<std::size_t>(SurfaceLaw::Hillslope)], before, h);
  }
  if (spec.erodibility > 0) {
    before = h;
    const auto rain = precipitation_pattern(h, spec.precipitation,
                                            spec.windward == Windward::None ? 1.0 : spec.windward_factor,
                                            spec.windward == Windward::Pro);
    erode_fluvial(h, dx, {spec.erodibility, spec.area_exponent, spec.slope_exponent}, rain, dt, open);
    record_lowering(out.lowered[static_cast<std::size_t>(SurfaceLaw::Fluvial)], before, h);
  }
  if (spec.script) {
    before = h;
    spec.script(h, dx, x_lo, dt);
    record_lowering(out.lowered[static_cast<std::size_t>(SurfaceLaw::Script)], before, h);
  }
  if (h.empty() || (spec.recycling <= 0 && spec.sediment_supply <= 0)) return out;
  // The sides of the divide: pro [0, divide), retro [divide, n).
  const auto divide = static_cast<std::size_t>(std::max_element(start.begin(), start.end()) - start.begin());
  auto fill_side = [&](int side, double area) {
    return side == 0 ? fill_to_level(h, 0, divide, dx, area, spec.base_level)
                     : fill_to_level(h, divide, h.size(), dx, area, spec.base_level);
  };
  if (spec.recycling > 0) {
    double loss[2] = {0, 0};  // net loss of each side
    for (std::size_t j = 0; j < h.size(); ++j) loss[j < divide ? 0 : 1] += (start[j] - h[j]) * dx;
    for (int side = 0; side < 2; ++side) {
      const double area = spec.recycling * std::max(loss[side], 0.0);
      const double left = fill_side(side, area);
      out.recycled += area - left;
      out.bypassed += left;
    }
  }
  if (spec.sediment_supply > 0) {
    const double pro = spec.supply_to == SupplySide::Both ? 0.5 : spec.supply_to == SupplySide::Pro ? 1.0 : 0.0;
    const double share[2] = {pro, 1.0 - pro};
    for (int side = 0; side < 2; ++side) {
      if (share[side] == 0) continue;
      const double area = share[side] * spec.sediment_supply * dt;
      const double left = fill_side(side, area);
      out.supplied += area - left;
      out.supply_bypassed += left;
    }
  }
  return out;
}

}  // namespace orogen
