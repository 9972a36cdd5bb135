#pragma once
#include <array>
#include <string_view>
// The biaxial test (MODEL §9: the bulk friction angle phi of the particle material, which the
// critical taper needs, has to be measured): a settled sample in a box of four smooth walls,
// without gravity, first consolidated isotropically to the confining stress sigma_3, then
// shortened by the top wall at a constant slow speed while the side walls hold sigma_3. The
// mobilised friction angle asin((s1 - s3) / (s1 + s3)) gives the bulk friction at its peak and
// in the residual state, and from them the critical taper of a dry wedge. The Brazilian variant
// (biaxial.test) measures a bonded material's tensile strength instead: the consolidated sample
// cut to its inscribed disc and squeezed across a diameter between two platens.
#include <memory>

#include "analysis/biaxial_results.hpp"
#include "analysis/displacement_tracker.hpp"
#include "experiments/experiment.hpp"
#include "io/archive_fields.hpp"
#include "experiments/packing_experiment.hpp"

namespace orogen {

struct BiaxialSpec {
  double width = 30, height = 60;  // sample settled in a box this size (d)
  double sigma3 = 5;               // confining stress (m g / d^2, m the mass of a disc of diameter d)
  double strain_rate = 2.5e-4;      // axial strain rate of the top wall (per sqrt(d/g))
  double strain_end = 0.2;         // stop at this axial strain
  int outputs = 100;               // output steps over the shearing
  double servo_gain = 1.0;         // fraction of a wall's stress error removed per step (see docs)
  std::ptrdiff_t material = -1;    // the sample's material (index into the materials); -1: the units
  double tolerance = 0.01;         // consolidated: every wall stress within this of sigma3
  double residual_from = 2.0 / 3;  // residual state: beyond this fraction of strain_end
  bool brazilian = false;          // the Brazilian test (biaxial.test)
  PackingSpec packing;
  SettleSpec settle;
};

class BiaxialExperiment final : public Experiment {
 public:
  explicit BiaxialExperiment(BiaxialSpec spec) : spec_(std::move(spec)) {}

  void setup(World& world) override;
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  std::vector<SnapshotField> fields(const World& world) const override {
    return displacements_.fields(world);
  }
  void after_output(const World& world) override;
  std::optional<double> output_interval() const override {
    return spec_.strain_end / spec_.strain_rate / spec_.outputs;
  }
  void save(ArchiveWriter& out) const override;
  void load(const ArchiveReader& in) override;
  std::vector<SummaryValue> summary(const World& world) const override;
  std::string status(const World& world) const override;
  double fraction_done(const World& world) const override;
  double h0() const override { return spec_.height; }
  std::array<double, 4> view_box(const World& world) const override;

  enum Phase : int { Consolidating = 0, Shearing = 1, Done = 2 };
  Phase phase() const { return static_cast<Phase>(phase_); }
  // Axial strain since shearing began, (H0 - H) / H0.
  double axial_strain(const World& world) const;
  // The results so far (rows recorded at output steps while shearing).
  BiaxialResults results() const;

  // The four walls: their names (World::wall), in the order of the stress arrays.
  enum WallIndex : std::size_t { kBottom = 0, kTop = 1, kLeft = 2, kRight = 3 };
  static constexpr std::array<std::string_view, 4> kWallNames = {"bottom", "top", "left", "right"};

 private:
  // Compressive stresses on the four walls now, from their elastic contact forces (code units).
  std::array<double, 4> wall_stresses(const World& world) const;
  // Sets the velocity of each servoed wall from its stress error.
  void servo(World& world, const std::array<double, 4>& stress, bool top_too) const;
  void start_shearing(World& world);
  // The Brazilian test's specimen: the disc inscribed in the sample (diameter D, returned), the
  // side walls off, the top and bottom walls touching it as platens.
  double cut_specimen(World& world);
  // Stresses averaged over the steps since the last output (the latest ones if none).
  std::array<double, 4> mean_stresses() const;
  BiaxialRow row(const World& world) const;
  std::vector<SummaryValue> brazilian_summary(const World& world) const;
  // The checkpointed state, each field once with its key, for save() and load()
  // (io/archive_fields.hpp); the displacement tracker saves itself.
  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("biaxial.phase", self.phase_);
    f("biaxial.mu", self.mu_);
    f("biaxial.sigma3_code", self.sigma3_code_);
    f("biaxial.h0", self.h0_);
    f("biaxial.a0", self.a0_);
    f("biaxial.latest", self.latest_);
    f("biaxial.output_sum", self.output_sum_);
    f("biaxial.output_steps", self.output_steps_);
    f("biaxial.check_sum", self.check_sum_);
    f("biaxial.check_steps", self.check_steps_);
    f("biaxial.rows.axial_strain", column(self.rows_, &BiaxialRow::axial_strain));
    f("biaxial.rows.vol_strain", column(self.rows_, &BiaxialRow::vol_strain));
    f("biaxial.rows.sigma1", column(self.rows_, &BiaxialRow::sigma1));
    f("biaxial.rows.sigma3", column(self.rows_, &BiaxialRow::sigma3));
    f("biaxial.coordination_start", self.coordination_start_);
    f("biaxial.solid_fraction_start", self.solid_fraction_start_);
    if (self.spec_.brazilian) {
      f("biaxial.peak_force", self.peak_force_);
      f("biaxial.strain_at_peak_force", self.strain_at_peak_force_);
    }
  }

  BiaxialSpec spec_;
  int phase_ = Consolidating;
  double mu_ = 0.3;                    // the material's friction, switched on for shearing
  double sigma3_code_ = 0;             // target stress in code units (force per length)
  double h0_ = 0, a0_ = 0;             // height and area when shearing began
  std::array<double, 4> latest_{};     // wall stresses of the last step
  std::array<double, 4> output_sum_{};  // summed over the steps since the last output
  std::uint64_t output_steps_ = 0;
  std::array<double, 4> check_sum_{};  // summed over the current consolidation check window
  std::uint64_t check_steps_ = 0;
  std::vector<BiaxialRow> rows_;       // output rows while shearing, for the summary
  double coordination_start_ = 0, solid_fraction_start_ = 0;
  // The Brazilian test: the largest platen force of any step (mean of the two platens), and the
  // axial strain (of the diameter) it came at.
  double peak_force_ = 0, strain_at_peak_force_ = 0;
  DisplacementTracker displacements_;
};

std::unique_ptr<Experiment> make_biaxial_experiment(const Config& config);

}  // namespace orogen
