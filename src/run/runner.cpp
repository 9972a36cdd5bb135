#include "run/runner.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <omp.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "analysis/contact_output.hpp"
#include "config/config.hpp"
#include "exhumation/analyze_command.hpp"
#include "experiments/experiment.hpp"
#include "experiments/spec_from_config.hpp"
#include "experiments/time_step_config.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_series.hpp"
#include "io/snapshot_reader.hpp"
#include "io/snapshot_writer.hpp"
#include "io/vtp_writer.hpp"
#include "run/branch_source.hpp"
#include "run/kept_files.hpp"
#include "run/progress.hpp"
#include "run/removal_log.hpp"
#include "run/run_folder.hpp"
#include "run/setup_report.hpp"
#include "run/status_line_sink.hpp"
#include "run/stop_signals.hpp"
#include "util/run_control.hpp"
#include "util/thread_tuner.hpp"
#include "world/world_archive.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

struct UsageError : BadInput {
  using BadInput::BadInput;
};

// The key that counts the outputs over a run whose end is `end_key` (the schema's OutputCount
// key of the same section: wedge.outputs for wedge.s_end).
std::string output_count_key(const std::string& end_key) {
  const std::string section = end_key.substr(0, end_key.find('.') + 1);
  for (const std::string& key : keys_that(kOutputCount))
    if (key.starts_with(section)) return key;
  throw std::logic_error("schema: no output count beside " + end_key);
}

// Everything the driver itself must carry across a checkpoint.
struct RunState {
  std::int64_t outputs = 0;          // output steps written
  std::vector<double> output_times;  // for run.pvd
  // Per output, the digest of its .vtp file (0: none written), so that a resume recognises
  // a file of another run; empty in checkpoints written before digests were kept.
  std::vector<std::uint64_t> vtp_digests;
  bool finished = false;
};

const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : "SIGTERM"; }

ContactOutputOptions contact_output_options(const Config& config) {
  ContactOutputOptions o{config.get_bool("output.contacts"), config.get_bool("output.stress"),
                         config.get_float("output.stress_grid")};
  // A finer grid than half a disc holds no more than one disc per cell, and a tiny one no memory.
  if (o.stress_grid > 0 && o.stress_grid < 0.5)
    throw config_error(config.source_of("output.stress_grid"), "output.stress_grid", fmt::format("{}", o.stress_grid),
                       "must be 0 (no grid) or at least 0.5 (cell size in d)");
  return o;
}

// The log goes to run.log and to stderr; the stderr sink also carries the progress line.
std::shared_ptr<spdlog::logger> make_logger(const fs::path& dir, const std::shared_ptr<StatusLineSink>& console) {
  auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "run.log").string());
  console->set_level(spdlog::level::info);
  auto log = std::make_shared<spdlog::logger>("orogen", spdlog::sinks_init_list{file, console});
  log->set_pattern("[%Y-%m-%d %H:%M:%S] %v");
  log->flush_on(spdlog::level::info);
  return log;
}

class Run {
 public:
  // `settings`, where given, holds this process's keys of speed and display (a resume's own
  // --set of them); `config` is the run's configuration, stored with its outputs.
  Run(const Config& config, fs::path dir, std::unique_ptr<Experiment> experiment, const Config* settings = nullptr)
      : config_(config), settings_(settings ? *settings : config), dir_(std::move(dir)), exp_(std::move(experiment)),
        interval_(exp_->output_interval().value_or(config.get_float("output.interval"))),
        checkpoint_every_(settings_.get_int("output.checkpoint_every")),
        write_vtp_(settings_.get_bool("output.vtp")), contact_output_(contact_output_options(config)),
        identity_(run_identity(config)), analyze_in_run_(config.get_bool("analysis.in_run")),
        analyze_every_(config.get_int("analysis.every")) {}

  // Builds the initial state and writes nothing, so that errors found here (time.dt above the
  // stability limit) leave no files behind.
  void setup() {
    apply_engine_config(config_, world_);
    exp_->setup(world_);
  }

  // The user's additions to the set-up (RunOptions::before_first_output), then the check that
  // the time step still suits the discs they made: still nothing is written.
  void build_on_setup(const BeforeFirstOutput& fn) {
    fn(world_, *exp_, config_);
    check_world_time_step(config_, world_);
  }

  // Writes output 0 and a checkpoint at once, so that from here on a killed run resumes.
  void start_fresh() {
    snapshots_.emplace(dir_ / "snapshots.h5", metadata());
    series_.emplace(dir_ / "series.csv", csv_columns(), preamble());
    if (write_vtp_) fs::create_directories(dir_ / "vtp");
    output();
    checkpoint();
  }

