#include "analysis/displacement_tracker.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace orogen {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

void DisplacementTracker::remember(const World& w) {
  prev_x_[2] = std::move(prev_x_[1]); prev_y_[2] = std::move(prev_y_[1]);
  prev_x_[1] = std::move(prev_x_[0]); prev_y_[1] = std::move(prev_y_[0]);
  prev_x_[0].assign(static_cast<std::size_t>(w.next_disc_id()), kNaN);
  prev_y_[0].assign(static_cast<std::size_t>(w.next_disc_id()), kNaN);
  for (std::size_t i = 0; i < w.discs().size(); ++i) {
    prev_x_[0][static_cast<std::size_t>(w.discs().id[i])] = w.discs().x[i];
    prev_y_[0][static_cast<std::size_t>(w.discs().id[i])] = w.discs().y[i];
  }
}

std::vector<SnapshotField> DisplacementTracker::fields(const World& w) const {
  const auto& d = w.discs();
  std::vector<double> rel(d.size(), 0.0), dx3(d.size(), kNaN), dy3(d.size(), kNaN);
  // Position of disc i at an earlier output (NaN if it did not exist then).
  auto prev = [&](const std::vector<double>& a, std::size_t i) {
    const auto id = static_cast<std::size_t>(d.id[i]);
    return id < a.size() ? a[id] : kNaN;
  };
  // Largest displacement since the previous output relative to any touching disc.
  w.for_each_pair_contact([&](const PairContactView& p) {
    const auto i = p.first, j = p.second;
    // Skip pairs made stale by removals since the list was built.
    if (i >= d.size() || j >= d.size() || d.id[i] != p.id_first || d.id[j] != p.id_second) return;
    const double gap = std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]) - d.radius[i] - d.radius[j];
    if (gap > 0) return;
    const double ux = (d.x[j] - prev(prev_x_[0], j)) - (d.x[i] - prev(prev_x_[0], i));
    const double uy = (d.y[j] - prev(prev_y_[0], j)) - (d.y[i] - prev(prev_y_[0], i));
    const double u = std::hypot(ux, uy);
    if (!std::isfinite(u)) return;
    rel[i] = std::max(rel[i], u);
    rel[j] = std::max(rel[j], u);
  });
  for (std::size_t i = 0; i < d.size(); ++i) {
    dx3[i] = d.x[i] - prev(prev_x_[2], i);
    dy3[i] = d.y[i] - prev(prev_y_[2], i);
  }
  return {{"max_rel_disp", std::move(rel), "d",
           "largest displacement since the previous output relative to any touching disc"},
          {"disp3_x", std::move(dx3), "d", "displacement over the last three outputs, horizontal; NaN for younger discs"},
          {"disp3_y", std::move(dy3), "d", "displacement over the last three outputs, vertical; NaN for younger discs"}};
}

void DisplacementTracker::save(ArchiveWriter& out, const std::string& prefix) const {
  for (int k = 0; k < 3; ++k) {
    out.put(fmt::format("{}.prev_x{}", prefix, k), prev_x_[k]);
    out.put(fmt::format("{}.prev_y{}", prefix, k), prev_y_[k]);
  }
}

void DisplacementTracker::load(const ArchiveReader& in, const std::string& prefix) {
  for (int k = 0; k < 3; ++k) {
    in.get(fmt::format("{}.prev_x{}", prefix, k), prev_x_[k]);
    in.get(fmt::format("{}.prev_y{}", prefix, k), prev_y_[k]);
  }
}

}  // namespace orogen
