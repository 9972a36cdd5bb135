#include "surface/surface_processes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>

#include "analysis/surface.hpp"
#include "io/archive_fields.hpp"
#include "io/binary_archive.hpp"
#include "surface/profile_step.hpp"
#include "util/random.hpp"

namespace orogen {
namespace {

constexpr int kMaxRemovalPasses = 16;  // a column pays at most this many particles in one update
constexpr double kPlacementGap = 1e-3;  // a laid disc starts this far above what it rests on [d]
constexpr int kMaxDepositsPerColumn = 64;  // in one update; more stay owed to the next

double disc_area_of(double r) { return std::numbers::pi * r * r; }

RemovalReason reason_of(SurfaceLaw law) {
  return static_cast<RemovalReason>(static_cast<int>(RemovalReason::ErodedHillslope) + static_cast<int>(law));
}

}  // namespace

double disc_area(const World& w) {
  double sum = 0;
  for (double r : w.discs().radius) sum += disc_area_of(r);
  return sum;
}

double body_area(const World& w, std::size_t i) {
  const auto k = w.discs().cluster[i];
  if (k < 0) return disc_area_of(w.discs().radius[i]);
  double sum = 0;
  for (const auto m : w.clusters().members[static_cast<std::size_t>(k)])
    if (m >= 0) sum += disc_area_of(w.discs().radius[static_cast<std::size_t>(m)]);
  return sum;
}

Surface SurfaceProcesses::columns_of(const World& w, std::int64_t first, std::int64_t last) const {
  // Half a column short of the end: measure_surface rounds the count up, and last - first
  // columns must not become one more by round-off.
  const double width = spec_.column_width, x_lo = static_cast<double>(first) * width;
  return measure_surface(w.discs(), x_lo, x_lo + (static_cast<double>(last - first) - 0.5) * width, width);
}

void SurfaceProcesses::load_state(const ArchiveReader& in) {
  loaded_ = in.has("surface.due");
  if (!loaded_) return;
  book_fields(*this, ArchiveLoader(in));
  // A branch that brings the supply in (its source had none) starts its books at zero.
  if (spec_.sediment_supply > 0 && in.has("surface.supplied")) supply_fields(*this, ArchiveLoader(in));
}

void SurfaceProcesses::start_in_branch(const World& w) {
  if (!loaded_) ledger_.entered = disc_area(w);
}

void SurfaceProcesses::cover(std::int64_t first, std::int64_t last) {
  if (carry_.due.empty()) origin_ = first;
  auto grow = [&](std::vector<double>& v) {
    if (first < origin_) v.insert(v.begin(), static_cast<std::size_t>(origin_ - first), 0.0);
    const auto size = static_cast<std::size_t>(last - std::min(first, origin_));
    if (v.size() < size) v.resize(size, 0.0);
  };
  grow(carry_.due);
  for (auto& share : carry_.by_law) grow(share);
  origin_ = std::min(first, origin_);
}

void SurfaceProcesses::update(World& w, double x_lo, double x_hi, double dt, const BaseHeight& base) {
  const double width = spec_.column_width;
  const auto first = static_cast<std::int64_t>(std::floor(x_lo / width));
  // Whole columns only: one reaching past x_hi (an end wall) would hold nothing beyond it.
  const auto last = std::max(first + 1, static_cast<std::int64_t>(std::floor(x_hi / width)));
  cover(first, last);
  Surface s = columns_of(w, first, last);
  const auto n = s.height.size();
  const auto offset = static_cast<std::size_t>(first - origin_);
  // The base under each column's middle, and the continuum surface: the particles' (the base's
  // in an empty column) less what the carry owes them.
  std::vector<double> ground(n, 0.0), h(n);
  if (base)
    for (std::size_t k = 0; k < n; ++k) ground[k] = base((static_cast<double>(first) + 0.5 + static_cast<double>(k)) * width);
  for (std::size_t k = 0; k < n; ++k)
    h[k] = (std::isnan(s.height[k]) ? ground[k] : s.height[k]) - carry_.due[offset + k] / width;
  const std::vector<double> before = h;
  double mean_before = 0;  // of the thickness over the base
  for (std::size_t k = 0; k < n; ++k) mean_before += (h[k] - ground[k]) / static_cast<double>(n);
  const ProfileStep step = advance_profile(h, width, static_cast<double>(first) * width, spec_, dt);
  // The lowest column the laws lowered, over the base (one the carry alone left below the base
  // is not theirs).
  double mean_after = 0, lowest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    mean_after += (h[k] - ground[k]) / static_cast<double>(n);
    if (h[k] < before[k]) lowest = std::min(lowest, h[k] - ground[k]);
  }
  const double diameter = radii_.empty() ? 1.0 : 2 * *std::max_element(radii_.begin(), radii_.end());
  if (lowest < 0 || (mean_after < diameter && mean_before >= diameter))
    throw InstabilityError(fmt::format(
        "the surface update at step {} would remove the whole layer: the profile over x = [{:.4g}, {:.4g}] d falls "
        "from a mean height of {:.4g} to {:.4g} d over the base (lowest column {:.4g} d over it) in {:.4g} time units; "
        "lower the surface laws' rates (surface.diffusivity, surface.erodibility, surface.precipitation) or "
        "surface.every",
        w.step(), x_lo, x_hi, mean_before, mean_after, lowest, dt));
  accrue_change(carry_, offset, before, h, width, step.lowered);
  ledger_.recycled += step.recycled;
  ledger_.bypassed += step.bypassed;
  ledger_.supplied += step.supplied;
  ledger_.supply_bypassed += step.supply_bypassed;
  // The first pass on the surface measured above (no disc has moved since), then again after
  // each pass that removed some.
  for (int pass = 0; pass < kMaxRemovalPasses && pay_removals(w, s, offset) > 0; ++pass) s = columns_of(w, first, last);
  if (spec_.deposition) lay_deposits(w, first, last, base);
}

