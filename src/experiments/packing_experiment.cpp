#include "experiments/packing_experiment.hpp"
#include "util/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/contact_stats.hpp"
#include "analysis/surface.hpp"
#include "config/config.hpp"
#include "experiments/series_table.hpp"
#include "experiments/spec_from_config.hpp"
#include "io/snapshot_writer.hpp"

namespace orogen {

namespace {
// Mass of a disc of diameter 1: the unit of mass (MODEL §1).
}  // namespace

void PackingExperiment::setup(World& w) {
  place_packing(w, packing_);
  w.set_drag(settle_.drag);
  mu_ = w.friction();
  phase_ = Falling;
  phase_start_time_ = 0;
}

double PackingExperiment::mean_kinetic_energy(const World& w) const {
  if (w.discs().size() == 0) return 0;
  return w.kinetic_energy() / static_cast<double>(w.discs().size()) / kUnitDiscMass;
}

bool PackingExperiment::advance(World& w) {
  if (phase_ == Done) return false;
  w.set_friction(phase_ < Relaxing ? settle_.mu : mu_);
  w.advance();
  if (w.step() % check_every_ != 0) return true;
  w.make_whole();  // the checks below read every disc (over ranks: every rank's state)
  if (w.time() > settle_.max_time)
    throw InstabilityError(fmt::format("the packing did not come to rest within settle.max_time = {} "
                                       "(mean kinetic energy per disc {:.3g} m g d, threshold {:.3g})",
                                       settle_.max_time, mean_kinetic_energy(w), settle_.ke_threshold));
  const bool at_rest = mean_kinetic_energy(w) < settle_.ke_threshold;
  switch (phase_) {
    case Falling:
      if (at_rest) {
        trim_to_thickness(w, packing_.thickness);
        phase_ = Resettling;
        phase_start_time_ = w.time();
      }
      break;
    case Resettling:
      if (at_rest) {
        w.set_drag(0);
        phase_ = Relaxing;
        phase_start_time_ = w.time();
      }
      break;
    case Relaxing:
      if (at_rest && w.time() - phase_start_time_ >= settle_.relax_time) {
        record_initial_state(w, 0.0, packing_.length, settle_.column_width_factor * mean_radius(w.discs()));
        phase_ = Done;
        w.set_friction(mu_);
        return false;
      }
      break;
    default: break;
  }
  return true;
}

namespace {

// One output's measurements, in the units of series.csv (kSeries names each field's column).
struct PackingSample {
  double step, time, phase, n_discs, n_clusters, kinetic_energy, contacts_per_disc, max_overlap, surface_mean;
};

using Entry = SeriesEntry<PackingSample>;
constexpr std::array kSeries = {
    Entry{"step", "-", "model time step", &PackingSample::step},
    Entry{"time", "sqrt(d/g)", "model time", &PackingSample::time},
    Entry{"phase", "-",
          "settling phase: 0 falling, 1 re-settling after trimming to the target thickness, 2 relaxing without drag, 3 "
          "done",
          &PackingSample::phase},
    Entry{"n_discs", "-", "number of discs", &PackingSample::n_discs},
    Entry{"n_clusters", "-", "number of rigid clusters", &PackingSample::n_clusters},
    Entry{"kinetic_energy", "m g d", "mean kinetic energy per disc", &PackingSample::kinetic_energy},
    Entry{"contacts_per_disc", "-", "mean number of touching neighbours per disc (walls excluded)",
          &PackingSample::contacts_per_disc},
    Entry{"max_overlap", "d", "largest disc-disc overlap", &PackingSample::max_overlap},
    Entry{"surface_mean", "d", "mean height of the upper surface", &PackingSample::surface_mean},
};

}  // namespace

std::vector<SeriesColumn> PackingExperiment::columns() const { return series_columns(kSeries); }

std::vector<double> PackingExperiment::measure(const World& w) const {
  const auto stats = measure_contacts(w);
  const Surface s = measure_surface(w.discs(), 0.0, packing_.length, settle_.column_width_factor * mean_radius(w.discs()));
  double sum = 0;
  int n = 0;
  for (double h : s.height)
    if (std::isfinite(h)) {
      sum += h;
      ++n;
    }
  const PackingSample sample{.step = static_cast<double>(w.step()),
                             .time = w.time(),
                             .phase = static_cast<double>(phase_),
                             .n_discs = static_cast<double>(w.discs().size()),
                             .n_clusters = static_cast<double>(w.clusters().size()),
                             .kinetic_energy = mean_kinetic_energy(w),
                             .contacts_per_disc = stats.contacts_per_disc,
                             .max_overlap = stats.max_overlap,
                             .surface_mean = n ? sum / n : 0.0};
  return series_values(kSeries, sample);
}

void PackingExperiment::save(ArchiveWriter& out) const { state_fields(*this, ArchiveSaver(out)); }

void PackingExperiment::load(const ArchiveReader& in) { state_fields(*this, ArchiveLoader(in)); }

void PackingExperiment::finish(World& w, const std::filesystem::path& out_dir) {
  // packing.h5: one snapshot of the settled layer plus what later runs need to know.
  SnapshotMetadata meta;
  meta.strings["content"] = "orogen-packing";
  meta.strings["packing"] = std::string(packing_kind_name(packing_.kind));
  meta.numbers["length"] = packing_.length;
  meta.numbers["thickness"] = packing_.thickness;
  meta.numbers["d_min"] = packing_.d_min;
  meta.numbers["d_max"] = packing_.d_max;
  meta.numbers["seed"] = static_cast<double>(packing_.seed);
  if (!config_toml_.empty()) meta.strings[kConfigAttr] = config_toml_;
  const Surface s = measure_surface(w.discs(), 0.0, packing_.length,
                                    settle_.column_width_factor * mean_radius(w.discs()));
  SnapshotFrame frame;
  frame.step = static_cast<std::int64_t>(w.step());
  frame.time = w.time();
  frame.discs = &w.discs();
  for (std::size_t k = 0; k < s.height.size(); ++k) frame.attrs[fmt::format("surface_{:05d}", k)] = s.height[k];
  frame.attrs["column_width"] = s.width;
  write_single_snapshot(out_dir / "packing.h5", meta, frame);
}

std::vector<SummaryValue> PackingExperiment::summary(const World& w) const {
  const auto stats = measure_contacts(w);
  const Surface s = measure_surface(w.discs(), 0.0, packing_.length,
                                    settle_.column_width_factor * mean_radius(w.discs()));
  // Column heights of the settled top: their mean is the layer's thickness, their spread its roughness.
  double sum = 0, sum2 = 0;
  int n = 0;
  for (double h : s.height)
    if (std::isfinite(h)) { sum += h; sum2 += h * h; ++n; }
  const double mean = n ? sum / n : 0.0;
  const double spread = n ? std::sqrt(std::max(0.0, sum2 / n - mean * mean)) : 0.0;
  // Cluster members touch without overlapping, so the disc areas add up to the solid area.
  double solid = 0;
  for (double r : w.discs().radius) solid += std::numbers::pi * r * r;
  const double bulk = packing_.length * mean;
  const double fraction = bulk > 0 ? solid / bulk : 0.0;
  return {{"time", "model time when the layer came to rest [sqrt(d/g)]", w.time()},
          {"steps", "time steps taken [-]", static_cast<double>(w.step())},
          {"n_discs", "number of discs [-]", static_cast<double>(w.discs().size())},
          {"n_clusters", "number of rigid clusters [-]", static_cast<double>(w.clusters().size())},
          {"thickness", "mean height of the upper surface: the settled layer's thickness [d]", mean},
          {"roughness", "standard deviation of the upper surface's column heights [d]", spread},
          {"solid_fraction", "disc area / (layer.length * thickness) [-]", fraction},
          {"porosity", "1 - solid_fraction [-]", 1.0 - fraction},
          {"contacts_per_disc", "mean number of touching neighbours per disc (walls excluded) [-]", stats.contacts_per_disc},
          {"max_overlap", "largest disc-disc overlap [d]", stats.max_overlap}};
}

std::string PackingExperiment::status(const World& w) const {
  static constexpr const char* kNames[] = {"falling", "re-settling", "relaxing", "done"};
  return fmt::format("{} KE/disc {:.2e}", kNames[phase_], mean_kinetic_energy(w));
}

std::array<double, 4> PackingExperiment::view_box(const World&) const {
  return {-1.0, packing_.length + 1.0, -1.0, 1.6 * packing_.thickness + 2.0};
}

std::unique_ptr<Experiment> make_packing_experiment(const Config& c) {
  check_material_size(c, c.get_float("layer.length"), c.get_float("layer.thickness"),
                      {"layer.length", "layer.thickness"});
  return std::make_unique<PackingExperiment>(packing_spec(c), settle_spec(c), c.to_toml());
}

}  // namespace orogen
