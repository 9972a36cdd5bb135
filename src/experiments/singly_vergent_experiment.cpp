#include "experiments/singly_vergent_experiment.hpp"
#include "util/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/surface.hpp"
#include "config/config.hpp"
#include "experiments/series_table.hpp"
#include "experiments/settled_layer.hpp"
#include "packing/packing.hpp"
#include "experiments/spec_from_config.hpp"
#include "experiments/surface_series.hpp"

namespace orogen {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint64_t kHousekeepingEvery = 100;
constexpr std::size_t kMaxGap = 2;  // surface columns below the raised level inside the wedge
constexpr std::string_view kBackstop = kBoxRight;  // the box's right wall; the left one is the far wall

}  // namespace

void SinglyVergentExperiment::setup(World& w) {
  PackingSpec p = spec_.packing;
  p.length = spec_.length;
  p.thickness = spec_.h0;
  settle_layer(w, p, spec_.settle);
  if (spec_.initial_slope > 0) cut_wedge(w);
  w.set_wall_friction(kBoxFloor, WallFriction::Rough, spec_.mu_b);
  w.set_wall_weakening(kBoxFloor, spec_.base_weakening);
  // Smooth, as the analytic and finite element solutions assume (thesis 3.2.3).
  const Wall backstop = w.wall(kBackstop);
  w.set_wall_friction(kBackstop, WallFriction::Smooth, backstop.mu);
  w.set_wall_velocity(kBackstop, -spec_.speed, backstop.vy);
  w.set_wall_ends(kBackstop, backstop.ax, backstop.ay, backstop.bx, std::max(backstop.by, 6.0 * spec_.h0 + 20.0));
  initial_discs_ = static_cast<std::int64_t>(w.discs().size());
  start_surface();
  surface_.ledger().entered = disc_area(w);
}

void SinglyVergentExperiment::start_surface() {
  constexpr int kSizes = 16;
  std::vector<double> radii;
  for (int k = 0; k < kSizes; ++k)
    radii.push_back(0.5 * (spec_.packing.d_min + (spec_.packing.d_max - spec_.packing.d_min) * (k + 0.5) / kSizes));
  SurfaceSpec s = spec_.surface;
  if (s.column_width <= 0) s.column_width = spec_.column_width_factor * 0.25 * (spec_.packing.d_min + spec_.packing.d_max);
  surface_ = SurfaceProcesses(std::move(s), radii, spec_.packing.seed);
}

bool SinglyVergentExperiment::set_surface_script(SurfaceScript script) {
  spec_.surface.script = script;
  surface_.set_script(std::move(script));
  return true;
}

// A wedge h0 high at the backstop whose surface falls at initial_slope towards the far wall
// (Buiter et al. 2016, experiment 1): the discs (whole clusters) whose centre is above that
// surface go, and the depths below the new surface are measured again.
void SinglyVergentExperiment::cut_wedge(World& w) {
  const double x_back = w.wall(kBackstop).ax, slope = std::tan(spec_.initial_slope);
  std::vector<std::uint8_t> above(w.discs().size(), 0);
  for (std::size_t i = 0; i < w.discs().size(); ++i)
    above[i] = w.discs().y[i] > spec_.h0 - slope * (x_back - w.discs().x[i]);
  w.remove(above, RemovalReason::Other);
  record_initial_state(w, 0.0, spec_.length, spec_.column_width_factor * mean_radius(w.discs()));
}

bool SinglyVergentExperiment::advance(World& w) {
  if (shortening(w) >= spec_.shortening) return false;
  w.advance();
  // The laws act between the far wall and the backstop.
  // Over ranks, the surface laws read and change the discs: every copy first gets the whole
  // state. Strays are found from the positions alone; removing them (rare) needs the whole state.
  if (surface_.updates_at(w)) {
    w.make_whole();
    surface_.update(w, 0.0, w.wall(kBackstop).ax, spec_.surface.every * w.dt());
  }
  if (w.step() % kHousekeepingEvery == 0) {
    w.gather_positions();
    if (const auto strays = stray_flags(w); any_flagged(strays)) {
      w.make_whole();
      remove_strays(w, strays);
    }
  }
  return true;
}

