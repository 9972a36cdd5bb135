#include "experiments/biaxial_experiment.hpp"
#include "util/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/biaxial_walls.hpp"
#include "analysis/contact_stats.hpp"
#include "analysis/surface.hpp"
#include "config/config.hpp"
#include "experiments/series_table.hpp"
#include "experiments/layer_units.hpp"
#include "experiments/settled_layer.hpp"
#include "experiments/spec_from_config.hpp"

namespace orogen {
namespace {

constexpr std::uint64_t kCheckEvery = 200;            // steps per consolidation check window
constexpr double kTaperBases[] = {0.1, 0.2, 0.3};     // basal friction coefficients of the summary tapers

// Inward unit normals of the walls, in WallIndex order.
constexpr double kNormalX[] = {0, 0, 1, -1};
constexpr double kNormalY[] = {1, -1, 0, 0};

double sample_width(const World& w) {
  return w.wall("right").ax - w.wall("left").ax;
}
double sample_height(const World& w) {
  return w.wall("top").ay - w.wall("bottom").ay;
}

double mean_kinetic_energy(const World& w) {
  return w.discs().size() ? w.kinetic_energy() / static_cast<double>(w.discs().size()) / kUnitDiscMass : 0.0;
}

double solid_area(const Discs& d) {
  double a = 0;
  for (double r : d.radius) a += std::numbers::pi * r * r;
  return a;
}

}  // namespace

void BiaxialExperiment::setup(World& w) {
  // Settled frictionless (settle.mu, also through the packing's relax phase), like every packing.
  mu_ = w.friction();
  w.set_friction(spec_.settle.mu);
  PackingSpec p = spec_.packing;
  p.length = spec_.width;
  p.thickness = spec_.height;
  settle_layer(w, p, spec_.settle, /*apply_materials=*/false);  // materials once consolidated
  w.clear_removals();  // the trimmed excess never belonged to the sample

  // Gravity off; four smooth walls around the sample, long enough never to leave a gap at the
  // corners as the walls move.
  w.set_body_force({.gx = 0, .gy = 0, .drag = 0});
  double top = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) top = std::max(top, w.discs().y[i] + w.discs().radius[i]);
  const double W = spec_.width;
  Wall bottom{.name = "bottom", .ax = -0.5 * W, .ay = 0, .bx = 1.5 * W, .by = 0};
  Wall upper{.name = "top", .ax = -0.5 * W, .ay = top, .bx = 1.5 * W, .by = top};
  Wall left{.name = "left", .ax = 0, .ay = -0.5 * top, .bx = 0, .by = 1.5 * top};
  Wall right{.name = "right", .ax = W, .ay = -0.5 * top, .bx = W, .by = 1.5 * top};
  w.set_walls({bottom, upper, left, right});

  sigma3_code_ = spec_.sigma3 * kUnitDiscMass;
  phase_ = Consolidating;
  latest_ = output_sum_ = check_sum_ = {};
  output_steps_ = check_steps_ = 0;
  rows_.clear();
}

std::array<double, 4> BiaxialExperiment::wall_stresses(const World& w) const {
  const auto f = elastic_wall_forces(w);
  const double width = sample_width(w), height = sample_height(w);
  std::array<double, 4> s{};
  for (std::size_t k = 0; k < 4; ++k) {
    const WallForce& fk = f[w.wall_index(kWallNames[k])];
    const double load = -(fk.fx * kNormalX[k] + fk.fy * kNormalY[k]);
    s[k] = load / (k < kLeft ? width : height);
  }
  return s;
}

// A stress error e moves the wall outward at gain * e * d / (k_n dt): with one contact per d
// of wall and a rigid sample behind, that removes the fraction `gain` of the error in one step.
void BiaxialExperiment::servo(World& w, const std::array<double, 4>& s, bool top_too) const {
  const double per_stress = spec_.servo_gain * spec_.packing.d_max / (w.law().kn * w.dt());
  for (std::size_t k = top_too ? kTop : kLeft; k <= kRight; ++k) {
    const double out = per_stress * (s[k] - sigma3_code_);
    w.set_wall_velocity(kWallNames[k], -out * kNormalX[k], -out * kNormalY[k]);
  }
}