  // Restores the checkpoint after checking that it, the configuration and the outputs belong
  // to one run; writes nothing, so a refused resume leaves the folder as it was.
  // `extending`: the resume changes the run's end (extension keys), so a finished run goes on.
  void load_checkpoint(bool extending) {
    apply_engine_config(config_, world_);
    const ArchiveReader in(dir_ / "checkpoint.bin");
    check_checkpoint_belongs(in);
    state_.finished = in.get_scalar<std::uint8_t>("run.finished") != 0;
    if (state_.finished && !extending) {
      const std::string end_key = keys_that(kRunEnd).front();  // the schema's end of an extendable run
      throw UsageError(fmt::format("the run in {} has already finished; to extend it, give it a later end: orogen run "
                                   "--resume {} --set {}=... ({} follows, at the same spacing)",
                                   dir_.string(), dir_.string(), end_key, output_count_key(end_key)));
    }
    state_.finished = false;
    load_world(in, world_);
    exp_->load(in);
    exp_->attach(world_);  // hooks are not state: they come back with the experiment
    state_.outputs = in.get_scalar<std::int64_t>("run.outputs");
    in.get("run.output_times", state_.output_times);
    last_output_step_ = in.get_scalar<std::uint64_t>("run.last_output_step");
    if (in.has("run.output_base")) output_base_ = in.get_scalar<double>("run.output_base");  // a branch
    if (in.has("run.branch_from")) branch_from_ = in.get_string("run.branch_from");
    checkpoint_config_ = in.get_string("run.config");
    if (in.has("run.vtp_digests")) in.get("run.vtp_digests", state_.vtp_digests);
    check_kept_files(in.has("run.series_digest") ? std::optional(in.get_scalar<std::uint64_t>("run.series_digest"))
                                                 : std::nullopt);
  }

  // Continues the outputs after the checkpoint's last one; later ones are dropped and written
  // again by the resumed run.
  void reopen_outputs() {
    snapshots_.emplace(SnapshotWriter::reopen(dir_ / "snapshots.h5", state_.outputs));
    snapshots_->set_metadata_string(kConfigAttr, config_.to_toml());  // an extension's new end
    series_->truncate(static_cast<std::size_t>(state_.outputs));
    for (std::int64_t k = state_.outputs;; ++k) {
      if (!fs::remove(dir_ / vtp_file_name(k))) break;
    }
    state_.vtp_digests.resize(static_cast<std::size_t>(state_.outputs), 0);
    if (write_vtp_) write_pvd_file();
    write_removal_log(dir_ / "removals.csv", world_.removals, world_.step);
    log().info("resumed at step {} (t = {:.6g}) after output {}", world_.step, world_.time, state_.outputs - 1);
  }

