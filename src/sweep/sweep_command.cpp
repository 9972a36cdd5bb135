#include "sweep/sweep_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <iostream>
#include <optional>
#include <set>
#include <thread>

#include "config/config.hpp"
#include "io/atomic_file.hpp"
#include "io/file_lock.hpp"
#include "io/snapshot_reader.hpp"
#include "sweep/sweep_log_tail.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_processes.hpp"
#include "sweep/sweep_report.hpp"
#include "sweep/sweep_results.hpp"
#include "sweep/sweep_run_state.hpp"
#include "util/command_error.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

using Args = std::vector<std::string>;

// The work left for one run: `orogen run` (fresh or resumed), then the renders.
struct Task {
  std::size_t run = 0;
  std::optional<Args> run_args;  // none: the run had finished already
  std::deque<Args> renders;      // filled once the run has finished
  bool render_planned = false;
};

struct Active {
  pid_t pid;
  std::size_t task;
  bool is_run;  // else a render
};

std::string runs_text(std::size_t n) { return fmt::format("{} run{}", n, n == 1 ? "" : "s"); }

std::string status_text(int status) {
  if (status == 2) return "exit 2: bad input";
  if (status == 3) return "exit 3: unstable";
  if (status > 128) return fmt::format("killed by signal {}", status - 128);
  return fmt::format("exit {}", status);
}

// The renders of a finished run: initial-depth horizons, and where the experiment writes it,
// the relative displacement of neighbours (active faults). A run without that field (a
// packing) would make `render --color field:max_rel_disp` refuse with exit 2.
std::deque<Args> render_steps(const fs::path& dir) {
  std::deque<Args> steps = {{"render", dir.string(), "--color", "horizons"}};
  bool has_field = false;
  try {
    const SnapshotReader reader(dir / "snapshots.h5");
    has_field = reader.count() > 0 && reader.read(reader.count() - 1).fields.count("max_rel_disp") > 0;
  } catch (const std::exception&) {
    // The horizons render reports what is wrong with the file.
  }
  if (has_field)
    steps.push_back({"render", dir.string(), "--color", "field:max_rel_disp", "--frames-dir", "frames_rel_disp"});
  return steps;
}

std::string stage_text(const RunInspection& s) {
  switch (s.stage) {
    case RunStage::Absent: return "to start";
    case RunStage::Restart: return "to start again (" + s.note + ")";
    case RunStage::Resume: return "to continue" + (s.note.empty() ? "" : " (" + s.note + ")");
    case RunStage::Finished: return s.rendered ? "finished, rendered" : "finished";
    case RunStage::Failed: return "failed before (" + status_text(s.failed_status) + ")";
  }
  return "";
}

class Sweep {
 public:
  Sweep(SweepPlan plan, const SweepOptions& opt)
      : plan_(std::move(plan)), opt_(opt), report_(opt.out / "sweep.log"), outcomes_(plan_.runs.size()) {
    const auto threads = static_cast<std::size_t>(std::max(1, opt.threads));
    jobs_ = opt.jobs > 0 ? static_cast<std::size_t>(opt.jobs)
                         : std::max<std::size_t>(1, std::thread::hardware_concurrency() / threads);
  }

  fs::path run_dir(std::size_t i) const { return opt_.out / "runs" / plan_.runs[i].name; }
  fs::path log_of(std::size_t i) const { return opt_.out / "logs" / (plan_.runs[i].name + ".log"); }

