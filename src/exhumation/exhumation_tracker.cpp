#include "exhumation/exhumation_tracker.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unordered_set>

#include "analysis/surface.hpp"
#include "particles/discs.hpp"

namespace orogen {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

ExhumationTracker::ExhumationTracker(ExhumationParams params) : p_(std::move(params)) {
  const std::size_t cells = p_.closure.size() * p_.n_columns;
  prev_surface_age_.assign(cells, kNaN);
  jump_total_.assign(cells, 0.0);
  jump_count_.assign(cells, 0);
  cum_area_.assign(p_.n_columns, 0.0);
  cum_count_.assign(p_.n_columns, 0);
}

void ExhumationTracker::check_loaded() const {
  const std::size_t cells = p_.closure.size() * p_.n_columns;
  if (prev_surface_age_.size() != cells || jump_total_.size() != cells || jump_count_.size() != cells ||
      cum_area_.size() != p_.n_columns || cum_count_.size() != p_.n_columns)
    throw std::runtime_error("column arrays of the wrong length");
}

void ExhumationTracker::record_erosion(std::span<const ErosionEvent> eroded, OutputRecord& r) {
  const std::size_t nc = p_.closure.size();
  for (const auto& e : eroded) {
    ErodedParticle ep;
    ep.event = e;
    ep.age.assign(nc, kNaN);
    ep.unreset.assign(nc, 0);
    ep.radius = p_.mean_radius;
    ep.depth = ep.max_depth = kNaN;
    if (const auto it = particles_.find(e.id); it != particles_.end()) {
      const Particle& q = it->second;
      ep.radius = q.radius;
      ep.last_output = q.last_output;
      ep.depth = q.ages.depth();
      ep.max_depth = q.ages.max_depth();
      for (std::size_t i = 0; i < nc; ++i) {
        ep.age[i] = q.ages.age(i);
        ep.unreset[i] = q.ages.unreset(i);
      }
      particles_.erase(it);
    }
    const double k = std::floor((e.x - p_.x_lo) / p_.column_width);
    const double area = std::numbers::pi * ep.radius * ep.radius;
    if (k >= 0 && k < static_cast<double>(p_.n_columns)) {
      ep.column = static_cast<std::int64_t>(k);
      cum_area_[static_cast<std::size_t>(k)] += area;
      ++cum_count_[static_cast<std::size_t>(k)];
    }
    r.eroded_area += area;
    ++r.eroded_count;
    eroded_.push_back(std::move(ep));
  }
}

OutputRecord ExhumationTracker::observe(const OutputDiscs& out, std::span<const ErosionEvent> eroded) {
  const std::size_t nc = p_.closure.size(), ncol = p_.n_columns, n = out.id.size();
  OutputRecord r;
  r.step = out.step;
  r.time = out.time;
  r.S = out.S;
  record_erosion(eroded, r);

  // The surface of this output on the fixed grid (the wedge's own surface code).
  Discs d;
  d.x = out.x;
  d.y = out.y;
  d.radius = out.radius;
  d.id = out.id;
  const Surface s = measure_surface(d, p_.x_lo, p_.x_lo + static_cast<double>(ncol) * p_.column_width,
                                    p_.column_width);

  // Particles gone without an erosion record (left the domain) leave the statistics.
  std::unordered_set<std::int64_t> present(out.id.begin(), out.id.end());
  std::erase_if(particles_, [&](const auto& kv) { return !present.contains(kv.first); });

  for (std::size_t j = 0; j < n; ++j) {
    auto [it, added] = particles_.try_emplace(out.id[j]);
    Particle& q = it->second;
    if (added) q.ages = ClosureAges(nc);
    q.radius = out.radius[j];
    q.last_output = outputs_;
    const double x = out.x[j];
    const bool inside = x >= p_.x_lo && x < p_.x_lo + static_cast<double>(ncol) * p_.column_width;
    const double depth = inside ? (s.at(x) - out.y[j]) / p_.h0 : kNaN;
    q.ages.observe(out.time, depth, p_.closure);
    if (out.id[j] % p_.particle_stride == 0) {
      r.particle_id.push_back(out.id[j]);
      r.particle_x.push_back(static_cast<float>(x / p_.h0));
      r.particle_y.push_back(static_cast<float>(out.y[j] / p_.h0));
      r.particle_depth.push_back(static_cast<float>(depth));
      r.particle_max_depth.push_back(static_cast<float>(q.ages.max_depth()));
      r.particle_deposition_time.push_back(out.deposition_time.empty() ? kNaN : out.deposition_time[j]);
    }
  }
  // Ages of the kept particles, closure-major.
  const std::size_t kept = r.particle_id.size();
  r.particle_age.resize(nc * kept);
  for (std::size_t m = 0; m < kept; ++m) {
    const ClosureAges& a = particles_.at(r.particle_id[m]).ages;
    for (std::size_t i = 0; i < nc; ++i) r.particle_age[i * kept + m] = static_cast<float>(a.age(i));
  }

  r.elevation.assign(ncol, kNaN);
  r.top_max_depth.assign(ncol, kNaN);
  r.top_id.assign(ncol, -1);
  r.surface_age.assign(nc * ncol, kNaN);
  r.surface_unreset.assign(nc * ncol, 0);
  for (std::size_t c = 0; c < ncol; ++c) {
    r.elevation[c] = s.height[c] / p_.h0;
    r.top_id[c] = s.top[c];
    if (s.top[c] < 0) continue;
    const ClosureAges& a = particles_.at(s.top[c]).ages;
    r.top_max_depth[c] = a.max_depth();
    for (std::size_t i = 0; i < nc; ++i) {
      const std::size_t cell = i * ncol + c;
      r.surface_age[cell] = a.age(i);
      r.surface_unreset[cell] = a.unreset(i);
    }
  }
  // A jump: the surface of a column younger than at the previous output.
  for (std::size_t cell = 0; cell < nc * ncol; ++cell) {
    const double now = r.surface_age[cell], before = prev_surface_age_[cell];
    if (now < before) {
      ++jump_count_[cell];
      jump_total_[cell] += before - now;
    }
    prev_surface_age_[cell] = now;
  }
  record_deposits(out, r);
  r.jump_count = jump_count_;
  r.jump_total = jump_total_;
  r.cum_eroded_area = cum_area_;
  r.cum_eroded_count = cum_count_;
  ++outputs_;
  last_step_ = out.step;
  return r;
}

// The sediment in each column (discs with a deposition time, by centre): its thickness, the
// discs' area over the column width, and its area-weighted mean age. Basin stratigraphy at any
// output is the deposits' positions there with analysis.h5's deposition_time.
void ExhumationTracker::record_deposits(const OutputDiscs& out, OutputRecord& r) const {
  const std::size_t ncol = p_.n_columns;
  std::vector<double> area(ncol, 0.0), age(ncol, 0.0);
  for (std::size_t j = 0; j < out.deposition_time.size(); ++j) {
    if (std::isnan(out.deposition_time[j])) continue;
    const double c = std::floor((out.x[j] - p_.x_lo) / p_.column_width);
    if (c < 0 || c >= static_cast<double>(ncol)) continue;
    const double a = std::numbers::pi * out.radius[j] * out.radius[j];
    area[static_cast<std::size_t>(c)] += a;
    age[static_cast<std::size_t>(c)] += a * (out.time - out.deposition_time[j]);
  }
  r.deposit_thickness.resize(ncol);
  r.deposit_age.resize(ncol);
  for (std::size_t c = 0; c < ncol; ++c) {
    r.deposit_thickness[c] = area[c] / p_.column_width / p_.h0;
    r.deposit_age[c] = area[c] > 0 ? age[c] / area[c] : kNaN;
  }
}

}  // namespace orogen
