#include "isostasy/isostatic_base.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "isostasy/plate_flexure.hpp"

namespace orogen {
namespace {

// The mean of the values within `width` nodes around each (half of it on each side; the ends'
// windows cut short, over the nodes they hold).
std::vector<double> running_mean(const std::vector<double>& v, double width) {
  const auto half = static_cast<std::ptrdiff_t>(0.5 * width);
  const auto n = static_cast<std::ptrdiff_t>(v.size());
  std::vector<double> out(v.size());
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double sum = 0;
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, k - half), hi = std::min(n - 1, k + half);
    for (std::ptrdiff_t j = lo; j <= hi; ++j) sum += v[static_cast<std::size_t>(j)];
    out[static_cast<std::size_t>(k)] = sum / static_cast<double>(hi - lo + 1);
  }
  return out;
}

}  // namespace

IsostaticBase::IsostaticBase(const IsostasySpec& spec, double x_lo, double x_hi, double reference_load)
    : spec_(spec), reference_load_(reference_load) {
  if (!active()) return;
  const double dx = spec_.segment_length;
  const auto pro = static_cast<long>(std::ceil(-x_lo / dx - 1e-9));
  const auto retro = static_cast<long>(std::ceil(x_hi / dx - 1e-9));
  for (long k = -pro; k <= retro; ++k) x_.push_back(static_cast<double>(k) * dx);
  const double alpha =
      spec_.model == IsostasyModel::Flexure ? flexural_parameter(spec_.rigidity, spec_.mantle_density) : 0.0;
  margin_ = static_cast<std::size_t>(std::ceil(4 * alpha / dx));
  from_.assign(x_.size(), 0.0);
  to_.assign(x_.size(), 0.0);
}

std::vector<Wall> IsostaticBase::segments(const Wall& pro, const Wall& retro, double retro_end) const {
  std::vector<Wall> out;
  const std::vector<double> h = heights(move_start_);
  for (std::size_t k = 0; k + 1 < x_.size(); ++k) {
    Wall w = x_[k + 1] <= 0 ? pro : retro;
    w.name = fmt::format("{}_{}", w.name, k);
    w.ax = x_[k];
    w.ay = h[k];
    w.bx = k + 2 == x_.size() ? std::max(retro_end, x_[k + 1]) : x_[k + 1];
    w.by = h[k + 1];
    out.push_back(std::move(w));
  }
  return out;
}

void IsostaticBase::solve(const Discs& d, double covered_lo, double covered_hi, std::uint64_t step) {
  const double dx = spec_.segment_length;
  const std::size_t n = x_.size();
  std::vector<double> load(n + 2 * margin_, 0.0);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double k = std::round((d.x[i] - x_.front()) / dx);
    if (k < 0 || k >= static_cast<double>(n)) continue;
    load[margin_ + static_cast<std::size_t>(k)] += std::numbers::pi * d.radius[i] * d.radius[i] / dx;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const bool covered = x_[k] - 0.5 * dx >= covered_lo && x_[k] + 0.5 * dx <= covered_hi;
    load[margin_ + k] = covered ? load[margin_ + k] - reference_load_ : 0.0;
  }
  if (spec_.model == IsostasyModel::Airy) load = running_mean(load, spec_.airy_width / dx);
  const std::vector<double> w = plate_deflection(load, dx, spec_.rigidity, spec_.mantle_density);
  from_ = heights(step);
  for (std::size_t k = 0; k < n; ++k) to_[k] = -w[margin_ + k];
  move_start_ = step;
}

double IsostaticBase::at_node(std::size_t k, std::uint64_t step) const {
  if (step >= move_start_ + static_cast<std::uint64_t>(spec_.every)) return to_[k];
  const double f = static_cast<double>(step - std::min(step, move_start_)) / spec_.every;
  return from_[k] + (to_[k] - from_[k]) * f;
}

std::vector<double> IsostaticBase::heights(std::uint64_t step) const {
  std::vector<double> h(x_.size());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = at_node(k, step);
  return h;
}

double IsostaticBase::height(double x, std::uint64_t step) const {
  if (x_.empty()) return 0.0;
  const double s = (x - x_.front()) / spec_.segment_length;
  if (s <= 0) return at_node(0, step);
  const auto k = static_cast<std::size_t>(s);
  if (k + 1 >= x_.size()) return at_node(x_.size() - 1, step);
  const double f = s - static_cast<double>(k);
  return at_node(k, step) * (1 - f) + at_node(k + 1, step) * f;
}

IsostaticBase::Shape IsostaticBase::shape(std::uint64_t step) const {
  const std::vector<double> h = heights(step);
  const auto deepest = static_cast<std::size_t>(std::min_element(h.begin(), h.end()) - h.begin());
  const double pro = *std::max_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(deepest) + 1);
  const double retro = *std::max_element(h.begin() + static_cast<std::ptrdiff_t>(deepest), h.end());
  return {-h[deepest], x_[deepest], pro, retro};
}

}  // namespace orogen
