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

#include "exhumation/analyze_command.hpp"
#include "experiments/spec_from_config.hpp"
#include "io/atomic_file.hpp"
#include "parallel/mpi_session.hpp"
#include "parallel/mpi_stepping.hpp"
#include "run/run.hpp"
#include "run/run_folder.hpp"
#include "run/setup_report.hpp"
#include "run/stop_signals.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// The log goes to run.log and to stderr; the stderr sink also carries the progress line.
std::shared_ptr<spdlog::logger> make_logger(const fs::path& dir, const std::shared_ptr<StatusLineSink>& console,
                                            bool writes_files) {
  if (!writes_files) return std::make_shared<spdlog::logger>("orogen");  // another rank: rank 0 logs the run
  auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "run.log").string());
  console->set_level(spdlog::level::info);
  auto log = std::make_shared<spdlog::logger>("orogen", spdlog::sinks_init_list{file, console});
  log->set_pattern("[%Y-%m-%d %H:%M:%S] %v");
  log->flush_on(spdlog::level::info);
  return log;
}


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
void release_new_run(const RunOptions& opt, std::optional<RunFolderLock>& lock) {
  if (!lock) return;  // another rank of a run over ranks: rank 0 owns the folder
  spdlog::drop("orogen");  // run.log is closed once the last logger holding it goes
  std::error_code ec;
  fs::remove(opt.out / "config.toml", ec);
  fs::remove(opt.out / "run.log", ec);
  lock->abandon();
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

// This process's configuration: a resume's stored one with its own --set of extension and
// display keys; a branch's (without a file, its source's) with --set, checked against the
// source; else the file's (or the defaults) with --set.
Config run_configuration(const RunOptions& opt, const ResumeOverrides& resume,
                         const std::optional<BranchSource>& source) {
  if (opt.resume) {
    std::vector<std::string> all = resume.extending;
    all.insert(all.end(), resume.display.begin(), resume.display.end());
    return Config::load(opt.out / "config.toml", all);
  }
  // A branch without a configuration file continues its source's configuration (with --set).
  const std::optional<fs::path> config_file = opt.config || !source ? opt.config : source->dir / "config.toml";
  Config config = Config::load(config_file, opt.overrides);
  if (source) check_branch_config(config, *source);
  return config;
}

// A run that does not start from a checkpoint: its set-up (or a branch's source state), on
// the terminal and in the log. Returns the exit code when the set-up ends the command (a stop
// by a signal, an instability); a new run's folder is released where it cannot be resumed.
std::optional<int> build_first_state(Run& run, const RunOptions& opt, const std::optional<BranchSource>& source,
                                     spdlog::logger& logger, StatusLineSink& console, Progress& progress,
                                     std::optional<RunFolderLock>& lock) {
  try {
    const SetupReport report(logger, console, progress, source.has_value());
    if (source) {
      build_branch(run, *source, opt.out);
    } else {
      run.setup();
      if (opt.before_first_output) run.build_on_setup(opt.before_first_output);
      else if (run.world().discs().size() == 0)
        throw UsageError("the set-up made no discs, so the run could only run empty; make the layer larger "
                         "(layer.length, layer.thickness)");
    }
  } catch (const run_control::Stopped& stop) {
    // A new run keeps its config.toml, as after a kill during the set-up: --resume starts it
    // again. A branch cannot be resumed before its first checkpoint: its folder goes.
    const bool keep = !source;
    logger.info("stopped by {} during the set-up, before output 0{}", signal_name(stop.signal),
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
  return std::nullopt;
}

// What `mpirun -n K orogen run` (K > 1) does not run: code of the user's inside or between the
// steps (the Python package's hooks) and branches (their replay runs one process).
void check_runnable_over_ranks(const RunOptions& opt, int ranks) {
  const char* refused = !opt.from.empty()                           ? "a branch (--from)"
                        : opt.between_steps || opt.before_first_output ? "the Python package's hooks"
                        : opt.surface_law                              ? "a Python surface law"
                                                                        : nullptr;
  if (refused)
    throw UsageError(fmt::format("a run over {} MPI ranks cannot run {} yet: run it as one process "
                                 "(docs/domain-decomposition.md)",
                                 ranks, refused));
}

// Hands the steps of the run's world to this MPI rank. Refused, with the folder of a new run
// released, where the world has what a step over ranks does not run yet (a hook inside the
// step other than the constant-velocity base's pin) or cannot be cut into as many
// slabs as ranks (a rank's slab is whole chunks of the pair list).
std::unique_ptr<MpiStepping> step_over_ranks(Run& run, const RunOptions& opt, std::optional<RunFolderLock>& lock,
                                             spdlog::logger& logger) {
  const int ranks = opt.mpi->size();
  const auto& chunk_start = run.world().neighbors().chunk_start;
  const std::size_t chunks = chunk_start.size() > 1 ? chunk_start.size() - 1 : static_cast<std::size_t>(kMaxPairChunks);
  try {
    if (static_cast<std::size_t>(ranks) > chunks)
      throw std::invalid_argument(fmt::format(
          "{} ranks are more than this world can be cut into: a rank's slab is whole chunks of the pair list, "
          "and it has {} (at most {}, fewer on a short domain)",
          ranks, chunks, kMaxPairChunks));
    auto stepping = std::make_unique<MpiStepping>(run.world());
    logger.info("stepping over {} MPI ranks (this log is rank 0's; the ranks gather the world before each stage, "
                "output and checkpoint)",
                ranks);
    return stepping;
  } catch (const std::invalid_argument& e) {
    if (!opt.resume) release_new_run(opt, lock);
    throw UsageError(fmt::format("cannot run over {} MPI ranks: {}", ranks, e.what()));
  }
}

// Opens the outputs: after a checkpoint they continue (an extension first rewrites
// config.toml with the new end), else output 0 and a checkpoint are written at once.
void open_outputs(Run& run, const RunOptions& opt, bool from_checkpoint, const Config& stored,
                  const std::vector<std::string>& extending, spdlog::logger& logger) {
  if (!from_checkpoint) {
    if (opt.resume) logger.info("no checkpoint yet (the run was stopped during its set-up): starting it again");
    run.start_fresh();
    return;
  }
  if (!extending.empty() && run.writes_files()) {
    const std::string before = run.checkpoint_config();
    const std::string header =
        run.branch_from().empty() ? "" : fmt::format("{}{} (orogen run --from)\n", kBranchHeader, run.branch_from());
    write_file_atomically(opt.out / "config.toml", header + stored.to_toml());
    logger.info("extended: {}", extension_changes(stored.to_toml(), before));
  }
  run.reopen_outputs();
}

}  // namespace

int run_command(const RunOptions& opt) {
  bool started = false;  // the folder holds a run that --resume can continue
  try {
    if (opt.resume && opt.out.empty()) throw UsageError("--resume needs a run folder");
    if (opt.out.empty()) throw UsageError("--out needs a folder (got an empty one)");
    if (opt.resume && !opt.from.empty()) throw UsageError("--from starts a new run (a branch); drop --resume");
    const ResumeOverrides resume = opt.resume ? resume_overrides(opt) : ResumeOverrides{};
    std::optional<BranchSource> source;
    if (!opt.from.empty()) source = find_branch_source(opt.from);
    const Config config = run_configuration(opt, resume, source);
    // Under mpirun with K > 1 ranks every rank runs this command on the same configuration;
    // rank 0 owns the folder and writes its files (docs/domain-decomposition.md).
    const int rank = opt.mpi ? opt.mpi->rank() : 0;
    const int ranks = opt.mpi ? opt.mpi->size() : 1;
    const bool writer = rank == 0;
    if (ranks > 1) check_runnable_over_ranks(opt, ranks);
    if (writer && !opt.resume && fs::exists(opt.out / "config.toml"))
      throw UsageError(fmt::format("{} already holds a run; continue it with --resume {} or choose another --out",
                                   opt.out.string(), opt.out.string()));
    auto experiment = make_experiment(config);
    if (ranks > 1 && !experiment->runs_over_ranks())
      throw UsageError(fmt::format("a run over {} MPI ranks cannot run run.experiment = \"{}\": only the wedge, the "
                                   "singly-vergent wedge and packings run over ranks; run it as one process "
                                   "(docs/domain-decomposition.md)",
                                   ranks, config.get_string("run.experiment")));
    if (opt.surface_law && !experiment->set_surface_script(opt.surface_law))
      throw UsageError("a surface law needs an experiment with surface processes (a wedge; docs/surface.md)");
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
    std::optional<RunFolderLock> lock;
    if (writer) lock.emplace(opt.out);
    // A resume without a checkpoint (killed during set-up) starts the run again from its set-up.
    const bool from_checkpoint = opt.resume && fs::exists(opt.out / "checkpoint.bin");
    if (writer && !opt.resume)
      claim_for_new_run(opt, config, *lock,
                        source ? fmt::format("{}{} (orogen run --from)\n", kBranchHeader, source->text()) : "");
    if (opt.resume && !from_checkpoint && is_branch_folder(opt.out))
      throw UsageError(fmt::format("--resume {}: this branch was stopped before its first checkpoint; remove the "
                                   "folder and start the branch again",
                                   opt.out.string()));
    // A resume from a checkpoint changes nothing before every kept file is checked (below).
    int stale = from_checkpoint || !writer ? 0 : remove_temporary_files(opt.out);
    if (writer && opt.resume && !from_checkpoint) remove_run_outputs(opt.out);

    // A resume's configuration as stored: the folder's, with only the extension keys changed.
    const std::vector<std::string>& extending = resume.extending;
    const Config stored = opt.resume ? Config::load(opt.out / "config.toml", extending) : config;
    Run run(stored, opt.out, std::move(experiment), &config);
    run.abort_after_outputs(opt.abort_after_outputs);
    run.between_steps(opt.between_steps, opt.between_every);
    if (ranks > 1)
      run.as_rank(rank, [mpi = opt.mpi](double mine) { return mpi->max({static_cast<int>(mine)}).front(); });
    if (from_checkpoint) {
      run.load_checkpoint(!extending.empty());
      if (writer) stale = remove_temporary_files(opt.out);
    }
    auto console = std::make_shared<StatusLineSink>(stderr);
    auto logger = make_logger(opt.out, console, writer);
    spdlog::drop("orogen");
    spdlog::register_logger(logger);
    logger->info("orogen {} {} in {} with {} thread(s)", OROGEN_VERSION, opt.resume ? "resume" : "run",
                 opt.out.string(), omp_get_max_threads());
    for (const auto& warning : config_warnings(config)) logger->warn("{}", warning);
    if (stale > 0) logger->info("removed {} temporary file(s) left by a killed write", stale);
    Progress progress(writer ? progress_mode(config) : Progress::Mode::Never, console);
    if (!from_checkpoint)
      if (const auto code = build_first_state(run, opt, source, *logger, *console, progress, lock)) return *code;
    // From here on each rank steps its part of one world (the same set-up or checkpoint in each).
    const std::unique_ptr<MpiStepping> over_ranks = ranks > 1 ? step_over_ranks(run, opt, lock, *logger) : nullptr;
    if (source)
      logger->info("branch of {} at output {} (step {}, t = {:.6g}), its state {}", source->dir.string(), source->output,
                   run.world().step(), run.world().time(),
                   source->at_checkpoint ? "from its checkpoint" : "rebuilt by replaying it from its set-up");

    open_outputs(run, opt, from_checkpoint, stored, extending, *logger);
    started = true;
    logger->info("{} discs, {} clusters, dt = {:.6g} (stable limit {:.6g}), k_n = {:.6g}", run.world().discs().size(),
                 run.world().clusters().size(), run.world().dt(), run.world().stable_dt(), run.world().law().kn);
    const std::uint64_t first_step = run.world().step();
    try {
      const int sig = run.loop(progress);
      if (over_ranks) logger->info("exchange: {}", over_ranks->traffic_per_step(run.world().step() - first_step));
      if (sig != 0) return sig < 0 ? kStoppedByHook : 128 + sig;
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
