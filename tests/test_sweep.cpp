// `orogen sweep` end to end with tiny packing runs: the results table, a second call that does
// nothing, a killed run continued bit for bit, a failed run recorded, and bad sweep files
// refused (exit 2, nothing written). Plus the plan itself (names, order, overrides) in-process.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "sweep/sweep_log_tail.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_run_state.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using orogen::testing::slurp;

namespace {

class Sweep : public orogen::testing::TempDirTest {
 protected:
  void SetUp() override {
    ::setenv("OMP_WAIT_POLICY", "passive", 0);
    TempDirTest::SetUp();
    // ~3000 steps of ~60 discs: settles in a fraction of a second, 7 outputs, a checkpoint every second.
    spit(dir_ / "base.toml",
         "[run]\nexperiment = \"packing\"\n"
         "[layer]\nlength = 12.0\nthickness = 4.0\n"
         "[contact]\nkn = 1000.0\n"
         "[settle]\nrelax_time = 1.0\nke_threshold = 1e-3\n"
         "[output]\ninterval = 2.0\ncheckpoint_every = 2\nvtp = false\nprogress = \"never\"\n");
  }

  static void spit(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

  struct Result {
    int status = -1;
    std::string err;
  };

  // Runs `orogen ARGS` (shell syntax) in the test folder.
  Result orogen(const std::string& args) {
    const fs::path err = dir_ / "stderr.txt";
    const std::string cmd =
        "cd '" + dir_.string() + "' && '" + OROGEN_BINARY + "' " + args + " >/dev/null 2>'" + err.string() + "'";
    const int raw = std::system(cmd.c_str());
    Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), slurp(err)};
    fs::remove(err);
    return r;
  }

  // results.csv as header names and rows of cells (RFC 4180 quotes; no line breaks in a cell).
  struct Csv {
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows;
  };
  static Csv read_csv(const fs::path& p) {
    Csv csv;
    std::istringstream in(slurp(p));
    auto split = [](const std::string& line) {
      std::vector<std::string> cells(1);
      bool quoted = false;
      for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') cells.back() += line[i++];
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) cells.emplace_back();
        else cells.back() += c;
      }
      return cells;
    };
    for (std::string line; std::getline(in, line);) {
      if (line.starts_with("#") || line.empty()) continue;
      const auto cells = split(line);
      if (csv.header.empty()) {
        csv.header = cells;
        continue;
      }
      auto& row = csv.rows.emplace_back();
      for (std::size_t j = 0; j < cells.size() && j < csv.header.size(); ++j) row[csv.header[j]] = cells[j];
    }
    return csv;
  }

  // Every file under a folder with its content and modification time.
  static std::map<std::string, std::string> fingerprint(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file())
        out[fs::relative(e.path(), dir).string()] =
            std::to_string(e.last_write_time().time_since_epoch().count()) + "\n" + slurp(e.path());
    return out;
  }
};

