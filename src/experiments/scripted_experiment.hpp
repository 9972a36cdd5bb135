#pragma once
// A scripted experiment: the geometry is written by the user (python/orogen: a `setup`
// function given to orogen.run or orogen.Simulation adds the discs and walls). The experiment
// itself starts from an empty world, takes plain World::advance() steps until scripted.duration
// and measures what any granular run has (time, disc count, kinetic energy, extent). Its
// checkpoint is the world alone: a resumed run never needs the setup function again.
#include "experiments/experiment.hpp"

namespace orogen {

struct ScriptedSpec {
  double duration = 0;  // model time the run lasts [sqrt(d/g)]
  int outputs = 1;      // output steps over it (after output 0)
};

class ScriptedExperiment final : public Experiment {
 public:
  explicit ScriptedExperiment(ScriptedSpec spec) : spec_(spec) {}

  void setup(World&) override {}  // empty: the user's setup function builds the geometry
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  std::optional<double> output_interval() const override { return spec_.duration / spec_.outputs; }
  void save(ArchiveWriter&) const override {}       // no state beyond the world
  void load(const ArchiveReader&) override {}
  std::string status(const World& world) const override;
  double fraction_done(const World& world) const override { return world.time() / spec_.duration; }
  double h0() const override { return 1.0; }  // no layer: lengths stay in d
  std::array<double, 4> view_box(const World& world) const override;

 private:
  ScriptedSpec spec_;
};

std::unique_ptr<Experiment> make_scripted_experiment(const Config& config);

}  // namespace orogen
