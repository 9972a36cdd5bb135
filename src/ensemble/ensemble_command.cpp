#include "ensemble/ensemble_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <thread>

#include "config/config.hpp"
#include "parallel/mpi_session.hpp"
#include "ensemble/ensemble_plan.hpp"
#include "ensemble/ensemble_pool.hpp"
#include "io/atomic_file.hpp"
#include "io/file_lock.hpp"
#include "sweep/sweep_log_tail.hpp"
#include "sweep/sweep_report.hpp"
#include "sweep/sweep_run_state.hpp"
#include "util/python_module.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

constexpr int kUnknown = -1;  // a member's status not known on this rank

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// DIR/members.csv: what became of each member, for the statistics and the results table.
void write_members_csv(const fs::path& out, const EnsemblePlan& plan, const std::vector<int>& status) {
  std::string text =
      "# Orogen ensemble members: one row per member of the ensemble file, in its order\n"
      "# name: the member's folder under members/\n"
      "# group: its [[member]] entry (empty without any); members of a group differ only in the seed\n"
      "# seed: run.seed (empty: the preset's)\n"
      "# exit_status: of `orogen run`: 0 finished, 2 bad input, 3 unstable, 128+N killed by signal N, 127 not "
      "started; empty: not run\n"
      "# error: a failed member: the last line of its log (logs/NAME.log)\n"
      "name,group,seed,exit_status,error\n";
  for (std::size_t i = 0; i < plan.members.size(); ++i) {
    const auto& m = plan.members[i];
    const std::string error = status[i] > 0 ? last_log_line(out / "logs" / (m.name + ".log")) : "";
    text += fmt::format("{},{},{},{},{}\n", csv_field(m.name), csv_field(m.group), m.seed ? std::to_string(*m.seed) : "",
                        status[i] == kUnknown ? "" : std::to_string(status[i]), csv_field(error));
  }
  write_file_atomically(out / "members.csv", text);
}

// Runs `python3 -m orogen.stats DIR` (the package's ensemble statistics); its output goes to our stderr.
int run_statistics(const fs::path& out) {
  if (const std::string why = python_module_unavailable("orogen.stats"); !why.empty()) {
    std::cerr << fmt::format("statistics skipped: {} (make them later: python3 -m orogen.stats {})\n", why,
                             out.string());
    return 1;
  }
  return run_python_module("orogen.stats", {out.string()}, true);
}

struct Work {
  std::vector<PoolTask> tasks;
  std::vector<std::size_t> member_of;  // task -> member index
};

}  // namespace

