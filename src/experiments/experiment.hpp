#pragma once
// An experiment assembles engine parts from a configuration and adds its own stages and
// measurements around World::advance(). The run driver (run/runner) owns outputs,
// checkpoints and progress; an experiment only says what to simulate and what to measure.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/binary_archive.hpp"
#include "io/snapshot_field.hpp"
#include "surface/surface_spec.hpp"
#include "world/world.hpp"

namespace orogen {

class Config;

struct SeriesColumn {
  std::string name, description;
};

// One result of a finished run (summary.csv; `orogen sweep` tabulates these across runs).
struct SummaryValue {
  std::string name, description;
  double value;
};

// Work a run does beside its outputs (the exhumation analysis with analysis.in_run): called
// after each output with the number written so far, and once more when the run has finished.
using OutputObserver = std::function<void(std::int64_t outputs, bool finished)>;

class Experiment {
 public:
  virtual ~Experiment() = default;
  // Builds the initial world of a fresh run (and attaches, below).
  virtual void setup(World& world) = 0;
  // Adds the experiment's stage hooks to the world it runs (World::hooks); setup() calls it,
  // the run driver calls it again after load(). Adding a hook again replaces it.
  virtual void attach(World&) {}
  // Advances one step with the experiment's own stages; false once the experiment is done.
  virtual bool advance(World& world) = 0;
  // Columns of series.csv and one row of them for the current state.
  virtual std::vector<SeriesColumn> columns() const = 0;
  virtual std::vector<double> measure(const World& world) const = 0;
  // Extra per-disc fields stored in each snapshot (name, values by disc index).
  virtual std::vector<SnapshotField> fields(const World&) const { return {}; }
  // Scalars stored on each snapshot group (e.g. S).
  virtual std::vector<std::pair<std::string, double>> scalars(const World&) const { return {}; }
  // Called after each output step is written (e.g. to remember positions for the next one).
  virtual void after_output(const World&) {}
  // What the run driver calls beside the outputs of a run in `run_dir` (none by default).
  virtual std::vector<OutputObserver> output_observers(const std::filesystem::path& /*run_dir*/) const { return {}; }
  // Model time between output steps, if the experiment sets it (else output.interval).
  virtual std::optional<double> output_interval() const { return std::nullopt; }
  // Pictures shade material that started at x0 < x_split apart (NaN: no split).
  virtual double x_split() const { return std::numeric_limits<double>::quiet_NaN(); }
  // Gives the run a user's surface law (docs/surface.md), run after the [surface] keys' laws at
  // each surface update; false where the experiment has no surface processes.
  virtual bool set_surface_script(SurfaceScript) { return false; }
  // Experiment state beyond the World, for checkpoints.
  virtual void save(ArchiveWriter& out) const = 0;
  virtual void load(const ArchiveReader& in) = 0;
  // A branch (orogen run --from) has loaded another run's state: put this run's values of the
  // keys a branch may change back where the state holds them (a wedge's basal friction), and
  // start what the source ran without (surface laws switched on in the branch).
  virtual void adopt_branch_config(World&) {}
  // Work after the last step (e.g. writing the packing file).
  virtual void finish(World&, const std::filesystem::path& /*out_dir*/) {}
  // The run's results, written to summary.csv after finish() (none: no file).
  virtual std::vector<SummaryValue> summary(const World&) const { return {}; }
  // Whether a run over MPI ranks may step it: its stages gather the world (World::make_whole)
  // before they read or change the discs. The others (the small samples: piles, the biaxial
  // test) are refused over ranks with a named error.
  virtual bool runs_over_ranks() const { return false; }
  // Short status for the progress line, and the fraction done (negative if unknown).
  virtual std::string status(const World& world) const = 0;
  virtual double fraction_done(const World&) const { return -1.0; }
  // Rendering hints: layer thickness and the view box of the pictures.
  virtual double h0() const = 0;
  virtual std::array<double, 4> view_box(const World& world) const = 0;
};

// The experiment named by run.experiment; cross-key checks throw ConfigError.
std::unique_ptr<Experiment> make_experiment(const Config& config);

// Applies the [contact], [time] and [neighbor] sections to a world (stiffness, damping,
// friction, time step with its stability check, skin).
void apply_engine_config(const Config& config, World& world);

}  // namespace orogen