// A disc squeezed out through a wall's end would fall for ever.
std::vector<std::uint8_t> SinglyVergentExperiment::stray_flags(const World& w) const {
  const auto& d = w.discs();
  std::vector<std::uint8_t> flags(d.size(), 0);
  for (std::size_t i = 0; i < d.size(); ++i)
    flags[i] = d.y[i] < -2.0 || d.x[i] < -2.0 || d.x[i] > w.wall(kBackstop).ax + 2.0;
  return flags;
}

void SinglyVergentExperiment::remove_strays(World& w, std::span<const std::uint8_t> strays) {
  const double before = surface_.active() ? disc_area(w) : 0.0;
  w.remove(strays, RemovalReason::LeftDomain);
  if (surface_.active()) surface_.ledger().left += before - disc_area(w);
}

SinglyVergentShape SinglyVergentExperiment::shape(const World& w) const {
  SinglyVergentShape g;
  // The crust without the deposits (a filled foreland is not the wedge).
  const std::unique_ptr<Discs> crust = crust_discs(surface_, spec_.surface.deposition, w, {});
  const auto& d = crust ? *crust : w.discs();
  g.backstop = w.wall(kBackstop).ax;
  const Surface s = measure_surface(d, 0.0, g.backstop, spec_.column_width_factor * mean_radius(d));
  // The wedge: surface columns raised by a disc diameter, contiguous from the backstop (gaps of
  // up to kMaxGap columns are bridged); a detached pop-up further out is not part of it.
  const double raised = spec_.h0 + 1.5 * spec_.packing.d_max;
  double top = -std::numeric_limits<double>::infinity();
  std::size_t gap = 0;
  bool found = false;
  for (std::size_t k = s.height.size(); k-- > 0;) {
    const double h = s.height[k];
    if (std::isfinite(h) && h > raised) {
      g.front = s.column_centre(k) - 0.5 * s.width;
      top = std::max(top, h);
      found = true;
      gap = 0;
    } else if (found && ++gap > kMaxGap) {
      break;
    }
  }
  g.has_wedge = found && g.front < g.backstop - 1.0;
  if (!g.has_wedge) return g;
  g.height = top - spec_.h0;
  g.taper_mean = std::atan(g.height / (g.backstop - g.front));
  // The column at the backstop is dragged up the wall; it is left out of the fits.
  const double x_hi = g.backstop - spec_.packing.d_max, mid = 0.5 * (g.front + x_hi);
  const double inf = std::numeric_limits<double>::infinity();
  auto angle = [&](double lo, double hi) {
    const ProfileFit f = fit_profile(s, lo, hi, -inf, inf);
    return f.valid() ? std::atan(f.slope) : kNaN;
  };
  g.taper = angle(g.front, x_hi);
  g.taper_front = angle(g.front, mid);
  g.taper_back = angle(mid, x_hi);
  return g;
}

