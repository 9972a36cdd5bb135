#include "experiments/repose_experiment.hpp"
#include "util/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/contact_stats.hpp"
#include "config/config.hpp"
#include "experiments/series_table.hpp"
#include "experiments/settled_layer.hpp"
#include "experiments/spec_from_config.hpp"
#include "io/atomic_file.hpp"
#include "world/hold.hpp"

namespace orogen {
namespace {

constexpr std::uint64_t kCheckEvery = 100;  // steps between removal and rest checks

}  // namespace

void ReposeExperiment::setup(World& w) {
  PackingSpec p = spec_.packing;
  p.length = spec_.size;
  p.thickness = spec_.size;
  settle_layer(w, p, spec_.settle);
  const Surface s = measure_surface(w.discs(), 0.0, spec_.size, spec_.column_width_factor * mean_radius(w.discs()));
  double sum = 0;
  int n = 0;
  for (double h : s.height)
    if (std::isfinite(h)) { sum += h; ++n; }
  top_ = n ? sum / n : spec_.size;

  auto& d = w.discs();
  std::vector<std::uint8_t> fix(d.size(), 0);
  if (spec_.variant == ReposeVariant::Slump) {
    // The whole right wall goes; the lowermost particles are held so the block cannot slide out.
    w.enable_wall(kBoxRight, false);
    for (std::size_t i = 0; i < d.size(); ++i) fix[i] = d.y[i] < spec_.fixed_height;
    base_ = spec_.fixed_height + spec_.packing.d_max;
  } else {
    // The lower part of the wall stays, and the particles touching it are fixed (thesis 3.2.2).
    const double lip = spec_.ledge_fraction * top_;
    const Wall& right = w.wall(kBoxRight);
    w.set_wall_ends(kBoxRight, right.ax, right.ay, right.bx, lip);
    for (std::size_t i = 0; i < d.size(); ++i)
      fix[i] = d.y[i] < lip && d.x[i] + d.radius[i] > spec_.size - 0.05 * spec_.packing.d_min;
    base_ = lip + spec_.packing.d_max;
  }
  hold_at_rest(w, fix);
  initial_discs_ = static_cast<std::int64_t>(d.size());
}

double ReposeExperiment::mean_kinetic_energy(const World& w) const {
  if (w.discs().size() == 0) return 0;
  return w.kinetic_energy() / static_cast<double>(w.discs().size()) / kUnitDiscMass;
}

// Particles that crossed the open side (or fell below the floor's end) leave the system.
void ReposeExperiment::remove_escaped(World& w) {
  const auto& d = w.discs();
  std::vector<std::uint8_t> flags(d.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < d.size(); ++i) {
    flags[i] = d.x[i] > spec_.size || d.y[i] < -2.0;
    any |= flags[i] != 0;
  }
  if (any) w.remove(flags, RemovalReason::LeftDomain);
}

bool ReposeExperiment::advance(World& w) {
  if (at_rest_) return false;
  w.advance();
  if (w.step() % kCheckEvery != 0) return true;
  remove_escaped(w);
  if (w.time() < spec_.min_time) return true;
  if (mean_kinetic_energy(w) < spec_.ke_threshold) {
    at_rest_ = true;
    rest_time_ = w.time();
    return false;
  }
  return w.time() < spec_.max_time;
}

Surface ReposeExperiment::surface(const World& w) const {
  return measure_surface(w.discs(), 0.0, spec_.size, spec_.column_width_factor * mean_radius(w.discs()));
}

ProfileFit ReposeExperiment::profile(const World& w) const {
  const Surface s = surface(w);
  // The slope: columns lowered by more than a disc below the settled top, and above the fixed
  // layer (slump) or the lip (ledge); the untouched plateau and the floor are not the slope.
  return fit_profile(s, 0.0, spec_.size, base_, top_ - 1.5 * spec_.packing.d_max);
}

namespace {

// One output's measurements, in the units of series.csv (kSeries names each field's column).
struct ReposeSample {
  double step, time, n_discs, n_removed, kinetic_energy, contacts_per_disc, angle, angle_r2, angle_rms, concavity,
      slope_x_lo, slope_x_hi, n_columns;
};

using Entry = SeriesEntry<ReposeSample>;
constexpr std::array kSeries = {
    Entry{"step", "-", "model time step", &ReposeSample::step},
    Entry{"time", "sqrt(d/g)", "model time since the wall was opened", &ReposeSample::time},
    Entry{"n_discs", "-", "discs in the box", &ReposeSample::n_discs},
    Entry{"n_removed", "-", "discs that left through the open side so far", &ReposeSample::n_removed},
    Entry{"kinetic_energy", "m g d", "mean kinetic energy per disc", &ReposeSample::kinetic_energy},
    Entry{"contacts_per_disc", "-", "mean number of touching neighbours per disc (walls excluded)",
          &ReposeSample::contacts_per_disc},
    Entry{"angle", "deg", "surface slope: least-squares line through the slope columns, descending to the open side",
          &ReposeSample::angle},
    Entry{"angle_r2", "-", "coefficient of determination of that line", &ReposeSample::angle_r2},
    Entry{"angle_rms", "d", "root-mean-square distance of the slope columns from that line", &ReposeSample::angle_rms},
    Entry{"concavity", "deg",
          "descent angle of a quadratic fit at the top of the slope minus at its foot; > 0 concave, ~0 planar",
          &ReposeSample::concavity},
    Entry{"slope_x_lo", "d", "left end of the fitted slope (column centre)", &ReposeSample::slope_x_lo},
    Entry{"slope_x_hi", "d", "right end of the fitted slope (column centre)", &ReposeSample::slope_x_hi},
    Entry{"n_columns", "-", "surface columns on the slope used by the fits", &ReposeSample::n_columns},
};

}  // namespace

std::vector<SeriesColumn> ReposeExperiment::columns() const { return series_columns(kSeries); }

std::vector<double> ReposeExperiment::measure(const World& w) const {
  const ProfileFit f = profile(w);
  const auto stats = measure_contacts(w);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<std::int64_t>(w.discs().size());
  const ReposeSample sample{.step = static_cast<double>(w.step()),
                            .time = w.time(),
                            .n_discs = static_cast<double>(n),
                            .n_removed = static_cast<double>(initial_discs_ - n),
                            .kinetic_energy = mean_kinetic_energy(w),
                            .contacts_per_disc = stats.contacts_per_disc,
                            .angle = f.valid() ? -std::atan(f.slope) * kDegPerRad : nan,
                            .angle_r2 = f.valid() ? f.r2 : nan,
                            .angle_rms = f.valid() ? f.rms : nan,
                            .concavity = f.valid() ? f.concavity * kDegPerRad : nan,
                            .slope_x_lo = f.valid() ? f.x_lo : nan,
                            .slope_x_hi = f.valid() ? f.x_hi : nan,
                            .n_columns = static_cast<double>(f.n)};
  return series_values(kSeries, sample);
}

std::vector<SummaryValue> ReposeExperiment::summary(const World& w) const {
  const ProfileFit f = profile(w);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<double>(w.discs().size());
  return {{"angle_deg", "angle of repose: slope of the straight-line fit of the surface at rest [deg]",
           f.valid() ? -std::atan(f.slope) * kDegPerRad : nan},
          {"angle_r2", "coefficient of determination of that line [-]", f.valid() ? f.r2 : nan},
          {"angle_rms", "root-mean-square residual of that line [d]", f.valid() ? f.rms : nan},
          {"concavity_deg", "slope at the top minus slope at the foot of a quadratic fit; > 0 concave [deg]",
           f.valid() ? f.concavity * kDegPerRad : nan},
          {"slope_length", "horizontal extent of the fitted slope [d]", f.valid() ? f.x_hi - f.x_lo : nan},
          {"removed_fraction", "fraction of the discs that left the box [-]", 1.0 - n / static_cast<double>(initial_discs_)},
          {"at_rest", "1 if the material came to rest, 0 if repose.max_time ended the run [-]", at_rest_ ? 1.0 : 0.0},
          {"time_to_rest", "model time from opening to rest [sqrt(d/g)]", at_rest_ ? rest_time_ : w.time()}};
}

void ReposeExperiment::finish(World& w, const std::filesystem::path& out_dir) {
  const Surface s = surface(w);
  const ProfileFit f = profile(w);
  const double y_hi = top_ - 1.5 * spec_.packing.d_max;
  std::string text = "# Surface profile at rest: columns of the surface (x: column centre, height: top of its highest disc),\n"
                     "# fitted: 1 where the column is on the slope and was fitted, line: the fitted straight line there.\n"
                     "x,height,fitted,line\n";
  for (std::size_t k = 0; k < s.height.size(); ++k) {
    const double x = s.column_centre(k), h = s.height[k];
    const bool fitted = f.valid() && std::isfinite(h) && h > base_ && h < y_hi;
    text += fmt::format("{},{},{},{}\n", x, h, fitted ? 1 : 0, f.valid() ? f.intercept + f.slope * x : std::nan(""));
  }
  write_file_atomically(out_dir / "profile.csv", text);
}

void ReposeExperiment::save(ArchiveWriter& out) const {
  state_fields(*this, ArchiveSaver(out));
  displacements_.save(out, "repose");
}

void ReposeExperiment::load(const ArchiveReader& in) {
  state_fields(*this, ArchiveLoader(in));
  displacements_.load(in, "repose");
}

std::string ReposeExperiment::status(const World& w) const {
  return fmt::format("{} discs, KE/disc {:.2e}", w.discs().size(), mean_kinetic_energy(w));
}

double ReposeExperiment::fraction_done(const World& w) const {
  // Unknown until rest; the kinetic energy falls towards the threshold over decades.
  const double ke = mean_kinetic_energy(w);
  if (w.time() < spec_.min_time || ke <= 0) return -1.0;
  return std::clamp(std::log(ke) / std::log(spec_.ke_threshold), 0.0, 0.99);
}

std::array<double, 4> ReposeExperiment::view_box(const World&) const {
  return {-1.0, spec_.size + 0.25 * spec_.size, -1.0, spec_.size + 2.0};
}

namespace {

// The angle is fitted to the surface columns between the base (the fixed layer or the lip, plus
// a disc) and 1.5 discs below the top; with less than kMinSlopeHeight between them too few
// columns remain and the angle would be NaN.
constexpr double kMinSlopeHeight = 3.0;

void check_slope_height(const Config& c, const ReposeSpec& s) {
  const double d = s.packing.d_max;
  const bool slump = s.variant == ReposeVariant::Slump;
  const double base = slump ? s.fixed_height : s.ledge_fraction * s.size;
  const double height = s.size - 1.5 * d - (base + d);
  if (height >= kMinSlopeHeight) return;
  const std::vector<std::string_view> keys = {"repose.size", slump ? "repose.fixed_height" : "repose.ledge_fraction",
                                              "particles.d_max", "repose.variant"};
  throw config_error(c.sources_of(keys), "repose.size", format_value(ConfigValue{s.size}),
                     fmt::format("leaves {:.3g} d of slope between the {} and the top, where the angle needs at "
                                 "least {} d (a larger repose.size, or a lower {}); from {}",
                                 height, slump ? "fixed layer" : "lip of the wall", kMinSlopeHeight,
                                 slump ? "repose.fixed_height" : "repose.ledge_fraction", c.describe(keys)));
}

}  // namespace

std::unique_ptr<Experiment> make_repose_experiment(const Config& c) {
  ReposeSpec s;
  s.variant = c.get_string("repose.variant") == "ledge" ? ReposeVariant::Ledge : ReposeVariant::Slump;
  s.size = c.get_float("repose.size");
  s.fixed_height = c.get_float("repose.fixed_height");
  s.ledge_fraction = c.get_float("repose.ledge_fraction");
  s.ke_threshold = c.get_float("repose.ke_threshold");
  s.min_time = c.get_float("repose.min_time");
  s.max_time = c.get_float("repose.max_time");
  read_layer_keys(c, s);
  if (s.max_time <= s.min_time)
    throw config_error(c.sources_of({"repose.max_time", "repose.min_time"}), "repose.max_time",
                       fmt::format("{}", s.max_time),
                       fmt::format("a time after repose.min_time ({})", c.describe({"repose.min_time"})));
  check_material_size(c, s.size, s.size, {"repose.size"});
  check_slope_height(c, s);
  return std::make_unique<ReposeExperiment>(std::move(s));
}

}  // namespace orogen