bool BiaxialExperiment::advance(World& w) {
  if (phase_ == Done) return false;
  // Set every step: a resumed run's engine configuration brings contact.mu back.
  w.set_friction(phase_ == Consolidating ? spec_.settle.mu : mu_);
  w.advance();
  latest_ = wall_stresses(w);
  for (std::size_t k = 0; k < 4; ++k) output_sum_[k] += latest_[k];
  ++output_steps_;

  if (phase_ == Consolidating) {
    servo(w, latest_, true);
    for (std::size_t k = 0; k < 4; ++k) check_sum_[k] += latest_[k];
    if (++check_steps_ < kCheckEvery) return true;
    // Consolidated when every wall's mean stress over the window is at the target and the
    // sample is at rest.
    bool steady = mean_kinetic_energy(w) < spec_.settle.ke_threshold;
    for (std::size_t k = 0; k < 4; ++k)
      steady = steady && std::fabs(check_sum_[k] / static_cast<double>(check_steps_) - sigma3_code_) <=
                             spec_.tolerance * sigma3_code_;
    check_sum_ = {};
    check_steps_ = 0;
    if (steady) {
      start_shearing(w);
    } else if (w.time() > spec_.settle.max_time) {
      throw InstabilityError(fmt::format("the biaxial sample did not consolidate to sigma3 = {} within "
                                         "settle.max_time = {} (mean kinetic energy per disc {:.3g} m g d)",
                                         spec_.sigma3, spec_.settle.max_time, mean_kinetic_energy(w)));
    }
    return true;
  }

  if (spec_.brazilian) {
    const double force = 0.5 * (latest_[kTop] + latest_[kBottom]) * sample_width(w);
    if (force > peak_force_) {
      peak_force_ = force;
      strain_at_peak_force_ = axial_strain(w);
    }
  } else {
    servo(w, latest_, false);
  }
  if (axial_strain(w) >= spec_.strain_end) {
    for (const auto name : kWallNames) w.set_wall_velocity(name, 0, 0);
    phase_ = Done;
    return false;
  }
  return true;
}

double BiaxialExperiment::cut_specimen(World& w) {
  const double left = w.wall("left").ax, right = w.wall("right").ax;
  const double bottom = w.wall("bottom").ay, top = w.wall("top").ay;
  const double cx = 0.5 * (left + right), cy = 0.5 * (bottom + top);
  const double radius = 0.5 * std::min(right - left, top - bottom);
  const Discs& d = w.discs();
  std::vector<std::uint8_t> outside(d.size());
  for (std::size_t i = 0; i < d.size(); ++i)
    outside[i] = std::hypot(d.x[i] - cx, d.y[i] - cy) + d.radius[i] > radius ? 1 : 0;
  w.remove(outside, RemovalReason::Other);
  for (const auto name : {kWallNames[kLeft], kWallNames[kRight]}) {
    w.set_wall_velocity(name, 0, 0);
    w.enable_wall(name, false);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < d.size(); ++i) {
    lo = std::min(lo, d.y[i] - d.radius[i]);
    hi = std::max(hi, d.y[i] + d.radius[i]);
  }
  for (const auto& [name, y] : {std::pair{kWallNames[kBottom], lo}, std::pair{kWallNames[kTop], hi}}) {
    const Wall& platen = w.wall(name);
    w.set_wall_ends(name, platen.ax, y, platen.bx, y);
    w.set_wall_velocity(name, 0, 0);
  }
  return hi - lo;
}

void BiaxialExperiment::start_shearing(World& w) {
  // The contacts of the consolidated sample (the Brazilian cut leaves the contact list to the
  // next step).
  coordination_start_ = measure_contacts(w).contacts_per_disc;
  // The Brazilian specimen is cut before it is bonded: no bond crosses the cut.
  h0_ = spec_.brazilian ? cut_specimen(w) : sample_height(w);
  a0_ = spec_.brazilian ? 0.25 * std::numbers::pi * h0_ * h0_ : sample_width(w) * h0_;
  solid_fraction_start_ = solid_area(w.discs()) / a0_;
  w.set_wall_velocity("top", 0, -spec_.strain_rate * h0_);  // constant speed: the strain rate is nominal (of H0)
  // Named materials: the sample is the first (no units: the whole sample), bonded now, at the
  // confining stress, as bonded samples are prepared (docs/materials.md, Calibration).
  if (spec_.material >= 0) w.set_layer_units({{static_cast<std::size_t>(spec_.material), spec_.height}});
  apply_units(w, 0, w.discs().size(), spec_.packing.seed);
  output_sum_ = {};
  output_steps_ = 0;
  phase_ = Shearing;
}

double BiaxialExperiment::axial_strain(const World& w) const {
  return phase_ == Consolidating ? 0.0 : (h0_ - sample_height(w)) / h0_;
}

