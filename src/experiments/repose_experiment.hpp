#pragma once
// Angle of repose experiments (thesis 3.2.1 and 3.2.2, MODEL §10). A square block of settled
// material in a box has its right wall opened:
//  - slump: the lowermost particles are fixed in space and the whole wall is removed;
//  - ledge: the base is a rough Coulomb wall and only the lower part of the wall stays, with
//    the particles touching it fixed (the alternative experiment, which adds internal
//    deformation of the pack as a second way to lower the slope).
// Particles that cross the open side are removed. When the material has come to rest, the
// surface profile is fitted with a straight line (the angle of repose) and a quadratic (its
// concavity).
#include "analysis/displacement_tracker.hpp"
#include "analysis/profile_fit.hpp"
#include "experiments/experiment.hpp"
#include "io/archive_fields.hpp"
#include "experiments/packing_experiment.hpp"

namespace orogen {

enum class ReposeVariant { Slump, Ledge };

struct ReposeSpec {
  ReposeVariant variant = ReposeVariant::Slump;
  double size = 40;              // side of the square block (d)
  double fixed_height = 1.0;     // slump: discs whose centre lies below this are fixed (d)
  double ledge_fraction = 0.2;   // ledge: the wall that stays, as a fraction of the block height
  double ke_threshold = 1e-5;    // at rest: mean kinetic energy per disc below this (m g d)
  double min_time = 20;          // no rest check before this time after opening
  double max_time = 3000;        // stop (not at rest) after this time
  double column_width_factor = 2.3;
  PackingSpec packing;
  SettleSpec settle;
};

class ReposeExperiment final : public Experiment {
 public:
  explicit ReposeExperiment(ReposeSpec spec) : spec_(std::move(spec)) {}

  void setup(World& world) override;
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  std::vector<SnapshotField> fields(const World& world) const override {
    return displacements_.fields(world);
  }
  void after_output(const World& world) override { displacements_.remember(world); }
  void save(ArchiveWriter& out) const override;
  void load(const ArchiveReader& in) override;
  std::vector<SummaryValue> summary(const World& world) const override;
  // Writes profile.csv: the surface columns at rest, which were fitted, and the fitted line.
  void finish(World& world, const std::filesystem::path& out_dir) override;
  std::string status(const World& world) const override;
  double fraction_done(const World& world) const override;
  double h0() const override { return spec_.size; }
  std::array<double, 4> view_box(const World& world) const override;

  // The fitted surface profile now (the slope region only: see docs/model.md).
  ProfileFit profile(const World& world) const;
  Surface surface(const World& world) const;
  bool at_rest() const { return at_rest_; }

 private:
  double mean_kinetic_energy(const World& world) const;
  void remove_escaped(World& world);

  ReposeSpec spec_;
  // The checkpointed state, each field once with its key, for save() and load()
  // (io/archive_fields.hpp).
  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("repose.top", self.top_);
    f("repose.base", self.base_);
    f("repose.rest_time", self.rest_time_);
    f("repose.at_rest", self.at_rest_);
    f("repose.initial_discs", self.initial_discs_);
  }

  double top_ = 0;       // mean surface height of the settled block
  double base_ = 0;      // height below which the profile is not fitted (fixed layer or lip)
  double rest_time_ = -1;
  bool at_rest_ = false;
  std::int64_t initial_discs_ = 0;
  DisplacementTracker displacements_;
};

std::unique_ptr<Experiment> make_repose_experiment(const Config& config);

}  // namespace orogen
