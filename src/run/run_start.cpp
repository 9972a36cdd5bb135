#include "run/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "config/run_identity.hpp"
#include "config/schema.hpp"
#include "experiments/time_step_config.hpp"
#include "run/kept_files.hpp"
#include "run/removal_log.hpp"
#include "run/run_folder.hpp"
#include "util/run_control.hpp"
#include "world/world_archive.hpp"

namespace fs = std::filesystem;

namespace orogen {

// The key that counts the outputs over a run whose end is `end_key` (the schema's OutputCount
// key of the same section: wedge.outputs for wedge.s_end).
std::string output_count_key(const std::string& end_key) {
  const std::string section = end_key.substr(0, end_key.find('.') + 1);
  for (const std::string& key : keys_that(kOutputCount))
    if (key.starts_with(section)) return key;
  throw std::logic_error("schema: no output count beside " + end_key);
}

ContactOutputOptions contact_output_options(const Config& config) {
  ContactOutputOptions o{config.get_bool("output.contacts"), config.get_bool("output.stress"),
                         config.get_float("output.stress_grid")};
  // A finer grid than half a disc holds no more than one disc per cell, and a tiny one no memory.
  if (o.stress_grid > 0 && o.stress_grid < 0.5)
    throw config_error(config.source_of("output.stress_grid"), "output.stress_grid", fmt::format("{}", o.stress_grid),
                       "must be 0 (no grid) or at least 0.5 (cell size in d)");
  return o;
}

Run::Run(const Config& config, fs::path dir, std::unique_ptr<Experiment> experiment, const Config* settings)
    : config_(config), settings_(settings ? *settings : config), dir_(std::move(dir)), exp_(std::move(experiment)),
      interval_(exp_->output_interval().value_or(config.get_float("output.interval"))),
      checkpoint_every_(settings_.get_int("output.checkpoint_every")),
      write_vtp_(settings_.get_bool("output.vtp")), contact_output_(contact_output_options(config)),
      identity_(run_identity(config)), observers_(exp_->output_observers(dir_)) {}

// Builds the initial state and writes nothing, so that errors found here (time.dt above the
// stability limit) leave no files behind.
void Run::setup() {
  apply_engine_config(config_, world_);
  exp_->setup(world_);
}

// The user's additions to the set-up (RunOptions::before_first_output), then the check that
// the time step still suits the discs they made: still nothing is written.
void Run::build_on_setup(const BeforeFirstOutput& fn) {
  fn(world_, *exp_, config_);
  check_world_time_step(config_, world_);
}

// Writes output 0 and a checkpoint at once, so that from here on a killed run resumes.
void Run::start_fresh() {
  if (!writes_files()) {  // another rank of a run over ranks: output 0's gather and state alone
    output();
    return;
  }
  snapshots_.emplace(dir_ / "snapshots.h5", metadata());
  series_.emplace(dir_ / "series.csv", csv_columns(), preamble());
  if (write_vtp_) fs::create_directories(dir_ / "vtp");
  output();
  checkpoint();
}

// Restores the checkpoint after checking that it, the configuration and the outputs belong
// to one run; writes nothing, so a refused resume leaves the folder as it was.
// `extending`: the resume changes the run's end (extension keys), so a finished run goes on.
void Run::load_checkpoint(bool extending) {
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
  if (writes_files())  // another rank of a run over ranks reads the checkpoint alone
    check_kept_files(in.has("run.series_digest")
                         ? std::optional(in.get_scalar<std::uint64_t>("run.series_digest"))
                         : std::nullopt);
}

// Continues the outputs after the checkpoint's last one; later ones are dropped and written
// again by the resumed run.
void Run::reopen_outputs() {
  if (!writes_files()) return;
  snapshots_.emplace(SnapshotWriter::reopen(dir_ / "snapshots.h5", state_.outputs));
  snapshots_->set_metadata_string(kConfigAttr, config_.to_toml());  // an extension's new end
  series_->truncate(static_cast<std::size_t>(state_.outputs));
  for (std::int64_t k = state_.outputs;; ++k) {
    if (!fs::remove(dir_ / vtp_file_name(k))) break;
  }
  state_.vtp_digests.resize(static_cast<std::size_t>(state_.outputs), 0);
  if (write_vtp_) write_pvd_file();
  write_removal_log(dir_ / "removals.csv", world_.removals(), world_.step());
  log().info("resumed at step {} (t = {:.6g}) after output {}", world_.step(), world_.time(), state_.outputs - 1);
}

// A branch's source, replayed: its set-up, then its steps up to output k with what its
// outputs do to the experiment's state, and no file written. Bitwise the source's run.
void Run::replay_to(std::int64_t k) {
  setup();
  auto output = [&] {
    exp_->after_output(world_);
    ++state_.outputs;
    last_output_step_ = world_.step();
  };
  output();
  const auto t0 = std::chrono::steady_clock::now();
  while (state_.outputs <= k) {
    // A replay can take as long as its source took: a signal stops it, the set-up report hears it.
    run_control::between_steps(world_.step(),
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!exp_->advance(world_)) {
      if (world_.step() != last_output_step_) output();  // a run's last output comes at its end
      break;
    }
    if (world_.time() >= static_cast<double>(state_.outputs) * interval_ - 1e-9 * interval_) output();
  }
  if (state_.outputs <= k) throw std::runtime_error(fmt::format("the replay ended before output {}", k));
}

// The state of the world and the experiment alone (what a branch starts from).
void Run::save_state(const fs::path& file) {
  ArchiveWriter out;
  save_world(out, world_);
  exp_->save(out);
  out.finish(file);
}

// Starts from another run's state at its output `snap` (read from `in`): the world and the
// experiment's state bit for bit, with this run's configuration; checks the positions,
// velocities and ids against the stored snapshot. Output 0 is that state again, with the
// source's own output fields; later outputs keep the source's spacing in time.
void Run::load_branch(const ArchiveReader& in, const BranchSource& source, const Snapshot& snap) {
  apply_engine_config(config_, world_);
  load_world(in, world_);
  exp_->load(in);
  exp_->attach(world_);  // hooks are not state: they come back with the experiment
  exp_->adopt_branch_config(world_);
  const Discs& d = world_.discs();
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
  output_base_ = std::floor(world_.time() / interval_ + 1e-6);
}

// The checkpoint must come from a run of this folder's configuration.
void Run::check_checkpoint_belongs(const ArchiveReader& in) const {
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
void Run::check_kept_files(std::optional<std::uint64_t> series_digest) {
  KeptFiles kept{.identity = identity_,
                 .config_toml = config_.to_toml(),
                 .output_times = state_.output_times,
                 .vtp_digests = state_.vtp_digests,
                 .series_digest = series_digest,
                 .series_columns = {},
                 .removals = world_.removals(),
                 .step = world_.step()};
  for (const auto& col : exp_->columns()) kept.series_columns.push_back(col.name);
  series_.emplace(check_kept_files_of_run(dir_, kept));
}

}  // namespace orogen