std::array<double, 4> BiaxialExperiment::mean_stresses() const {
  if (output_steps_ == 0) return latest_;
  std::array<double, 4> s{};
  for (std::size_t k = 0; k < 4; ++k) s[k] = output_sum_[k] / static_cast<double>(output_steps_);
  return s;
}

BiaxialRow BiaxialExperiment::row(const World& w) const {
  const auto s = mean_stresses();
  BiaxialRow r;
  // Top and bottom (and the two sides) differ only by the sample's acceleration; their mean
  // cancels it to first order.
  r.sigma1 = 0.5 * (s[kTop] + s[kBottom]) / kUnitDiscMass;
  r.sigma3 = 0.5 * (s[kLeft] + s[kRight]) / kUnitDiscMass;
  if (phase_ != Consolidating) {
    r.axial_strain = axial_strain(w);
    r.vol_strain = spec_.brazilian ? std::numeric_limits<double>::quiet_NaN()
                                   : sample_width(w) * sample_height(w) / a0_ - 1.0;
  }
  return r;
}

namespace {

// One output's measurements, in the units of series.csv (kSeries names each field's column).
struct BiaxialSample {
  double step, time, phase, axial_strain, vol_strain, width, height, sigma1, sigma3, phi_deg, mu_mobilised,
      coordination, kinetic_energy, n_discs;
};

using Entry = SeriesEntry<BiaxialSample>;
constexpr std::array kSeries = {
    Entry{"step", "-", "model time step", &BiaxialSample::step},
    Entry{"time", "sqrt(d/g)", "model time since the sample was settled", &BiaxialSample::time},
    Entry{"phase", "-", "0 consolidating isotropically to sigma3, 1 shearing, 2 done", &BiaxialSample::phase},
    Entry{"axial_strain", "-", "axial shortening since shearing began, (H0 - H) / H0 (0 before)",
          &BiaxialSample::axial_strain},
    Entry{"vol_strain", "-",
          "area change since shearing began, (A - A0) / A0, positive when dilating (NaN in a Brazilian test)",
          &BiaxialSample::vol_strain},
    Entry{"width", "d", "distance between the side walls", &BiaxialSample::width},
    Entry{"height", "d", "distance between the top and bottom walls", &BiaxialSample::height},
    Entry{"sigma1", "m g / d^2",
          "axial stress: mean of the top and bottom wall forces per width, averaged since the previous output "
          "(a Brazilian test: the platen force is sigma1 x width)",
          &BiaxialSample::sigma1},
    Entry{"sigma3", "m g / d^2",
          "confining stress: mean of the side wall forces per height, averaged since the previous output",
          &BiaxialSample::sigma3},
    Entry{"phi_deg", "deg",
          "mobilised friction angle asin((sigma1 - sigma3) / (sigma1 + sigma3)) (NaN in a Brazilian test once loading)",
          &BiaxialSample::phi_deg},
    Entry{"mu_mobilised", "-", "tan(phi): the mobilised bulk friction coefficient", &BiaxialSample::mu_mobilised},
    Entry{"coordination", "-",
          "mean number of touching neighbours per disc (walls and discs of the same cluster excluded)",
          &BiaxialSample::coordination},
    Entry{"kinetic_energy", "m g d", "mean kinetic energy per disc", &BiaxialSample::kinetic_energy},
    Entry{"n_discs", "-", "number of discs", &BiaxialSample::n_discs},
};

}  // namespace

std::vector<SeriesColumn> BiaxialExperiment::columns() const { return series_columns(kSeries); }

std::vector<double> BiaxialExperiment::measure(const World& w) const {
  const BiaxialRow r = row(w);
  // The Brazilian specimen has no confinement: no mobilised friction to speak of.
  const double phi = spec_.brazilian && phase_ != Consolidating ? std::numeric_limits<double>::quiet_NaN()
                                                                 : mobilised_friction(r.sigma1, r.sigma3);
  const BiaxialSample sample{.step = static_cast<double>(w.step()),
                             .time = w.time(),
                             .phase = static_cast<double>(phase_),
                             .axial_strain = r.axial_strain,
                             .vol_strain = r.vol_strain,
                             .width = sample_width(w),
                             .height = sample_height(w),
                             .sigma1 = r.sigma1,
                             .sigma3 = r.sigma3,
                             .phi_deg = phi * kDegPerRad,
                             .mu_mobilised = std::tan(phi),
                             .coordination = measure_contacts(w).contacts_per_disc,
                             .kinetic_energy = mean_kinetic_energy(w),
                             .n_discs = static_cast<double>(w.discs().size())};
  return series_values(kSeries, sample);
}