  // Steps to the end, or until SIGINT/SIGTERM: then it checkpoints the step it is at and
  // returns the signal (the run resumes from exactly there; no extra output is written, so
  // the outputs stay those of an uninterrupted run). Returns 0 when the run finished.
  int loop(Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t step0 = world_.step;
    double particle_steps = 0;
    auto seconds = [&t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    ThreadTuner tuner(settings_.get_bool("run.adapt_threads") ? omp_get_max_threads() : 1,
                      settings_.get_float("run.adapt_slice"));
    while (exp_->advance(world_)) {
      // A scripted rule acts after its step and before that step's output, so outputs show it.
      const bool hook_stop =
          between_every_ > 0 && world_.step % between_every_ == 0 && between_(world_, *exp_, config_);
      const auto work = static_cast<double>(world_.discs.size());
      particle_steps += work;
      const int threads = tuner.threads();
      if (tuner.after_step(work, seconds()) != threads) omp_set_num_threads(tuner.threads());
      if (world_.time >= (output_base_ + static_cast<double>(state_.outputs)) * interval_ - 1e-9 * interval_) {
        const double output_start = seconds();
        output();
        const double secs = seconds();
        log().info("output {} at step {} (t = {:.4g}): {} discs, {:.3g} M particle-steps/s{}, {}", state_.outputs - 1,
                   world_.step, world_.time, world_.discs.size(), particle_steps / secs / 1e6,
                   tuner.active() ? fmt::format(" (now on {} thread(s))", tuner.threads()) : "", exp_->status(world_));
        if (checkpoint_every_ > 0 && state_.outputs % checkpoint_every_ == 0) checkpoint();
        tuner.exclude(seconds() - output_start);  // outputs are not stepping
      }
      if ((world_.step & 63) == 0 && progress.enabled())
        progress.update(world_.step, world_.time, world_.discs.size(), exp_->fraction_done(world_), exp_->status(world_));
      if (hook_stop) {
        progress.finish();
        checkpoint();
        log().info("stopped by the between-steps hook at step {} (t = {:.6g}) after output {}, with a checkpoint",
                   world_.step, world_.time, state_.outputs - 1);
        return -1;
      }
      if (const int sig = StopSignals::received(); sig != 0) {
        progress.finish();
        checkpoint();
        log().info("stopped by {} at step {} (t = {:.6g}) after output {}, with a checkpoint; continue with orogen run "
                   "--resume {}",
                   signal_name(sig), world_.step, world_.time, state_.outputs - 1, dir_.string());
        return sig;
      }
    }
    progress.finish();
    if (state_.output_times.empty() || world_.step != last_output_step_) output();
    exp_->finish(world_, dir_);
    write_summary();
    if (analyze_in_run_) analyze();  // the outputs since the last analysis.every
    state_.finished = true;
    checkpoint();
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    log().info("finished at step {} (t = {:.6g}) after {} steps in {:.1f} s ({:.3g} M particle-steps/s, {} neighbour "
               "list builds in all)",
               world_.step, world_.time, world_.step - step0, secs, particle_steps / std::max(secs, 1e-9) / 1e6,
               world_.neighbors.builds);
    if (const auto threads = tuner.summary(); !threads.empty()) log().info("threads: {}", threads);
    return 0;
  }

  // A branch's source, replayed: its set-up, then its steps up to output k with what its
  // outputs do to the experiment's state, and no file written. Bitwise the source's run.
  void replay_to(std::int64_t k) {
    setup();
    auto output = [&] {
      exp_->after_output(world_);
      ++state_.outputs;
      last_output_step_ = world_.step;
    };
    output();
    const auto t0 = std::chrono::steady_clock::now();
    while (state_.outputs <= k) {
      // A replay can take as long as its source took: a signal stops it, the set-up report hears it.
      run_control::between_steps(world_.step,
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (!exp_->advance(world_)) {
        if (world_.step != last_output_step_) output();  // a run's last output comes at its end
        break;
      }
      if (world_.time >= static_cast<double>(state_.outputs) * interval_ - 1e-9 * interval_) output();
    }
    if (state_.outputs <= k) throw std::runtime_error(fmt::format("the replay ended before output {}", k));
  }

  // The state of the world and the experiment alone (what a branch starts from).
  void save_state(const fs::path& file) {
    ArchiveWriter out;
    save_world(out, world_);
    exp_->save(out);
    out.finish(file);
  }

  // Starts from another run's state at its output `snap` (read from `in`): the world and the
  // experiment's state bit for bit, with this run's configuration; checks the positions,
  // velocities and ids against the stored snapshot. Output 0 is that state again, with the
  // source's own output fields; later outputs keep the source's spacing in time.
  void load_branch(const ArchiveReader& in, const BranchSource& source, const Snapshot& snap) {
    apply_engine_config(config_, world_);
    load_world(in, world_);
    exp_->load(in);
    exp_->attach(world_);  // hooks are not state: they come back with the experiment
    exp_->adopt_branch_config(world_);
    const Discs& d = world_.discs;
    bool same = d.size() == snap.size();
    for (std::size_t i = 0; same && i < d.size(); ++i)
      same = d.id[i] == snap.id[i] && d.x[i] == snap.field("x")[i] && d.y[i] == snap.field("y")[i] &&
             d.vx[i] == snap.field("vx")[i] && d.vy[i] == snap.field("vy")[i];
    if (!same)
      throw std::runtime_error(fmt::format("--from {}: the rebuilt state differs from the stored output (was the run "
                                           "made by another Orogen version?)",
                                           source.text()));
    for (const auto& [name, values] : snap.fields)
      if (std::find(kSnapshotDiscArrays.begin(), kSnapshotDiscArrays.end(), name) == kSnapshotDiscArrays.end())
        branch_fields_[name] = values;
    branch_from_ = source.text();
    branch_start_ = true;
    // The next output comes at the next multiple of the interval after the branch's time.
    output_base_ = std::floor(world_.time / interval_ + 1e-6);
  }

  World& world() { return world_; }
  const std::string& branch_from() const { return branch_from_; }
  const std::string& checkpoint_config() const { return checkpoint_config_; }
  void abort_after_outputs(std::int64_t n) { abort_after_outputs_ = n; }
  void between_steps(BetweenSteps fn, std::uint64_t every) {
    between_ = std::move(fn);
    between_every_ = between_ ? every : 0;
  }

 private:
  spdlog::logger& log() { return *spdlog::get("orogen"); }

  SnapshotMetadata metadata() const {
    SnapshotMetadata m;
    m.strings["experiment"] = config_.get_string("run.experiment");
    m.strings["orogen_version"] = OROGEN_VERSION;
    m.numbers["h0"] = exp_->h0();
    m.numbers["dt"] = world_.dt;
    m.numbers["x_split"] = exp_->x_split();
    m.strings["run_identity"] = identity_;
    m.strings[kConfigAttr] = config_.to_toml();
    if (!branch_from_.empty()) m.strings["branch_from"] = branch_from_;
    return m;
  }

  std::vector<CsvSeries::Column> csv_columns() const {
    std::vector<CsvSeries::Column> cols;
    for (const auto& c : exp_->columns()) cols.push_back({c.name, c.description});
    return cols;
  }

  std::vector<std::string> preamble() const {
    return {fmt::format("Orogen {} series, experiment '{}': one row per output step", OROGEN_VERSION,
                        config_.get_string("run.experiment")),
            "lengths in units of the largest disc diameter d, time in sqrt(d/g); each column's unit in [] after its "
            "description",
            fmt::format("h0 = {} d (the layer thickness; the unit of a wedge's lengths)", exp_->h0())};
  }

  void output() {
    SnapshotFrame frame;
    frame.step = static_cast<std::int64_t>(world_.step);
    frame.time = world_.time;
    frame.discs = &world_.discs;
    for (auto& [name, value] : exp_->scalars(world_)) frame.attrs[name] = value;
    frame.fields = exp_->fields(world_);
    // A branch's output 0 repeats the source's output fields (their units and descriptions are the experiment's).
    for (auto& field : frame.fields)
      if (auto it = branch_fields_.find(field.name); it != branch_fields_.end()) field.values = it->second;
    branch_fields_.clear();
    for (const auto& w : world_.walls)
      if (w.enabled) frame.walls.push_back({w.ax, w.ay, w.bx, w.by});
    frame.groups = contact_output_groups(world_, contact_output_);
    snapshots_->append(frame);
    state_.vtp_digests.push_back(write_vtp_ ? write_vtp(dir_ / vtp_file_name(state_.outputs), frame) : 0);
    series_->add_row(exp_->measure(world_));
    write_removal_log(dir_ / "removals.csv", world_.removals, world_.step);
    state_.output_times.push_back(world_.time);
    ++state_.outputs;
    last_output_step_ = world_.step;
    if (!branch_start_) exp_->after_output(world_);  // a branch's state has seen its output already
    branch_start_ = false;
    if (write_vtp_) write_pvd_file();
    if (analyze_in_run_ && state_.outputs % analyze_every_ == 0) analyze();
    // Test hook (--abort-after-outputs): die like a kill, with no cleanup.
    if (state_.outputs == abort_after_outputs_) std::_Exit(137);
  }

  // The same incremental analysis as `orogen analyze DIR` afterwards: it reads only the
  // outputs it has not seen. A failure is logged and the run goes on (it can be re-run later).
  void analyze() {
    AnalyzeOptions analysis;
    analysis.dir = dir_;
    analysis.quiet = true;
    if (analyze_command(analysis) != 0)
      if (auto log = spdlog::get("orogen")) log->warn("in-run analysis failed (see the error above); the run goes on");
  }

  // summary.csv: the series format with a single row, one column per result.
  void write_summary() {
    const auto values = exp_->summary(world_);
    if (values.empty()) return;
    std::vector<CsvSeries::Column> cols;
    std::vector<double> row;
    for (const auto& v : values) {
      cols.push_back({v.name, v.description});
      row.push_back(v.value);
    }
    CsvSeries summary(dir_ / "summary.csv", std::move(cols),
                      {fmt::format("Orogen {} summary, experiment '{}': the results of the finished run", OROGEN_VERSION,
                                   config_.get_string("run.experiment"))});
    summary.add_row(std::move(row));
  }

  void write_pvd_file() {
    std::vector<std::pair<double, std::string>> entries;
    for (std::int64_t k = 0; k < state_.outputs; ++k) entries.emplace_back(state_.output_times[k], vtp_file_name(k));
    write_pvd(dir_ / "run.pvd", entries);
  }

  void checkpoint() {
    ArchiveWriter out;
    save_world(out, world_);
    exp_->save(out);
    out.put_scalar("run.outputs", state_.outputs);
    out.put("run.output_times", state_.output_times);
    out.put("run.vtp_digests", state_.vtp_digests);
    out.put_scalar("run.series_digest", series_->digest(static_cast<std::size_t>(state_.outputs)));
    out.put_scalar<std::uint8_t>("run.finished", state_.finished ? 1 : 0);
    out.put_scalar("run.last_output_step", last_output_step_);
    out.put_scalar("run.output_base", output_base_);
    out.put_string("run.branch_from", branch_from_);
    out.put_string("run.identity", identity_);
    out.put_string("run.config", config_.to_toml());
    out.finish(dir_ / "checkpoint.bin");
  }

  // The checkpoint must come from a run of this folder's configuration.
  void check_checkpoint_belongs(const ArchiveReader& in) const {
    const fs::path ckpt = dir_ / "checkpoint.bin";
    if (!in.has("run.config") || !in.has("run.identity"))
      throw RunFolderError(fmt::format("{} was written by an older Orogen and holds no copy of its configuration; "
                                       "start the run again in a new folder",
                                       ckpt.string()));
    const std::string differences =
        config_differences(config_.to_toml(), in.get_string("run.config"), "config.toml", "the checkpoint");
    if (!differences.empty())
      throw RunFolderError(fmt::format("{} and {} are not of one run: {}. Restore config.toml, or start a new run "
                                       "in another folder",
                                       (dir_ / "config.toml").string(), ckpt.string(), differences));
    if (in.get_string("run.identity") != identity_)
      throw RunFolderError(fmt::format("{} comes from another run (identity {}, this configuration's is {})",
                                       ckpt.string(), in.get_string("run.identity"), identity_));
  }

  // Every file the resume keeps must be of this run (kept_files.hpp); loads the series for
  // reopen_outputs().
  void check_kept_files(std::optional<std::uint64_t> series_digest) {
    KeptFiles kept{.identity = identity_,
                   .config_toml = config_.to_toml(),
                   .output_times = state_.output_times,
                   .vtp_digests = state_.vtp_digests,
                   .series_digest = series_digest,
                   .series_columns = {},
                   .removals = world_.removals,
                   .step = world_.step};
    for (const auto& col : exp_->columns()) kept.series_columns.push_back(col.name);
    series_.emplace(check_kept_files_of_run(dir_, kept));
  }

  const Config& config_;
  const Config& settings_;
  fs::path dir_;
  std::unique_ptr<Experiment> exp_;
  World world_;
  RunState state_;
  double interval_;
  std::int64_t checkpoint_every_;
  bool write_vtp_;
  ContactOutputOptions contact_output_;
  std::string identity_;
  bool analyze_in_run_;
  std::int64_t analyze_every_;
  std::string checkpoint_config_;  // the configuration the loaded checkpoint was written with
  std::uint64_t last_output_step_ = 0;
  std::int64_t abort_after_outputs_ = 0;
  BetweenSteps between_;            // RunOptions::between_steps
  std::uint64_t between_every_ = 0;
  double output_base_ = 0;        // a branch: outputs of its source before its output 0
  std::string branch_from_;       // a branch: "SOURCE_DIR:OUTPUT"
  bool branch_start_ = false;     // the next output is a branch's output 0
  std::map<std::string, std::vector<double>> branch_fields_;  // its fields, by name
  std::optional<SnapshotWriter> snapshots_;
  std::optional<CsvSeries> series_;
};

Progress::Mode progress_mode(const Config& c) {
  const auto& m = c.get_string("output.progress");
  if (m == "always") return Progress::Mode::Always;
  if (m == "never") return Progress::Mode::Never;
  return Progress::Mode::Auto;
}

}  // namespace

namespace {

// A fresh run: the folder is claimed (locked) before anything else, must hold no run files,
// and gets its config.toml before set-up, so that a run killed during a long set-up is
// already a run that --resume starts again.
// `header`: comment lines put before the configuration (a branch names its source there).
void claim_for_new_run(const RunOptions& opt, const Config& config, RunFolderLock& lock, const std::string& header) {
  if (fs::exists(opt.out / "config.toml")) {
    lock.abandon();
    throw UsageError(fmt::format("{} already holds a run; continue it with --resume {} or choose another --out",
                                 opt.out.string(), opt.out.string()));
  }
  if (const auto found = run_files_in(opt.out); !found.empty()) {
    lock.abandon();
    throw UsageError(fmt::format("{} holds files of a run ({}) but no config.toml; remove them or choose another "
                                 "--out",
                                 opt.out.string(), fmt::join(found, ", ")));
  }
  write_file_atomically(opt.out / "config.toml", header + config.to_toml());
}

constexpr std::string_view kBranchHeader = "# branch of ";

bool is_branch_folder(const fs::path& dir) {
  std::ifstream in(dir / "config.toml");
  std::string first;
  std::getline(in, first);
  return first.starts_with(kBranchHeader);
}

// A branch's first state: its source's checkpoint when that holds the output, else a replay
// of the source from its set-up (bitwise the same run) to that output.
void build_branch(Run& run, const BranchSource& source, const fs::path& out) {
  const fs::path h5 = source.dir / "snapshots.h5";
  const SnapshotReader reader(h5);
  const std::string identity = run_identity(source.config);
  if (const std::string why =
          foreign_output(reader, source.output, reader.stamp(source.output), identity, source.config.to_toml());
      !why.empty())
    throw BranchError(fmt::format("--from {}: {}", source.text(), why));
  const Snapshot snap = reader.read(source.output);
  if (source.at_checkpoint) {
    const ArchiveReader checkpoint(source.dir / "checkpoint.bin");
    if (!checkpoint.has("run.identity") || checkpoint.get_string("run.identity") != identity)
      throw BranchError(fmt::format("--from {}: {} comes from another run than {}", source.text(),
                                    (source.dir / "checkpoint.bin").string(), (source.dir / "config.toml").string()));
    run.load_branch(checkpoint, source, snap);
    return;
  }
  const SnapshotMetadata meta = read_snapshot_metadata(h5);
  if (const auto it = meta.strings.find("branch_from"); it != meta.strings.end())
    throw BranchError(fmt::format("--from {}: that run is itself a branch (of {}), which a replay cannot rebuild; "
                                  "branch from its checkpointed output instead",
                                  source.text(), it->second));
  if (source.config.get_string("run.experiment") == "scripted")
    throw BranchError(fmt::format("--from {}: a scripted run's geometry was built by its setup function, which a "
                                  "replay cannot call; branch from its checkpointed output instead",
                                  source.text()));
  Run replay(source.config, source.dir, make_experiment(source.config));
  replay.replay_to(source.output);
  const fs::path state = out / "branch_state.bin";
  replay.save_state(state);
  try {
    run.load_branch(ArchiveReader(state), source, snap);
  } catch (...) {
    fs::remove(state);
    throw;
  }
  fs::remove(state);
}

// Undoes claim_for_new_run after a set-up that failed (bad input, unstable set-up): nothing
// of the run is left behind.
void release_new_run(const RunOptions& opt, RunFolderLock& lock) {
  spdlog::drop("orogen");  // run.log is closed once the last logger holding it goes
  std::error_code ec;
  fs::remove(opt.out / "config.toml", ec);
  fs::remove(opt.out / "run.log", ec);
  lock.abandon();
}

std::string override_key(const std::string& assignment) { return assignment.substr(0, assignment.find('=')); }

// A resume's new end (`end_key`, a RunEnd key: wedge.s_end) against the run's: never earlier
// (the outputs already written would lie past the end). Without a new output count
// (`keep_spacing`), it must be a whole number of the run's output spacings; returns the
// "wedge.outputs=N" that keeps it.
std::string check_new_end(const fs::path& dir, const std::string& end_key, const std::vector<std::string>& extending,
                          bool keep_spacing) {
  const std::string count_key = output_count_key(end_key);
  const Config before = Config::load(dir / "config.toml", {});
  const Config after = Config::load(dir / "config.toml", extending);
  const double old_end = before.get_float(end_key), new_end = after.get_float(end_key);
  if (new_end < old_end)
    throw UsageError(fmt::format("--resume {}: {} = {:g} is before the run's end, {:g}; a resume may only move "
                                 "the end later (start a new run, or a branch with --from, for a shorter one)",
                                 dir.string(), end_key, new_end, old_end));
  const double spacing = old_end / static_cast<double>(before.get_int(count_key));
  const double outputs = new_end / spacing;
  const double whole = std::max(1.0, std::round(outputs));
  if (keep_spacing && std::abs(outputs - whole) > 1e-6 * whole)
    throw UsageError(fmt::format("--resume {}: a new {} alone keeps the run's output spacing (S = {:.6g}, "
                                 "{} / {}), and {:g} is not a whole number of it: give an end that "
                                 "is ({:.6g} gives {:.0f} outputs), or set {} too",
                                 dir.string(), end_key, spacing, end_key, count_key, new_end, whole * spacing, whole,
                                 count_key));
  return fmt::format("{}={:.0f}", count_key, whole);
}

// A resume's --set overrides: those that extend the run (extension keys; a new end is never
// earlier, and alone it keeps the outputs' spacing, so the output count follows it),
// and those that change only how this process goes (display keys). Any other key is refused.
struct ResumeOverrides {
  std::vector<std::string> extending, display;
};

ResumeOverrides resume_overrides(const RunOptions& opt) {
  if (opt.config) throw UsageError("--resume takes its configuration from the run folder; drop CONFIG");
  ResumeOverrides r;
  std::string end_key;  // the run's end, when the resume moves it
  bool sets_outputs = false;
  for (const auto& o : opt.overrides) {
    const std::string key = override_key(o);
    if (is_extension_key(key)) {
      r.extending.push_back(o);
      if (key_may(key, kRunEnd)) end_key = key;
      sets_outputs |= key_may(key, kOutputCount);
    } else if (is_display_key(key)) {
      r.display.push_back(o);
    } else {
      throw UsageError(fmt::format("--resume takes its configuration from the run folder; --set {} would change what "
                                   "the run computes (a resume may change only {}, to extend it, and the keys of "
                                   "speed and display such as run.threads and output.progress): start a new run instead",
                                   o, extension_keys_text()));
    }
  }
  if (!fs::is_directory(opt.out)) throw UsageError(fmt::format("--resume {}: no such folder", opt.out.string()));
  if (!fs::exists(opt.out / "config.toml"))
    throw UsageError(fmt::format("--resume {}: no run there (config.toml is missing)", opt.out.string()));
  if (!end_key.empty()) {
    const std::string outputs = check_new_end(opt.out, end_key, r.extending, !sets_outputs);
    if (!sets_outputs) r.extending.push_back(outputs);
  }
  return r;
}

}  // namespace

int run_command(const RunOptions& opt) {
  bool started = false;  // the folder holds a run that --resume can continue
  try {
    if (opt.resume && opt.out.empty()) throw UsageError("--resume needs a run folder");
    if (opt.out.empty()) throw UsageError("--out needs a folder (got an empty one)");
    if (opt.resume && !opt.from.empty()) throw UsageError("--from starts a new run (a branch); drop --resume");
    const ResumeOverrides resume = opt.resume ? resume_overrides(opt) : ResumeOverrides{};
    std::vector<std::string> resume_all = resume.extending;
    resume_all.insert(resume_all.end(), resume.display.begin(), resume.display.end());
    std::optional<BranchSource> source;
    if (!opt.from.empty()) source = find_branch_source(opt.from);
    // A branch without a configuration file continues its source's configuration (with --set).
    const std::optional<fs::path> config_file = opt.config || !source ? opt.config : source->dir / "config.toml";
    const Config config =
        opt.resume ? Config::load(opt.out / "config.toml", resume_all) : Config::load(config_file, opt.overrides);
    if (source) check_branch_config(config, *source);
    if (!opt.resume && fs::exists(opt.out / "config.toml"))
      throw UsageError(fmt::format("{} already holds a run; continue it with --resume {} or choose another --out",
                                   opt.out.string(), opt.out.string()));
    auto experiment = make_experiment(config);
    check_in_run_analysis(config);  // before the folder is claimed: a refusal leaves nothing
    const int threads = opt.threads >= 0 ? opt.threads : config.get_int32("run.threads");
    if (threads > 0) omp_set_num_threads(threads);

    // A run that starts from its set-up with nothing to build: refused, as it could only run empty.
    if (!source && !opt.before_first_output && config.get_string("run.experiment") == "scripted" &&
        !(opt.resume && fs::exists(opt.out / "checkpoint.bin")))
      throw UsageError("run.experiment = \"scripted\" builds no discs itself: they come from a Python setup "
                       "function (orogen.run(config, out=DIR, setup=build); docs/python.md), which the command line "
                       "cannot give; from the command line, choose another experiment, or branch a scripted run "
                       "with --from");

    // Installed before the set-up, which can take minutes: a stop there ends the run cleanly.
    const StopSignals stop_signals;
    RunFolderLock lock(opt.out);
    // A resume without a checkpoint (killed during set-up) starts the run again from its set-up.
    const bool from_checkpoint = opt.resume && fs::exists(opt.out / "checkpoint.bin");
    if (!opt.resume)
      claim_for_new_run(opt, config, lock,
                        source ? fmt::format("{}{} (orogen run --from)\n", kBranchHeader, source->text()) : "");
    if (opt.resume && !from_checkpoint && is_branch_folder(opt.out))
      throw UsageError(fmt::format("--resume {}: this branch was stopped before its first checkpoint; remove the "
                                   "folder and start the branch again",
                                   opt.out.string()));
    // A resume from a checkpoint changes nothing before every kept file is checked (below).
    int stale = from_checkpoint ? 0 : remove_temporary_files(opt.out);
    if (opt.resume && !from_checkpoint) remove_run_outputs(opt.out);

    // A resume's configuration as stored: the folder's, with only the extension keys changed.
    const std::vector<std::string>& extending = resume.extending;
    const Config stored = opt.resume ? Config::load(opt.out / "config.toml", extending) : config;
    Run run(stored, opt.out, std::move(experiment), &config);
    run.abort_after_outputs(opt.abort_after_outputs);
    run.between_steps(opt.between_steps, opt.between_every);
    if (from_checkpoint) {
      run.load_checkpoint(!extending.empty());
      stale = remove_temporary_files(opt.out);
    }
    auto console = std::make_shared<StatusLineSink>(stderr);
    auto logger = make_logger(opt.out, console);
    spdlog::drop("orogen");
    spdlog::register_logger(logger);
    logger->info("orogen {} {} in {} with {} thread(s)", OROGEN_VERSION, opt.resume ? "resume" : "run",
                 opt.out.string(), omp_get_max_threads());
    for (const auto& warning : config_warnings(config)) logger->warn("{}", warning);
    if (stale > 0) logger->info("removed {} temporary file(s) left by a killed write", stale);
    Progress progress(progress_mode(config), console);
    if (!from_checkpoint) {
      try {
        const SetupReport report(*logger, *console, progress, source.has_value());
        if (source) {
          build_branch(run, *source, opt.out);
        } else {
          run.setup();
          if (opt.before_first_output) run.build_on_setup(opt.before_first_output);
          else if (run.world().discs.size() == 0)
            throw UsageError("the set-up made no discs, so the run could only run empty; make the layer larger "
                             "(layer.length, layer.thickness)");
        }
      } catch (const run_control::Stopped& stop) {
        // A new run keeps its config.toml, as after a kill during the set-up: --resume starts it
        // again. A branch cannot be resumed before its first checkpoint: its folder goes.
        const bool keep = !source;
        logger->info("stopped by {} during the set-up, before output 0{}", signal_name(stop.signal),
                     keep ? fmt::format("; orogen run --resume {} starts it again", opt.out.string())
                          : "; the branch's folder is removed");
        if (!keep) release_new_run(opt, lock);
        return 128 + stop.signal;
      } catch (const InstabilityError& e) {
        if (!opt.resume) release_new_run(opt, lock);
        std::cerr << "error: the set-up became unstable: " << e.what() << "\n";
        return 3;
      } catch (...) {
        if (!opt.resume) release_new_run(opt, lock);
        throw;
      }
    }
    if (source)
      logger->info("branch of {} at output {} (step {}, t = {:.6g}), its state {}", source->dir.string(), source->output,
                   run.world().step, run.world().time,
                   source->at_checkpoint ? "from its checkpoint" : "rebuilt by replaying it from its set-up");

    if (from_checkpoint) {
      if (!extending.empty()) {
        const std::string before = run.checkpoint_config();
        const std::string header =
            run.branch_from().empty() ? "" : fmt::format("{}{} (orogen run --from)\n", kBranchHeader, run.branch_from());
        write_file_atomically(opt.out / "config.toml", header + stored.to_toml());
        logger->info("extended: {}", extension_changes(stored.to_toml(), before));
      }
      run.reopen_outputs();
    } else {
      if (opt.resume) logger->info("no checkpoint yet (the run was stopped during its set-up): starting it again");
      run.start_fresh();
    }
    started = true;
    logger->info("{} discs, {} clusters, dt = {:.6g} (stable limit {:.6g}), k_n = {:.6g}", run.world().discs.size(),
                 run.world().clusters.size(), run.world().dt, run.world().stable_dt(), run.world().law.kn);
    try {
      if (const int sig = run.loop(progress); sig != 0) return sig < 0 ? kStoppedByHook : 128 + sig;
    } catch (const InstabilityError& e) {
      progress.finish();
      logger->error("stopped: {}", e.what());
      return 3;
    }
    return 0;
  } catch (const BadInput& e) {  // a configuration, usage, branch or folder error
    return report_error(e);
  } catch (const std::exception& e) {
    // Anything else (a file that cannot be written, a full disk) ends the run with its reason.
    if (auto log = spdlog::get("orogen")) log->error("stopped: {}", e.what());  // to the terminal too
    else std::cerr << "error: " << e.what() << "\n";
    if (started)
      std::cerr << "The run's files up to its last checkpoint are intact: once the cause is fixed, continue it with "
                   "orogen run --resume "
                << opt.out.string() << "\n";
    return 1;
  }
}

}  // namespace orogen