TEST_F(Sweep, RunsEveryCombinationAndTabulatesTheSummaries) {
  spit(dir_ / "s.toml",
       "[sweep]\nbase = \"base.toml\"\n"
       "[set]\n\"contact.mu\" = 0.2\n"
       "[matrix]\n\"particles.packing\" = [\"random_discs\", \"random_clusters\"]\n");
  const auto r = orogen("sweep s.toml --out out --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path out = dir_ / "out";
  const Csv csv = read_csv(out / "results.csv");
  for (const char* col : {"name", "particles.packing", "exit_status", "n_discs", "n_clusters", "thickness",
                          "solid_fraction", "porosity", "contacts_per_disc"})
    EXPECT_NE(std::find(csv.header.begin(), csv.header.end(), col), csv.header.end()) << col;
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0].at("name"), "000_packing=random_discs");
  EXPECT_EQ(csv.rows[1].at("name"), "001_packing=random_clusters");
  EXPECT_EQ(csv.rows[0].at("particles.packing"), "random_discs");
  EXPECT_EQ(csv.rows[1].at("particles.packing"), "random_clusters");
  for (const auto& row : csv.rows) {
    SCOPED_TRACE(row.at("name"));
    EXPECT_EQ(row.at("exit_status"), "0");
    EXPECT_GT(std::stod(row.at("n_discs")), 30);
    EXPECT_GT(std::stod(row.at("thickness")), 2.5);
    EXPECT_LT(std::stod(row.at("thickness")), 5.0);
    EXPECT_GT(std::stod(row.at("solid_fraction")), 0.6);
    EXPECT_LT(std::stod(row.at("solid_fraction")), 0.95);
    EXPECT_GT(std::stod(row.at("contacts_per_disc")), 0.5);
    // The table holds the run's own summary.csv values.
    EXPECT_NE(slurp(out / "runs" / row.at("name") / "summary.csv").find(row.at("solid_fraction")), std::string::npos);
    // The run used the fixed and the swept values.
    const orogen::Config c = orogen::Config::load(out / "runs" / row.at("name") / "config.toml", {});
    EXPECT_EQ(c.get_float("contact.mu"), 0.2);
    EXPECT_EQ(c.get_string("particles.packing"), row.at("particles.packing"));
  }
  EXPECT_EQ(csv.rows[0].at("n_clusters"), "0");
  EXPECT_GT(std::stod(csv.rows[1].at("n_clusters")), 5);
  EXPECT_NE(slurp(out / "results.md").find("| 001_packing=random_clusters | random_clusters | 0 |"), std::string::npos)
      << slurp(out / "results.md");

  // The same command again starts nothing and leaves every run file as it was.
  const auto runs_before = fingerprint(out / "runs");
  const auto csv_before = slurp(out / "results.csv");
  const auto again = orogen("sweep s.toml --out out --jobs 2");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("2 finished already, 0 failed before, 0 to continue, 0 to start"), std::string::npos)
      << again.err;
  EXPECT_EQ(again.err.find("started"), std::string::npos) << again.err;
  EXPECT_TRUE(fingerprint(out / "runs") == runs_before);
  EXPECT_EQ(slurp(out / "results.csv"), csv_before);
}