void BiaxialExperiment::after_output(const World& w) {
  if (phase_ != Consolidating) rows_.push_back(row(w));
  output_sum_ = {};
  output_steps_ = 0;
  displacements_.remember(w);
}

BiaxialResults BiaxialExperiment::results() const {
  return analyse_biaxial(rows_, spec_.strain_end, spec_.residual_from, spec_.sigma3);
}

std::vector<SummaryValue> BiaxialExperiment::summary(const World& w) const {
  if (rows_.empty()) return {};
  if (spec_.brazilian) return brazilian_summary(w);
  const BiaxialResults r = results();
  // Inertial number of the residual flow, I = gamma_dot d sqrt(rho / p), with the shear rate
  // of an isochoric biaxial flow, 2 x the axial rate, and unit grain density.
  double p = 0;
  int n = 0;
  for (const auto& row : rows_)
    if (row.axial_strain >= spec_.residual_from * spec_.strain_end) { p += 0.5 * (row.sigma1 + row.sigma3); ++n; }
  p = n ? p / n * kUnitDiscMass : std::numeric_limits<double>::quiet_NaN();
  const double inertial = 2 * spec_.strain_rate * 2 * mean_radius(w.discs()) / std::sqrt(p);
  std::vector<SummaryValue> out = {
      {"phi_peak_deg", "peak mobilised friction angle [deg]", r.phi_peak * kDegPerRad},
      {"axial_strain_peak", "axial strain at the peak [-]", r.strain_at_peak},
      {"phi_residual_deg",
       fmt::format("mean mobilised friction angle beyond axial strain {:.4g} (residual state) [deg]",
                   spec_.residual_from * spec_.strain_end),
       r.phi_residual * kDegPerRad},
      {"mu_bulk_peak", "tan(phi_peak): peak bulk friction coefficient [-]", std::tan(r.phi_peak)},
      {"mu_bulk_residual", "tan(phi_residual): residual bulk friction coefficient [-]", std::tan(r.phi_residual)},
      {"dilatancy_peak", "d vol_strain / d axial_strain at the peak (positive: dilating) [-]", r.dilatancy_peak},
      {"psi_peak_deg", "dilatancy angle at the peak, asin(D / (2 + D)) [deg]", r.psi_peak * kDegPerRad},
      {"vol_strain_end", "area change at the end, (A - A0) / A0 [-]", rows_.back().vol_strain},
      {"sigma3", "target confining stress [m g / d^2]", spec_.sigma3},
      {"sigma3_mean", "mean measured confining stress while shearing [m g / d^2]", r.sigma3_mean},
      {"sigma3_max_dev", "largest |sigma3 - target| / target over the output steps while shearing [-]",
       r.sigma3_max_dev},
      {"solid_fraction_start", "disc area / sample area when shearing began [-]", solid_fraction_start_},
      {"coordination_start", "contacts per disc when shearing began (walls and discs of the same cluster excluded) [-]",
       coordination_start_},
      {"inertial_number", "2 x axial strain rate x mean diameter x sqrt(1 / mean stress) in the residual state; "
                          "quasi-static below about 1e-3 [-]",
       inertial},
      {"n_discs", "number of discs [-]", static_cast<double>(w.discs().size())}};
  // Critical taper of a dry, non-cohesive wedge on a flat base (MODEL §9) from each bulk friction.
  for (double mu_b : kTaperBases)
    for (const auto& [name, phi] : {std::pair{"residual", r.phi_residual}, std::pair{"peak", r.phi_peak}})
      out.push_back({fmt::format("taper_mub{}_{}_deg", mu_b, name),
                     fmt::format("critical surface slope for basal friction {} and the {} bulk friction (NaN: "
                                 "none, the base is not weaker) [deg]",
                                 mu_b, name),
                     critical_taper_or_nan(phi, mu_b) * kDegPerRad});
  return out;
}