int ensemble_command(const EnsembleOptions& opt) {
  if (MpiSession::launched_without_mpi()) {
    std::cerr << "error: started by mpirun, but this orogen was built without MPI (install libopenmpi-dev and "
                 "build again; docs/ensembles.md): every process would run every member\n";
    return 2;
  }
  MpiSession mpi;
  const bool root = mpi.rank() == 0;
  EnsemblePlan plan;
  std::string error;
  std::optional<FileLock> folder_lock;  // rank 0: one ensemble at a time per folder, until we end
  // 1. The plan: every member's configuration checked before anything is written.
  try {
    plan = load_ensemble(opt.file);
    if (opt.dry_run) {
      if (root)
        for (const auto& m : plan.members) {
          const auto s = inspect_run(opt.out / "members" / m.name, m.resolved_toml);
          static const char* kStage[] = {"to start", "to start again", "to continue", "finished", "failed before"};
          std::cout << m.name << ": " << kStage[static_cast<int>(s.stage)] << "\n";
        }
      return 0;
    }
    if (root) {
      std::error_code ec;
      fs::create_directories(opt.out, ec);
      if (ec) throw std::runtime_error(fmt::format("cannot create the ensemble folder {}: {}", opt.out.string(), ec.message()));
      folder_lock.emplace(lock_command_folder(opt.out / "ensemble.lock", "ensemble"));
      fs::create_directories(opt.out / "members");
      fs::create_directories(opt.out / "logs");
      write_file_atomically(opt.out / "ensemble.toml", plan_to_toml(plan));
    }
  } catch (const ConfigError& e) {
    error = e.what();
  } catch (const std::exception& e) {
    error = std::string("error: ") + e.what();
  }
  if (!mpi.all(error.empty())) {
    if (!error.empty()) std::cerr << error << "\n";
    return 2;
  }

  // 2. What each of this rank's members needs (member i belongs to rank i mod size). A folder
  // of another configuration stops every rank before any member starts.
  Work work;
  std::vector<int> status(plan.members.size(), kUnknown);
  try {
    for (std::size_t i = 0; i < plan.members.size(); ++i) {
      if (static_cast<int>(i % static_cast<std::size_t>(mpi.size())) != mpi.rank()) continue;
      const auto& m = plan.members[i];
      const fs::path dir = opt.out / "members" / m.name;
      const RunInspection s = inspect_run(dir, m.resolved_toml);
      PoolTask t{m.name, {}, opt.out / "logs" / (m.name + ".log"), "started"};
      switch (s.stage) {
        case RunStage::Finished: status[i] = 0; continue;
        case RunStage::Failed: status[i] = s.failed_status; continue;
        case RunStage::Resume:
          t.args = {"run", "--resume", dir.string()};
          t.what = "continuing";
          break;
        case RunStage::Restart:
          fs::remove_all(dir);  // killed before its first checkpoint: nothing to keep
          [[fallthrough]];
        case RunStage::Absent:
          t.args = {"run", m.preset.string()};
          for (const auto& o : m.overrides) t.args.insert(t.args.end(), {"--set", o});
          t.args.insert(t.args.end(), {"--out", dir.string()});
          break;
      }
      work.tasks.push_back(std::move(t));
      work.member_of.push_back(i);
    }
  } catch (const std::exception& e) {
    error = std::string("error: ") + e.what();
  }
  if (!mpi.all(error.empty())) {
    if (!error.empty()) std::cerr << error << "\n";
    return 2;
  }

  // 3. Run them: members in parallel processes, and the cores left over as threads of each
  // when there are fewer members than cores. Results do not depend on either.
  int code = 0;
  try {
    const auto hw = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
    const int cores = std::max(1, hw / std::max(1, mpi.local_size()));
    const int n = std::max(1, static_cast<int>(work.tasks.size()));
    const int jobs = opt.jobs > 0 ? opt.jobs : opt.threads > 0 ? std::max(1, cores / opt.threads) : std::min(cores, n);
    const int threads = opt.threads > 0 ? opt.threads : std::max(1, cores / jobs);
    for (auto& t : work.tasks) t.args.insert(t.args.end(), {"--threads", std::to_string(threads)});
    SweepReport report(opt.out / "ensemble.log");
    report.event(fmt::format("rank {} of {}: {} member{} to run here, {} at a time, {} thread{} each", mpi.rank(),
                             mpi.size(), work.tasks.size(), work.tasks.size() == 1 ? "" : "s", jobs, threads,
                             threads == 1 ? "" : "s"));
    run_pool(work.tasks, static_cast<std::size_t>(jobs), report, [&](std::size_t k, int st) {
      const std::size_t i = work.member_of[k];
      const auto& m = plan.members[i];
      status[i] = st;
      if (st == 0) {
        report.event(m.name + ": finished");
        return;
      }
      const std::string why = last_log_line(opt.out / "logs" / (m.name + ".log"));
      report.event(fmt::format("{}: failed (exit {}){}", m.name, st, why.empty() ? "" : ": " + why));
      // A verdict on the configuration would come again: recorded, so a restart skips it.
      if (is_verdict(st)) {
        fs::create_directories(opt.out / "members" / m.name);
        write_file_atomically(opt.out / "members" / m.name / kFailedMarker, std::to_string(st) + "\n" + why + "\n");
      }
    });
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    code = 1;
  }

  // 4. Rank 0 gathers (the statuses; the members' files are in the shared folder) and writes
  // the aggregate once every rank is done.
  const std::vector<int> all_status = mpi.max(status);
  const bool failed = std::any_of(all_status.begin(), all_status.end(), [](int s) { return s != 0; });
  if (root && code == 0) {
    try {
      write_members_csv(opt.out, plan, all_status);
      if (!opt.no_stats && run_statistics(opt.out) != 0) {
        std::cerr << "error: the statistics failed (see above); the members are complete\n";
        code = 1;
      }
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      code = 1;
    }
  }
  const bool ok = mpi.all(code == 0);
  if (root)
    std::cerr << fmt::format("{} members: {} finished, {} failed; results in {}\n", plan.members.size(),
                             std::count(all_status.begin(), all_status.end(), 0),
                             plan.members.size() - static_cast<std::size_t>(std::count(all_status.begin(), all_status.end(), 0)),
                             (opt.out / "results.md").string());
  return !ok || failed ? 1 : 0;
}

}  // namespace orogen