TEST_F(Sweep, ContinuesAKilledRunBitForBitAndRestartsOneWithoutCheckpoint) {
  spit(dir_ / "s.toml", "[sweep]\nbase = \"base.toml\"\n[matrix]\n\"contact.mu\" = [0.3, 0.1]\n");
  // Run 000 dies after its third output (checkpoint after the second), run 001 after its
  // first (no checkpoint yet), each started exactly as the sweep would start it.
  const auto k0 = orogen("run base.toml --set contact.mu=0.3 --out 'out/runs/000_mu=0.3' --threads 1 "
                         "--abort-after-outputs 3");
  ASSERT_EQ(k0.status, 137) << k0.err;
  const auto k1 = orogen("run base.toml --set contact.mu=0.1 --out 'out/runs/001_mu=0.1' --threads 1 "
                         "--abort-after-outputs 1");
  ASSERT_EQ(k1.status, 137) << k1.err;
  ASSERT_TRUE(fs::exists(dir_ / "out/runs/000_mu=0.3/checkpoint.bin"));
  ASSERT_FALSE(fs::exists(dir_ / "out/runs/001_mu=0.1/checkpoint.bin"));

  const auto r = orogen("sweep s.toml --out out --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("1 to continue, 1 to start"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("000_mu=0.3: continuing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("001_mu=0.1: no checkpoint yet; starting it again"), std::string::npos) << r.err;
  EXPECT_NE(slurp(dir_ / "out/runs/000_mu=0.3/run.log").find("resumed at step"), std::string::npos);

  // The same runs done in one go: identical, byte for byte.
  for (const auto& [name, mu] : {std::pair{"000_mu=0.3", "0.3"}, std::pair{"001_mu=0.1", "0.1"}}) {
    SCOPED_TRACE(name);
    const std::string ref = std::string("ref_") + mu;
    const auto whole = orogen("run base.toml --set contact.mu=" + std::string(mu) + " --out " + ref + " --threads 1");
    ASSERT_EQ(whole.status, 0) << whole.err;
    for (const char* f : {"series.csv", "summary.csv", "removals.csv", "checkpoint.bin", "config.toml"})
      EXPECT_TRUE(slurp(dir_ / ref / f) == slurp(dir_ / "out/runs" / name / f)) << f << " differs";
  }
  const Csv csv = read_csv(dir_ / "out/results.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0].at("contact.mu"), "0.3");
  EXPECT_EQ(csv.rows[1].at("contact.mu"), "0.1");
  EXPECT_EQ(csv.rows[0].at("exit_status"), "0");
  EXPECT_EQ(csv.rows[1].at("exit_status"), "0");
}

TEST_F(Sweep, FailedRunIsRecordedAndNotRepeated) {
  // contact.kn = 3 is far too soft: the run stops unstable (exit 3); the other finishes.
  spit(dir_ / "s.toml", "[sweep]\nbase = \"base.toml\"\n[matrix]\n\"contact.kn\" = [1000, 3]\n");
  const auto r = orogen("sweep s.toml --out out --jobs 2");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("001_kn=3: failed (exit 3: unstable)"), std::string::npos) << r.err;
  Csv csv = read_csv(dir_ / "out/results.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows[0].at("exit_status"), "0");
  EXPECT_FALSE(csv.rows[0].at("n_discs").empty());
  EXPECT_EQ(csv.rows[1].at("exit_status"), "3");
  EXPECT_TRUE(csv.rows[1].at("n_discs").empty());
  // The reason is in the table and in the marker: the run's last log line.
  EXPECT_TRUE(csv.rows[0].at("error").empty());
  EXPECT_NE(csv.rows[1].at("error").find("unstable"), std::string::npos) << csv.rows[1].at("error");
  EXPECT_NE(slurp(dir_ / "out/runs/001_kn=3/sweep.failed").find("unstable"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "out/results.md").find("unstable"), std::string::npos);

  const auto again = orogen("sweep s.toml --out out --jobs 2");
  EXPECT_EQ(again.status, 1) << again.err;
  EXPECT_NE(again.err.find("001_kn=3: failed before (exit 3: unstable: stopped"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("started"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("continuing"), std::string::npos) << again.err;
  csv = read_csv(dir_ / "out/results.csv");
  EXPECT_EQ(csv.rows[1].at("exit_status"), "3");
  EXPECT_NE(csv.rows[1].at("error").find("unstable"), std::string::npos) << csv.rows[1].at("error");

  // Removing the member's folder is how to try it again.
  fs::remove_all(dir_ / "out/runs/001_kn=3");
  const auto retry = orogen("sweep s.toml --out out --jobs 2");
  EXPECT_EQ(retry.status, 1) << retry.err;
  EXPECT_NE(retry.err.find("001_kn=3: started"), std::string::npos) << retry.err;
}

TEST_F(Sweep, ResultsAreWrittenForMembersWithoutASummary) {
  spit(dir_ / "s.toml", "[sweep]\nbase = \"base.toml\"\n[matrix]\n\"contact.mu\" = [0.1, 0.2, 0.3]\n");
  ASSERT_EQ(orogen("sweep s.toml --out out --jobs 2").status, 0);
  const fs::path runs = dir_ / "out" / "runs";
  // No summary, a header only, and garbage: each row keeps its name and status, cells empty.
  fs::remove(runs / "000_mu=0.1" / "summary.csv");
  fs::remove(runs / "000_mu=0.1" / "series.csv");
  spit(runs / "001_mu=0.2" / "summary.csv", "# nothing\nn_discs,thickness\n");
  spit(runs / "002_mu=0.3" / "summary.csv", std::string("\x00\xff,,,\n\"\n", 9));
  const auto r = orogen("sweep s.toml --out out --jobs 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv csv = read_csv(dir_ / "out" / "results.csv");
  ASSERT_EQ(csv.rows.size(), 3u);
  for (const auto& row : csv.rows) {
    EXPECT_EQ(row.at("exit_status"), "0");
    EXPECT_TRUE(row.count("n_discs") == 0 || row.at("n_discs").empty()) << row.at("name");
  }
  EXPECT_NE(slurp(dir_ / "out" / "results.md").find("3 finished, 0 failed"), std::string::npos);
}

// A marker written for a verdict (exit 2 or 3) skips the member; anything else is retried.
TEST(SweepRunState, FailedMarkerHoldsAVerdictAndItsReason) {
  const fs::path dir = fs::temp_directory_path() / ("orogen_sweep_state_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto marker = [&](const std::string& text) {
    std::ofstream(dir / orogen::kFailedMarker, std::ios::binary) << text;
    return orogen::inspect_run(dir, "");
  };
  auto s = marker("3\nstopped: simulation became unstable\n");
  EXPECT_EQ(s.stage, orogen::RunStage::Failed);
  EXPECT_EQ(s.failed_status, 3);
  EXPECT_EQ(s.failed_error, "stopped: simulation became unstable");
  s = marker("2\n");  // as older sweeps wrote it
  EXPECT_EQ(s.stage, orogen::RunStage::Failed);
  EXPECT_EQ(s.failed_status, 2);
  EXPECT_EQ(s.failed_error, "");
  for (const char* retried : {"137\n", "134\nterminate called\n", "1\n", "", "garbage"}) {
    EXPECT_EQ(marker(retried).stage, orogen::RunStage::Restart) << retried;
  }
  fs::remove_all(dir);
}

TEST(SweepLogTail, LastLineOfTheLatestAttempt) {
  const fs::path log = fs::temp_directory_path() / ("orogen_sweep_log_" + std::to_string(::getpid()) + ".log");
  std::ofstream(log, std::ios::binary) << "=== 2026-01-01 orogen run a\n[2026-01-01 10:00:00] first reason\n"
                                          "=== 2026-01-02 orogen run --resume a\n[2026-01-02 10:00:00] step 5\n"
                                          "[2026-01-02 10:00:01] stopped: unstable\n\n";
  EXPECT_EQ(orogen::last_log_line(log), "stopped: unstable");
  std::ofstream(log, std::ios::binary | std::ios::app) << "=== 2026-01-03 orogen run --resume a\n";
  EXPECT_EQ(orogen::last_log_line(log), "");  // the latest attempt wrote nothing
  std::ofstream(log, std::ios::binary | std::ios::app) << std::string(100000, 'x') << "\n";
  EXPECT_EQ(orogen::last_log_line(log).size(), 300u);
  fs::remove(log);
  EXPECT_EQ(orogen::last_log_line(log), "");
}

TEST_F(Sweep, BadSweepFilesExitWith2NamingTheKeyAndWriteNothing) {
  struct Case {
    std::string text;
    std::vector<std::string> expect;  // in stderr
  };
  const std::string base = "[sweep]\nbase = \"base.toml\"\n";
  const std::vector<Case> cases = {
      {base + "[matrix]\n\"contact.muu\" = [0.1]\n", {"bad.toml, line 4", "contact.muu", "unknown key", "contact.mu"}},
      {base + "[matrix]\n\"contact.mu\" = [0.1, -1]\n", {"bad.toml, line 4", "contact.mu = -1", "must be >= 0"}},
      {base + "[matrix]\n\"particles.packing\" = [\"square\"]\n",
       {"particles.packing = \"square\"", "\"hexagonal\", \"random_discs\", \"random_clusters\""}},
      {base + "[matrix]\n\"contact.mu\" = []\n", {"contact.mu", "at least one value"}},
      {base + "[matrix]\n\"contact.mu\" = 0.1\n", {"contact.mu = 0.1", "a list of values"}},
      {base + "[matrix]\n\"contact.mu\" = [0.1, 0.1]\n", {"contact.mu = 0.1", "listed twice"}},
      {base + "[set]\n\"output.vtp\" = \"no\"\n", {"bad.toml, line 4", "output.vtp = \"no\"", "true or false"}},
      {base + "[matrix]\n\"particles.d_min\" = [0.5, 0.9]\n\"particles.d_max\" = [0.8]\n",
       {"run 001_d_min=0.9_d_max=0.8", "particles.d_min = 0.9", "must not exceed particles.d_max = 0.8"}},
      {base + "[matirx]\n\"contact.mu\" = [0.1]\n", {"[matirx]", "unknown table", "[matrix]"}},
      {base + "bsae = 1\n", {"sweep.bsae", "keys in [sweep]: base"}},
      {"[matrix]\n\"contact.mu\" = [0.1]\n", {"sweep.base", "missing"}},
      {"[sweep]\nbase = \"nope.toml\"\n", {"sweep.base = \"nope.toml\"", "does not exist"}},
      {base + "[matrix]\n\"contact.mu\" = [0.1,\n", {"bad.toml, line", "TOML syntax error"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    spit(dir_ / "bad.toml", c.text);
    const auto r = orogen("sweep bad.toml --out out");
    EXPECT_EQ(r.status, 2) << r.err;
    for (const auto& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << "expected '" << e << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
  EXPECT_EQ(orogen("sweep missing.toml --out out").status, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Sweep, RefusesAFolderHoldingARunOfAnotherConfiguration) {
  spit(dir_ / "s.toml", "[sweep]\nbase = \"base.toml\"\n[matrix]\n\"contact.mu\" = [0.3]\n");
  ASSERT_EQ(orogen("run base.toml --set contact.mu=0.2 --out 'out/runs/000_mu=0.3' --threads 1 "
                   "--abort-after-outputs 1").status,
            137);
  const auto r = orogen("sweep s.toml --out out");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("contact.mu = 0.2 there, 0.3 now"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out/results.csv"));
}

// Every sweep in examples/sweeps/ names an existing base and valid values for all its runs.
TEST(SweepPlan, EveryExampleSweepLoads) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(fs::path(OROGEN_SOURCE_DIR) / "examples" / "sweeps")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    try {
      EXPECT_GE(orogen::load_sweep(e.path()).runs.size(), 2u);  // a matrix, not a single run
    } catch (const std::exception& err) {
      ADD_FAILURE() << err.what();
    }
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(SweepPlan, NamesOrderAndOverrides) {
  const fs::path dir = fs::temp_directory_path() / ("orogen_sweep_plan_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "base.toml") << "[run]\nexperiment = \"packing\"\n";
  // Dotted keys, quoted keys and sub-tables name the same configuration keys.
  std::ofstream(dir / "sub" / "s.toml") << "[sweep]\nbase = \"../base.toml\"\n"
                                           "[set.output]\nvtp = false\n"
                                           "[matrix]\nparticles.packing = [\"hexagonal\", \"random_clusters\"]\n"
                                           "\"contact.mu\" = [0.3, 0.1, 0.03]\n"
                                           "settle.mu = [0.0]\n";
  const auto plan = orogen::load_sweep(dir / "sub" / "s.toml");
  fs::remove_all(dir);
  EXPECT_EQ(plan.base, dir / "base.toml");
  ASSERT_EQ(plan.axes.size(), 3u);
  EXPECT_EQ(plan.axes[0].key, "particles.packing");
  // Two keys end in "mu": both are named in full.
  EXPECT_EQ(plan.axes[1].label, "contact.mu");
  EXPECT_EQ(plan.axes[2].label, "settle.mu");
  ASSERT_EQ(plan.runs.size(), 6u);
  EXPECT_EQ(plan.runs[0].name, "000_packing=hexagonal_contact.mu=0.3_settle.mu=0.0");
  EXPECT_EQ(plan.runs[4].name, "004_packing=random_clusters_contact.mu=0.1_settle.mu=0.0");
  EXPECT_EQ(plan.runs[4].overrides,
            (std::vector<std::string>{"output.vtp=false", "particles.packing=\"random_clusters\"", "contact.mu=0.1",
                                      "settle.mu=0.0"}));
  EXPECT_NE(plan.runs[5].resolved_toml.find("mu = 0.03"), std::string::npos);
}

}  // namespace