std::size_t SurfaceProcesses::pay_removals(World& w, const Surface& s, std::size_t offset) {
  // Each column's top particle, named by its disc index.
  std::vector<TopParticle> tops;
  std::unordered_set<std::int32_t> clusters;
  for (std::size_t k = 0; k < s.height.size(); ++k) {
    if (s.top[k] < 0 || carry_.due[offset + k] <= 0) continue;
    const std::size_t i = s.top_index[k];
    if (w.discs().cluster[i] >= 0 && !clusters.insert(w.discs().cluster[i]).second) continue;  // paid once
    tops.push_back({offset + k, body_area(w, i), static_cast<std::int64_t>(i)});
  }
  const auto paid = pay_erosion(carry_, tops);
  if (paid.empty()) return 0;
  // One removal per law; each flags by stable id, as the one before re-orders the discs.
  std::array<std::unordered_set<std::int64_t>, kSurfaceLaws> ids;
  for (const DueRemoval& r : paid) {
    const auto i = static_cast<std::size_t>(r.id);
    ids[static_cast<std::size_t>(r.law)].insert(w.discs().id[i]);
    ledger_.eroded[static_cast<std::size_t>(r.law)] += body_area(w, i);
  }
  for (std::size_t law = 0; law < kSurfaceLaws; ++law) {
    if (ids[law].empty()) continue;
    std::vector<std::uint8_t> flags(w.discs().size(), 0);
    for (std::size_t i = 0; i < w.discs().size(); ++i) flags[i] = ids[law].count(w.discs().id[i]) ? 1 : 0;
    w.remove(flags, reason_of(static_cast<SurfaceLaw>(law)));
  }
  return paid.size();
}

double SurfaceProcesses::draw_radius(std::uint64_t draw, double& offset) const {
  Random r(seed_ ^ (0x9E3779B97F4A7C15ull * (draw + 1)));
  const auto pick = static_cast<std::size_t>(r.uniform() * static_cast<double>(radii_.size()));
  const double radius = radii_.empty() ? 0.5 : radii_[pick];
  offset = r.uniform(-0.25, 0.25);
  return radius;
}

void SurfaceProcesses::lay_deposits(World& w, std::int64_t first, std::int64_t last, const BaseHeight& base) {
  const double width = spec_.column_width;
  const auto offset = static_cast<std::size_t>(first - origin_);
  for (std::int64_t col = first; col < last; ++col) {
    double& owed = carry_.due[offset + static_cast<std::size_t>(col - first)];
    for (int laid = 0; laid < kMaxDepositsPerColumn; ++laid) {
      double jitter = 0;
      const double r = draw_radius(static_cast<std::uint64_t>(deposits_), jitter);
      if (!(-owed >= disc_area_of(r))) break;  // (a NaN owes nothing)
      const double x = (static_cast<double>(col) + 0.5 + jitter) * width;  // inside the column
      // The lowest height at x where a disc of radius r touches nothing (overlapping no disc
      // and not the base: above the base's highest point under it, sampled every r / 2).
      double y = r;
      if (base) {
        double top = base(x - r);
        for (double at : {x - 0.5 * r, x, x + 0.5 * r, x + r}) top = std::max(top, base(at));
        y = top + r;
      }
      const auto& d = w.discs();
      for (std::size_t j = 0; j < d.size(); ++j) {
        const double reach = r + d.radius[j], dx = d.x[j] - x;
        if (std::fabs(dx) >= reach) continue;
        y = std::max(y, d.y[j] + std::sqrt(reach * reach - dx * dx));
      }
      const std::size_t i = w.add_disc(x, y + kPlacementGap, r);
      if (w.discs().has_materials) w.set_material(i, spec_.sediment_material);
      const auto id = static_cast<std::size_t>(w.discs().id[i]);
      if (deposited_at_.size() <= id) deposited_at_.resize(id + 1, std::numeric_limits<double>::quiet_NaN());
      deposited_at_[id] = w.time();
      owed += disc_area_of(r);
      ledger_.deposited += disc_area_of(r);
      ++deposits_;
    }
  }
}

}  // namespace orogen