namespace {

// One output's measurements, in the units of series.csv (kSeries names each field's column).
struct SinglyVergentSample {
  double step, time, shortening, backstop, front, width, height, taper, taper_front, taper_back, taper_mean, slip_base,
      n_discs;
};

using Entry = SeriesEntry<SinglyVergentSample>;
constexpr std::array kSeries = {
    Entry{"step", "-", "model time step", &SinglyVergentSample::step},
    Entry{"time", "sqrt(d/g)", "model time since the backstop started", &SinglyVergentSample::time},
    Entry{"shortening", "-", "backstop displacement / h0", &SinglyVergentSample::shortening},
    Entry{"backstop", "h0", "x of the backstop", &SinglyVergentSample::backstop},
    Entry{"front", "h0",
          "deformation front: left end of the surface raised above h0 + 1.5 d_max, contiguous from the backstop",
          &SinglyVergentSample::front},
    Entry{"width", "h0", "wedge width: backstop minus front", &SinglyVergentSample::width},
    Entry{"height", "h0", "highest surface point of the wedge minus h0", &SinglyVergentSample::height},
    Entry{"taper", "deg", "wedge taper: least-squares slope of the surface from the front to the backstop",
          &SinglyVergentSample::taper},
    Entry{"taper_front", "deg", "least-squares surface slope over the front half of the wedge",
          &SinglyVergentSample::taper_front},
    Entry{"taper_back", "deg", "least-squares surface slope over the back half, next to the backstop",
          &SinglyVergentSample::taper_back},
    Entry{"taper_mean", "deg", "atan(height / width)", &SinglyVergentSample::taper_mean},
    Entry{"slip_base", "-", "fraction of touching basal contacts at the Coulomb limit",
          &SinglyVergentSample::slip_base},
    Entry{"n_discs", "-", "discs in the model", &SinglyVergentSample::n_discs},
};

}  // namespace

std::vector<SeriesColumn> SinglyVergentExperiment::columns() const {
  auto out = series_columns(kSeries);
  if (surface_.active()) {
    const auto ledger = ledger_columns(surface_);
    out.insert(out.end(), ledger.begin(), ledger.end());
  }
  return out;
}

std::vector<SnapshotField> SinglyVergentExperiment::fields(const World& w) const {
  auto out = displacements_.fields(w);
  if (spec_.surface.deposition) out.push_back(deposition_field(surface_, w));
  return out;
}

std::vector<double> SinglyVergentExperiment::measure(const World& w) const {
  const SinglyVergentShape g = shape(w);
  const WallContactStats base = w.wall_contact_stats(w.wall_index(kBoxFloor));
  const double h0 = spec_.h0;
  auto or_nan = [&](double v) { return g.has_wedge ? v : kNaN; };
  const SinglyVergentSample sample{.step = static_cast<double>(w.step()),
                                   .time = w.time(),
                                   .shortening = shortening(w),
                                   .backstop = g.backstop / h0,
                                   .front = or_nan(g.front / h0),
                                   .width = or_nan((g.backstop - g.front) / h0),
                                   .height = or_nan(g.height / h0),
                                   .taper = or_nan(g.taper * kDegPerRad),
                                   .taper_front = or_nan(g.taper_front * kDegPerRad),
                                   .taper_back = or_nan(g.taper_back * kDegPerRad),
                                   .taper_mean = or_nan(g.taper_mean * kDegPerRad),
                                   .slip_base = base.slip_fraction(),
                                   .n_discs = static_cast<double>(w.discs().size())};
  auto out = series_values(kSeries, sample);
  if (surface_.active())
    for (double v : ledger_values(surface_, w)) out.push_back(v);
  return out;
}

std::vector<std::pair<std::string, double>> SinglyVergentExperiment::scalars(const World& w) const {
  return {{"S", shortening(w)}};
}

void SinglyVergentExperiment::after_output(const World& w) {
  displacements_.remember(w);
  const SinglyVergentShape g = shape(w);
  history_s_.push_back(shortening(w));
  history_taper_.push_back(g.has_wedge ? g.taper * kDegPerRad : kNaN);
}