  // Turns what the folders hold into the work left.
  void plan_work(const std::vector<RunInspection>& states) {
    std::size_t finished = 0, failed = 0, resumed = 0, started = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
      const auto& s = states[i];
      const auto& run = plan_.runs[i];
      const fs::path dir = run_dir(i);
      Task t{i, std::nullopt, {}, false};
      switch (s.stage) {
        case RunStage::Finished:
          ++finished;
          outcomes_[i].exit_status = 0;
          if (s.rendered) outcomes_[i].render_status = 0;
          if (!opt_.render || s.rendered) continue;
          break;
        case RunStage::Failed:
          ++failed;
          outcomes_[i].exit_status = s.failed_status;
          outcomes_[i].error = s.failed_error.empty() ? last_log_line(log_of(i)) : s.failed_error;
          report_.event(fmt::format("{}: failed before ({}{}); remove {} to try again", run.name,
                                    status_text(s.failed_status),
                                    outcomes_[i].error.empty() ? "" : ": " + outcomes_[i].error, dir.string()));
          continue;
        case RunStage::Resume:
          ++resumed;
          t.run_args = Args{"run", "--resume", dir.string(), "--threads", std::to_string(opt_.threads)};
          if (!s.note.empty()) report_.event(run.name + ": " + s.note);
          break;
        case RunStage::Restart:
          report_.event(fmt::format("{}: {}; starting it again", run.name, s.note));
          fs::remove_all(dir);
          [[fallthrough]];
        case RunStage::Absent: {
          ++started;
          Args args = {"run", plan_.base.string()};
          for (const auto& o : run.overrides) args.insert(args.end(), {"--set", o});
          args.insert(args.end(), {"--out", dir.string(), "--threads", std::to_string(opt_.threads)});
          t.run_args = std::move(args);
          break;
        }
      }
      pending_.insert(i);
      tasks_.push_back(std::move(t));
    }
    report_.event(fmt::format("{} in {}: {} finished already, {} failed before, {} to continue, {} to start; "
                              "{} at a time",
                              runs_text(plan_.runs.size()), opt_.out.string(), finished, failed, resumed, started, jobs_));
  }

  int execute() {
    std::deque<std::size_t> waiting;
    for (std::size_t k = 0; k < tasks_.size(); ++k) waiting.push_back(k);
    write_results();
    while (!waiting.empty() || !active_.empty()) {
      bool changed = false;
      while (active_.size() < jobs_ && !waiting.empty()) {
        const std::size_t k = waiting.front();
        waiting.pop_front();
        start_next(k);
        changed = true;
      }
      bool reaped = false;
      while (const auto e = reap_child()) {
        const auto it = std::find_if(active_.begin(), active_.end(), [&](const Active& a) { return a.pid == e->pid; });
        if (it == active_.end()) continue;  // not one of ours
        const Active done = *it;
        active_.erase(it);
        reaped = true;
        on_exit(done, e->status);
      }
      std::vector<std::string> running;
      for (const auto& a : active_) running.push_back(plan_.runs[tasks_[a.task].run].name + (a.is_run ? "" : " (render)"));
      report_.progress(done_count(), plan_.runs.size(), failed_count(), running, changed || reaped);
      if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    report_.finish();
    write_results();
    const std::size_t failed = failed_count();
    report_.event(fmt::format("{}: {} finished, {} failed; results in {}", runs_text(plan_.runs.size()),
                              plan_.runs.size() - failed, failed, (opt_.out / "results.md").string()));
    return failed ? 1 : 0;
  }

 private:
  // Starts the task's next step: the run, else its next render; finishes the task if none is left.
  void start_next(std::size_t k) {
    Task& t = tasks_[k];
    const std::size_t i = t.run;
    if (t.run_args) {
      const Args args = std::move(*t.run_args);
      t.run_args.reset();
      spawn(k, args, true);
      return;
    }
    if (opt_.render && !t.render_planned) {
      t.renders = render_steps(run_dir(i));
      t.render_planned = true;
    }
    if (!t.renders.empty()) {
      const Args args = std::move(t.renders.front());
      t.renders.pop_front();
      spawn(k, args, false);
      return;
    }
    if (opt_.render && !outcomes_[i].render_status) {
      write_file_atomically(run_dir(i) / kRenderedMarker, "");
      outcomes_[i].render_status = 0;
    }
    pending_.erase(i);
    write_results();
  }

  void spawn(std::size_t k, const Args& args, bool is_run) {
    const std::size_t i = tasks_[k].run;
    try {
      const pid_t pid = spawn_self(args, log_of(i));
      active_.push_back({pid, k, is_run});
      const std::string what = !is_run ? "rendering " + args[3] : args[1] == "--resume" ? "continuing" : "started";
      report_.event(plan_.runs[i].name + ": " + what);
    } catch (const std::exception& e) {
      report_.event(fmt::format("{}: {}", plan_.runs[i].name, e.what()));
      on_exit({0, k, is_run}, 127);
    }
  }

  void on_exit(const Active& a, int status) {
    Task& t = tasks_[a.task];
    const std::size_t i = t.run;
    const auto& name = plan_.runs[i].name;
    if (a.is_run) {
      outcomes_[i].exit_status = status;
      if (status != 0) {
        outcomes_[i].error = last_log_line(log_of(i));
        report_.event(fmt::format("{}: failed ({}), see {}", name, status_text(status), log_of(i).string()));
        // A verdict on the configuration would come again: recorded, so a restarted sweep does not repeat it.
        if (is_verdict(status)) {
          fs::create_directories(run_dir(i));
          write_file_atomically(run_dir(i) / kFailedMarker,
                                std::to_string(status) + "\n" + outcomes_[i].error + "\n");
        }
        pending_.erase(i);
        write_results();
        return;
      }
      report_.event(name + ": finished");
    } else if (status != 0) {
      outcomes_[i].render_status = status;
      outcomes_[i].error = last_log_line(log_of(i));
      report_.event(fmt::format("{}: render failed ({}), see {}", name, status_text(status), log_of(i).string()));
      t.renders.clear();
      pending_.erase(i);
      write_results();
      return;
    }
    start_next(a.task);
  }

  std::size_t failed_count() const {
    std::size_t n = 0;
    for (const auto& o : outcomes_)
      if ((o.exit_status && *o.exit_status != 0) || (o.render_status && *o.render_status != 0)) ++n;
    return n;
  }
  std::size_t done_count() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < outcomes_.size(); ++i)
      if (outcomes_[i].exit_status && !pending_.count(i)) ++n;
    return n;
  }

  void write_results() { write_sweep_results(opt_.out, plan_, outcomes_, opt_.render); }

  SweepPlan plan_;
  const SweepOptions& opt_;
  SweepReport report_;
  std::vector<SweepOutcome> outcomes_;
  std::size_t jobs_ = 1;
  std::vector<Task> tasks_;
  std::vector<Active> active_;
  std::set<std::size_t> pending_;  // runs with a step under way or still to come
};

}  // namespace