// The Brazilian test (Hondros 1959; in 2-D, unit thickness): a disc of diameter D squeezed by a
// line load F across a diameter is in tension across that diameter at 2 F / (pi D).
std::vector<SummaryValue> BiaxialExperiment::brazilian_summary(const World& w) const {
  const double strength = 2 * peak_force_ / (std::numbers::pi * h0_);  // code units: rho g d
  return {{"tensile_strength", "2 F_peak / (pi D): the specimen's tensile strength [m g / d^2]",
           strength / kUnitDiscMass},
          {"tensile_strength_rho_g_d", "the same in the unit of the bond strengths [rho g d]", strength},
          {"peak_force", "largest platen force (mean of the two platens) of any step [m g]",
           peak_force_ / kUnitDiscMass},
          {"axial_strain_peak", "shortening of the diameter at the peak force, relative to D [-]",
           strain_at_peak_force_},
          {"diameter", "specimen diameter D when loading began [d]", h0_},
          {"bonds_broken", "bonds broken by the end [-]", static_cast<double>(w.bonds().breaks.size())},
          {"bonds_intact", "bonds intact at the end [-]", static_cast<double>(w.bonds().size())},
          {"sigma3", "consolidation stress before the cut [m g / d^2]", spec_.sigma3},
          {"solid_fraction_start", "disc area / specimen area when loading began [-]", solid_fraction_start_},
          {"coordination_start", "contacts per disc of the consolidated sample before the cut [-]",
           coordination_start_},
          {"n_discs", "number of discs [-]", static_cast<double>(w.discs().size())}};
}

void BiaxialExperiment::save(ArchiveWriter& out) const {
  state_fields(*this, ArchiveSaver(out));
  displacements_.save(out, "biaxial.disp");
}

void BiaxialExperiment::load(const ArchiveReader& in) {
  state_fields(*this, ArchiveLoader(in));
  displacements_.load(in, "biaxial.disp");
}

std::string BiaxialExperiment::status(const World& w) const {
  const auto s = latest_;
  const double s3 = 0.5 * (s[kLeft] + s[kRight]) / kUnitDiscMass;
  if (phase_ == Consolidating)
    return fmt::format("consolidating sigma3 {:.3g} KE/disc {:.2e}", s3, mean_kinetic_energy(w));
  const double s1 = 0.5 * (s[kTop] + s[kBottom]) / kUnitDiscMass;
  if (spec_.brazilian)
    return fmt::format("splitting strain {:.4f} platen force {:.3g} m g (peak {:.3g})", axial_strain(w),
                       s1 * sample_width(w), peak_force_ / kUnitDiscMass);
  return fmt::format("shearing strain {:.4f} phi {:.1f} deg sigma3 {:.3g}", axial_strain(w),
                     mobilised_friction(s1, s3) * kDegPerRad, s3);
}

double BiaxialExperiment::fraction_done(const World& w) const {
  if (phase_ == Consolidating) return 0.0;
  return std::min(1.0, axial_strain(w) / spec_.strain_end);
}

std::array<double, 4> BiaxialExperiment::view_box(const World&) const {
  return {-2.0, spec_.width + 2.0, -2.0, spec_.height + 2.0};
}

std::unique_ptr<Experiment> make_biaxial_experiment(const Config& c) {
  BiaxialSpec s;
  s.width = c.get_float("biaxial.width");
  s.height = c.get_float("biaxial.height");
  s.sigma3 = c.get_float("biaxial.sigma3");
  s.strain_rate = c.get_float("biaxial.strain_rate");
  s.strain_end = c.get_float("biaxial.strain_end");
  s.outputs = c.get_int32("biaxial.outputs");
  s.servo_gain = c.get_float("biaxial.servo_gain");
  s.brazilian = c.get_string("biaxial.test") == "brazilian";
  s.material = material_named_by(c, "biaxial.material");
  read_layer_keys(c, s);
  check_material_size(c, s.width, s.height, {"biaxial.width", "biaxial.height"});
  // Quasi-static: inertial number below 1e-2 even at the lowest mean stress, sigma3, for the
  // largest discs (MODEL's bulk friction is the rate-independent limit).
  const double inertial = 2 * s.strain_rate * s.packing.d_max / std::sqrt(s.sigma3 * kUnitDiscMass);
  if (inertial > 1e-2)
    throw config_error(c.sources_of({"biaxial.strain_rate", "biaxial.sigma3", "particles.d_max"}),
                       "biaxial.strain_rate", fmt::format("{}", s.strain_rate),
                       fmt::format("a quasi-static rate: inertial number 2 rate d sqrt(rho / sigma3) = {:.3g} is above "
                                   "1e-2 (use biaxial.strain_rate <= {:.3g}, or a larger biaxial.sigma3; from {})",
                                   inertial, s.strain_rate * 1e-2 / inertial,
                                   c.describe({"biaxial.sigma3", "particles.d_max"})));
  return std::make_unique<BiaxialExperiment>(std::move(s));
}

}  // namespace orogen