std::vector<SummaryValue> SinglyVergentExperiment::summary(const World& w) const {
  // Steady taper: mean and spread over the outputs after the transient.
  const double from = spec_.steady_from * spec_.shortening;
  double sum = 0, sum2 = 0, n = 0;
  for (std::size_t k = 0; k < history_s_.size(); ++k) {
    if (history_s_[k] < from || !std::isfinite(history_taper_[k])) continue;
    sum += history_taper_[k];
    sum2 += history_taper_[k] * history_taper_[k];
    n += 1;
  }
  const double mean = n > 0 ? sum / n : kNaN;
  const double sd = n > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1))) : kNaN;
  const SinglyVergentShape g = shape(w);
  auto or_nan = [&](double v) { return g.has_wedge ? v : kNaN; };
  return {{"taper_steady_deg", "mean wedge taper over the outputs after singly.steady_from of the run [deg]", mean},
          {"taper_steady_sd_deg", "standard deviation of the taper over those outputs [deg]", sd},
          {"taper_final_deg", "wedge taper at the end [deg]", or_nan(g.taper * kDegPerRad)},
          {"taper_front_final_deg", "surface slope over the front half of the wedge at the end [deg]",
           or_nan(g.taper_front * kDegPerRad)},
          {"taper_back_final_deg", "surface slope over the back half (at the backstop) at the end [deg]",
           or_nan(g.taper_back * kDegPerRad)},
          {"width_final", "wedge width at the end [h0]", or_nan((g.backstop - g.front) / spec_.h0)},
          {"height_final", "wedge height at the end [h0]", or_nan(g.height / spec_.h0)},
          {"shortening", "backstop displacement at the end [h0]", shortening(w)}};
}

void SinglyVergentExperiment::save(ArchiveWriter& out) const {
  state_fields(*this, ArchiveSaver(out));
  displacements_.save(out, "singly");
  if (surface_.active()) SurfaceProcesses::state_fields(surface_, ArchiveSaver(out));
}

void SinglyVergentExperiment::load(const ArchiveReader& in) {
  state_fields(*this, ArchiveLoader(in));
  displacements_.load(in, "singly");
  start_surface();
  if (surface_.active()) surface_.load_state(in);
}

// Surface laws switched on in a branch start their ledger from the branch's discs.
void SinglyVergentExperiment::adopt_branch_config(World& w) {
  if (surface_.active()) surface_.start_in_branch(w);
}

std::string SinglyVergentExperiment::status(const World& w) const {
  const SinglyVergentShape g = shape(w);
  return fmt::format("shortening {:.2f}/{:.1f} h0, taper {:.1f} deg", shortening(w), spec_.shortening,
                     g.has_wedge ? g.taper * kDegPerRad : 0.0);
}

std::array<double, 4> SinglyVergentExperiment::view_box(const World&) const {
  return {-1.0, spec_.length + 1.0, -1.0, std::max(4.0 * spec_.h0, 0.35 * spec_.length)};
}

std::unique_ptr<Experiment> make_singly_vergent_experiment(const Config& c) {
  SinglyVergentSpec s;
  s.h0 = c.get_float("layer.thickness");
  s.length = c.get_float("layer.length");
  s.speed = c.get_float("singly.speed");
  s.mu_b = c.get_float("singly.mu_b");
  s.base_weakening = base_weakening(c, "singly");
  s.shortening = c.get_float("singly.shortening");
  s.initial_slope = c.get_float("singly.initial_slope") / kDegPerRad;
  s.outputs = c.get_int32("singly.outputs");
  s.steady_from = c.get_float("singly.steady_from");
  read_layer_keys(c, s);
  s.surface = read_surface_keys(c, s.h0);
  check_material_size(c, s.length, s.h0, {"layer.length", "layer.thickness"});
  if (s.shortening * s.h0 > 0.8 * s.length)
    throw config_error(c.sources_of({"singly.shortening", "layer.length", "layer.thickness"}), "singly.shortening",
                       fmt::format("{}", s.shortening),
                       fmt::format("at most 0.8 layer.length / layer.thickness = {:.3g}: the backstop must stay "
                                   "well clear of the far wall (from {})",
                                   0.8 * s.length / s.h0, c.describe({"layer.length", "layer.thickness"})));
  // The backstop is not the constant-velocity base of eq. 4.3: above the bound the shortening
  // is faster than quasi-static, not unstable (docs/model.md); by default only a warning
  // (config_warnings).
  if (c.get_string("singly.speed_bound") == "refuse") check_imposed_speed(c, "singly.speed");
  return std::make_unique<SinglyVergentExperiment>(std::move(s));
}

}  // namespace orogen