int sweep_command(const SweepOptions& opt) {
  SweepPlan plan;
  std::vector<RunInspection> states;
  std::optional<FileLock> folder_lock;  // one sweep at a time per folder, until we end
  try {
    // Everything is checked before anything is started; a bad sweep file writes nothing.
    plan = load_sweep(opt.file);
    if (opt.dry_run) {
      for (const auto& run : plan.runs)
        std::cout << run.name << ": " << stage_text(inspect_run(opt.out / "runs" / run.name, run.resolved_toml)) << "\n";
      return 0;
    }
    std::error_code ec;
    fs::create_directories(opt.out, ec);
    if (ec) throw std::runtime_error(fmt::format("cannot create the sweep folder {}: {}", opt.out.string(), ec.message()));
    // Before looking at the runs: another sweep may be changing them.
    folder_lock.emplace(lock_command_folder(opt.out / "sweep.lock", "sweep"));
    for (const auto& run : plan.runs) states.push_back(inspect_run(opt.out / "runs" / run.name, run.resolved_toml));
    fs::create_directories(opt.out / "logs");
    fs::create_directories(opt.out / "runs");
  } catch (const std::exception& e) {  // nothing started yet: each failure here is the sweep's input
    return report_error(e, "", kExitBadInput);
  }
  try {
    Sweep sweep(std::move(plan), opt);
    sweep.plan_work(states);
    return sweep.execute();
  } catch (const std::exception& e) {
    // A file the sweep cannot write (results, markers): its children die with it.
    return report_error(e);
  }
}

}  // namespace orogen
