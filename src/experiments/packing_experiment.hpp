#pragma once
// The packing experiment (MODEL §10, first row): particles placed on a grid in a box settle
// under gravity, are trimmed to the target thickness and settle again. The result, with each
// particle's settled position and initial depth, is written to packing.h5 for later runs.
#include "experiments/experiment.hpp"
#include "io/archive_fields.hpp"
#include "packing/packing.hpp"

namespace orogen {

struct SettleSpec {
  double drag = 1.0;             // extra viscous drag rate while settling (1/time)
  double ke_threshold = 1e-6;    // mean kinetic energy per disc at rest (m g d)
  double max_time = 3000;        // give up after this model time
  double relax_time = 20;        // undamped time at the end
  double mu = 0.0;               // contact friction while falling and settling
  double column_width_factor = 2.3;
  // Thread tuning of the settling loop (run.adapt_threads, run.adapt_slice).
  bool adapt_threads = true;
  double adapt_slice = 2.0;
};

class PackingExperiment final : public Experiment {
 public:
  // `config_toml`: the resolved configuration, stored in packing.h5 (empty: none stored).
  PackingExperiment(PackingSpec packing, SettleSpec settle, std::string config_toml = {})
      : packing_(packing), settle_(settle), config_toml_(std::move(config_toml)) {}

  void setup(World& world) override;
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  void save(ArchiveWriter& out) const override;
  void load(const ArchiveReader& in) override;
  void finish(World& world, const std::filesystem::path& out_dir) override;
  std::vector<SummaryValue> summary(const World& world) const override;
  bool runs_over_ranks() const override { return true; }
  std::string status(const World& world) const override;
  double h0() const override { return packing_.thickness; }
  std::array<double, 4> view_box(const World& world) const override;

  // Settling phases, in order.
  enum Phase : int { Falling = 0, Resettling = 1, Relaxing = 2, Done = 3 };
  Phase phase() const { return static_cast<Phase>(phase_); }

 private:
  double mean_kinetic_energy(const World& world) const;

  PackingSpec packing_;
  SettleSpec settle_;
  std::string config_toml_;
  // The checkpointed state, each field once with its key, for save() and load()
  // (io/archive_fields.hpp).
  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("packing.phase", self.phase_);
    f("packing.phase_start_time", self.phase_start_time_);
    f("packing.mu", self.mu_);
  }

  int phase_ = Falling;
  double mu_ = 0.3;  // the material's friction (contact.mu), restored for the relax phase
  double phase_start_time_ = 0;
  std::uint64_t check_every_ = 200;  // steps between rest checks
};

// The packing experiment from the [layer], [particles] and [settle] keys.
std::unique_ptr<Experiment> make_packing_experiment(const Config& config);

}  // namespace orogen
