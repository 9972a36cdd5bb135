#pragma once
// One run of the run driver (`orogen run`): a run folder's world, experiment and outputs. Its
// pieces are files of their own: starting it (run_start.cpp: a new run, a resume, a branch,
// the replay of a branch's source), the loop (run_loop.cpp: stepping, signals, thread tuning,
// the between-steps hook) and the outputs (run_outputs.cpp: snapshots, series, summary,
// removals, checkpoints, in-run analysis). runner.cpp turns `orogen run`'s options into one.
#include <spdlog/spdlog.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/contact_output.hpp"
#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "io/binary_archive.hpp"
#include "io/csv_series.hpp"
#include "io/snapshot_reader.hpp"
#include "io/snapshot_writer.hpp"
#include "run/branch_source.hpp"
#include "run/progress.hpp"
#include "run/runner.hpp"
#include "util/command_error.hpp"
#include "world/world.hpp"

namespace orogen {

// A command line that cannot run as given (exit 2).
struct UsageError : BadInput {
  using BadInput::BadInput;
};

// The key that counts the outputs over a run whose end is `end_key` (the schema's OutputCount
// key of the same section: wedge.outputs for wedge.s_end).
std::string output_count_key(const std::string& end_key);

// "SIGINT" or "SIGTERM", for the log.
const char* signal_name(int sig);

// [output] contacts, stress and stress_grid, checked.
ContactOutputOptions contact_output_options(const Config& config);

// Everything the driver itself must carry across a checkpoint.
struct RunState {
  std::int64_t outputs = 0;          // output steps written
  std::vector<double> output_times;  // for run.pvd
  // Per output, the digest of its .vtp file (0: none written), so that a resume recognises
  // a file of another run; empty in checkpoints written before digests were kept.
  std::vector<std::uint64_t> vtp_digests;
  bool finished = false;
};

class Run {
 public:
  // `settings`, where given, holds this process's keys of speed and display (a resume's own
  // --set of them); `config` is the run's configuration, stored with its outputs.
  Run(const Config& config, std::filesystem::path dir, std::unique_ptr<Experiment> experiment,
      const Config* settings = nullptr);

  // Builds the initial state and writes nothing, so that errors found here (time.dt above the
  // stability limit) leave no files behind.
  void setup();

  // The user's additions to the set-up (RunOptions::before_first_output), then the check that
  // the time step still suits the discs they made: still nothing is written.
  void build_on_setup(const BeforeFirstOutput& fn);

  // Writes output 0 and a checkpoint at once, so that from here on a killed run resumes.
  void start_fresh();

  // Restores the checkpoint after checking that it, the configuration and the outputs belong
  // to one run; writes nothing, so a refused resume leaves the folder as it was.
  // `extending`: the resume changes the run's end (extension keys), so a finished run goes on.
  void load_checkpoint(bool extending);

  // Continues the outputs after the checkpoint's last one; later ones are dropped and written
  // again by the resumed run.
  void reopen_outputs();

  // Steps to the end, or until SIGINT/SIGTERM: then it checkpoints the step it is at and
  // returns the signal (the run resumes from exactly there; no extra output is written, so
  // the outputs stay those of an uninterrupted run). Returns 0 when the run finished.
  int loop(Progress& progress);

  // A branch's source, replayed: its set-up, then its steps up to output k with what its
  // outputs do to the experiment's state, and no file written. Bitwise the source's run.
  void replay_to(std::int64_t k);

  // The state of the world and the experiment alone (what a branch starts from).
  void save_state(const std::filesystem::path& file);

  // Starts from another run's state at its output `snap` (read from `in`): the world and the
  // experiment's state bit for bit, with this run's configuration; checks the positions,
  // velocities and ids against the stored snapshot. Output 0 is that state again, with the
  // source's own output fields; later outputs keep the source's spacing in time.
  void load_branch(const ArchiveReader& in, const BranchSource& source, const Snapshot& snap);

  // RunOptions::between_steps: `fn` after every `every`-th step (none: the CLI's run).
  void between_steps(BetweenSteps fn, std::uint64_t every);

  // Makes this run rank `rank` of a run over MPI ranks (mpirun -n K orogen run, K > 1): every
  // rank runs this driver on its copy of the world (stepped over the ranks: World::step_as_rank)
  // and gathers it whole before each output and checkpoint; rank 0 alone writes files. The
  // ranks look for a stop signal every 64 steps and agree through `max_over_ranks` (collective),
  // so that all stop at one step.
  void as_rank(int rank, std::function<double(double)> max_over_ranks);
  bool writes_files() const { return rank_ == 0; }

  World& world() { return world_; }
  const std::string& branch_from() const { return branch_from_; }
  const std::string& checkpoint_config() const { return checkpoint_config_; }
  void abort_after_outputs(std::int64_t n) { abort_after_outputs_ = n; }

 private:
  // The file attributes of snapshots.h5, the columns and opening lines of series.csv.
  SnapshotMetadata metadata() const;
  std::vector<CsvSeries::Column> csv_columns() const;
  std::vector<std::string> preamble() const;

  // One output step: the snapshot, the .vtp file, a series row, removals.csv, run.pvd, and
  // the in-run analysis when due.
  void output();
  void write_output_files();  // the files of output(): snapshot, .vtp, series row, event logs

  // summary.csv: the series format with a single row, one column per result.
  void write_summary();

  void write_pvd_file();

  // checkpoint.bin: the world, the experiment and the driver's state, with the configuration.
  void checkpoint();
  void write_event_logs();  // removals.csv and bond_breaks.csv, through the current step

  // The checkpoint must come from a run of this folder's configuration.
  void check_checkpoint_belongs(const ArchiveReader& in) const;

  // Every file the resume keeps must be of this run (kept_files.hpp); loads the series for
  // reopen_outputs().
  void check_kept_files(std::optional<std::uint64_t> series_digest);

  spdlog::logger& log() { return *spdlog::get("orogen"); }

  const Config& config_;
  const Config& settings_;
  std::filesystem::path dir_;
  std::unique_ptr<Experiment> exp_;
  World world_;
  RunState state_;
  double interval_;
  std::int64_t checkpoint_every_;
  bool write_vtp_;
  ContactOutputOptions contact_output_;
  std::string identity_;
  std::vector<OutputObserver> observers_;  // the experiment's work beside the outputs
  std::string checkpoint_config_;  // the configuration the loaded checkpoint was written with
  std::uint64_t last_output_step_ = 0;
  std::int64_t abort_after_outputs_ = 0;
  BetweenSteps between_;            // RunOptions::between_steps
  std::uint64_t between_every_ = 0;
  double output_base_ = 0;        // a branch: outputs of its source before its output 0
  std::string branch_from_;       // a branch: "SOURCE_DIR:OUTPUT"
  bool branch_start_ = false;     // the next output is a branch's output 0
  std::map<std::string, std::vector<double>> branch_fields_;  // its fields, by name
  int rank_ = 0;                  // a run over MPI ranks: this process's rank (as_rank)
  std::function<double(double)> max_over_ranks_;  // and how the ranks agree; none in one process
  // The stop signal this step should act on: this process's, or in a run over ranks the ranks'
  // agreed one every 64 steps.
  int stop_signal() const;
  std::optional<SnapshotWriter> snapshots_;
  std::optional<CsvSeries> series_;
};

}  // namespace orogen
