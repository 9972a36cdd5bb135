// The `orogen` command line end to end: determinism across thread counts, resume after a
// kill, refusal of bad input (exit 2, nothing written) and the printed default config.
#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "temp_dir_fixture.hpp"
#include "tmpfs_mount.hpp"
#include "util/parallel.hpp"
#include <signal.h>
#include <spawn.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/snapshot_reader.hpp"
#include "io/snapshot_writer.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace orogen;

namespace {

// A fresh directory per test, removed afterwards.
class Cli : public orogen::testing::TempDirTest {
 protected:
  void SetUp() override {
    // Idle OpenMP threads sleep instead of spinning: on a loaded 2-core machine a spinning
    // team makes the 2-thread runs 10-100x slower. Results do not depend on it.
    ::setenv("OMP_WAIT_POLICY", "passive", 0);
    TempDirTest::SetUp();
  }
};

using orogen::testing::decode_exit_status;
using orogen::testing::run_orogen;
using orogen::testing::slurp;
using orogen::testing::spit;

// Small settling runs (tenths of a second). Thread counts only matter above
// kMinParallelItems (16384) discs, so the determinism runs use ~17000-18000 discs and
// stop after 600 steps (every rest check passes at once with a huge threshold).
std::string big_short(const std::string& packing) {
  return "--set run.experiment=packing --set particles.packing=" + packing + " --set layer.length=" + (packing == "hexagonal" ? "700" : "620") +
         " --set layer.thickness=20 --set settle.relax_time=0 --set settle.ke_threshold=1e9"
         " --set output.interval=0.25 --set output.checkpoint_every=2 --set output.progress=never --set output.vtp=false";
}
// Settles for real: ~3000 steps of 45 discs, 7 outputs with a checkpoint every second one.
// Few outputs: each costs a dozen fsyncs, which dominate these runs.
const std::string kTiny =
    "--set run.experiment=packing --set particles.packing=random_discs --set layer.length=10"
    " --set layer.thickness=3 --set contact.kn=1000"
    " --set settle.relax_time=1 --set settle.ke_threshold=1e-3 --set output.interval=2"
    " --set output.checkpoint_every=2 --set output.progress=never --threads 1";

std::uint64_t fnv1a(const void* data, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}
template <class T>
std::uint64_t hash_of(const std::vector<T>& v) {
  return fnv1a(v.data(), v.size() * sizeof(T)) ^ v.size();
}
std::uint64_t hash_of(const std::string& s) { return fnv1a(s.data(), s.size()); }
std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Content hash of everything a reader sees in a snapshot file (snapshots.h5, packing.h5):
// root metadata, the names of the links under the root, and per output its step, time,
// attributes and every dataset. HDF5 files themselves are not byte-comparable (object
// time stamps, space left by deleted groups).
std::map<std::string, std::uint64_t> snapshot_digest(const fs::path& file) {
  std::map<std::string, std::uint64_t> d;
  std::string links;
  {
    auto f = h5::File::open(file, h5::File::Mode::ReadOnly);
    for (const auto& name : h5::list(f.id())) links += name + "\n";
  }
  d["links under /"] = hash_of(links);
  const SnapshotReader r(file);
  d["n_outputs"] = static_cast<std::uint64_t>(r.count());
  for (const auto& [k, v] : r.metadata().numbers) d["meta " + k] = bits_of(v);
  for (const auto& [k, v] : r.metadata().strings) d["meta " + k] = hash_of(v);
  for (std::int64_t k = 0; k < r.count(); ++k) {
    const Snapshot s = r.read(k);
    const std::string g = snapshot_group_name(k) + "/";
    d[g + "step"] = static_cast<std::uint64_t>(s.step);
    d[g + "time"] = bits_of(s.time);
    for (const auto& [name, v] : s.attrs) d[g + "@" + name] = bits_of(v);
    for (const auto& [name, v] : s.fields) d[g + name] = hash_of(v);
    d[g + "id"] = hash_of(s.id);
    d[g + "cluster_id"] = hash_of(s.cluster_id);
    d[g + "motion"] = hash_of(s.motion);
    d[g + "walls"] = hash_of(s.walls);
    EXPECT_TRUE(s.fields.contains("x") && s.fields.contains("y") && s.fields.contains("radius")) << file << " " << g;
    EXPECT_GT(s.size(), 0u) << file << " " << g;
  }
  return d;
}

void expect_same_snapshots(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  const auto da = snapshot_digest(a), db = snapshot_digest(b);
  EXPECT_EQ(da.size(), db.size()) << a << " vs " << b;
  int shown = 0;
  for (const auto& [key, h] : da) {
    const auto it = db.find(key);
    if (it == db.end()) {
      ADD_FAILURE() << key << " is in " << a << " but not in " << b;
    } else if (it->second != h) {
      ADD_FAILURE() << key << " differs between " << a << " and " << b;
    } else {
      continue;
    }
    if (++shown == 10) break;
  }
}

void expect_same_bytes(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  EXPECT_TRUE(slurp(a) == slurp(b)) << a << " and " << b << " differ";
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

// Two finished runs hold the same results: every snapshot dataset, packing.h5 (if any), and the
// text outputs byte for byte (vtp files, when written).
void expect_same_run(const fs::path& a, const fs::path& b) {
  expect_same_snapshots(a / "snapshots.h5", b / "snapshots.h5");
  if (fs::exists(a / "packing.h5") || fs::exists(b / "packing.h5"))
    expect_same_snapshots(a / "packing.h5", b / "packing.h5");
  for (const char* f : {"series.csv", "removals.csv", "checkpoint.bin"}) expect_same_bytes(a / f, b / f);
  EXPECT_EQ(fs::exists(a / "run.pvd"), fs::exists(b / "run.pvd"));
  if (fs::exists(a / "run.pvd")) expect_same_bytes(a / "run.pvd", b / "run.pvd");
  const auto vtp_a = names_in(a / "vtp"), vtp_b = names_in(b / "vtp");
  EXPECT_EQ(vtp_a, vtp_b);
  for (const auto& f : vtp_a) expect_same_bytes(a / "vtp" / f, b / "vtp" / f);
}

std::int64_t outputs_in(const fs::path& run) { return SnapshotReader(run / "snapshots.h5").count(); }

TEST_F(Cli, SameSeedSameOutputsForOneAndTwoThreads) {
  for (const std::string packing : {"hexagonal", "random_discs", "random_clusters"}) {
    SCOPED_TRACE(packing);
    const fs::path one = dir_ / (packing + "_1"), two = dir_ / (packing + "_2");
    const auto r1 = run_orogen("run --out '" + one.string() + "' --threads 1 " + big_short(packing), dir_);
    ASSERT_EQ(r1.status, 0) << r1.err;
    const auto r2 = run_orogen("run --out '" + two.string() + "' --threads 2 " + big_short(packing), dir_);
    ASSERT_EQ(r2.status, 0) << r2.err;
    EXPECT_NE(slurp(one / "run.log").find("with 1 thread(s)"), std::string::npos);
    EXPECT_NE(slurp(two / "run.log").find("with 2 thread(s)"), std::string::npos);
    EXPECT_GE(outputs_in(one), 4);
    expect_same_run(one, two);
    // Above the parallel threshold, so the 2-thread run took its parallel paths.
    EXPECT_GT(SnapshotReader(one / "snapshots.h5").read(0).size(), static_cast<std::size_t>(kMinParallelItems));
  }
}

// Every experiment, small, with the parallel threshold lowered so that two threads take the
// parallel paths of every loop: the outputs must not depend on the thread count.
TEST_F(Cli, EveryExperimentSameOutputsForOneAndTwoThreads) {
  const std::string quiet = " --set output.progress=never --set output.vtp=false";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"repose", "--set run.experiment=repose --set particles.packing=random_clusters --set repose.size=16"
                 " --set repose.min_time=5 --set repose.max_time=15"},
      {"singly", "--set run.experiment=singly_vergent --set particles.packing=random_discs --set layer.length=60"
                 " --set layer.thickness=6 --set contact.kn=2000 --set singly.speed=0.05 --set singly.shortening=1"
                 " --set singly.outputs=5"},
      {"biaxial", "--set run.experiment=biaxial --set particles.packing=random_clusters --set biaxial.width=10"
                  " --set biaxial.height=20 --set biaxial.strain_rate=5e-4 --set biaxial.strain_end=0.02"
                  " --set biaxial.outputs=6"},
      {"wedge", "--set run.experiment=wedge --set layer.thickness=5 --set wedge.tile_length=4"
                " --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.s_end=0.2 --set wedge.outputs=4"
                " --set wedge.erosion_height=0.9"},
      // Constant velocity: its pinning hook runs inside the step's thread team.
      {"wedge_cv", "--set run.experiment=wedge --set layer.thickness=5 --set wedge.tile_length=4"
                   " --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.s_end=0.2 --set wedge.outputs=4"
                   " --set wedge.basal=constant_velocity"},
      // The same with the thread count switched between 2 and 1 every few milliseconds.
      {"wedge_switching", "--set run.experiment=wedge --set layer.thickness=5 --set wedge.tile_length=4"
                          " --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.s_end=0.2"
                          " --set wedge.outputs=4 --set wedge.erosion_height=0.9 --set run.adapt_slice=0.002"},
  };
  for (const auto& [name, args] : runs) {
    SCOPED_TRACE(name);
    const fs::path one = dir_ / (name + "_1"), two = dir_ / (name + "_2");
    const std::string env = "OROGEN_MIN_PARALLEL_ITEMS=16 ";
    const auto r1 = run_orogen("run --out '" + one.string() + "' --threads 1 " + args + quiet, dir_, env);
    ASSERT_EQ(r1.status, 0) << r1.err;
    const auto r2 = run_orogen("run --out '" + two.string() + "' --threads 2 " + args + quiet, dir_, env);
    ASSERT_EQ(r2.status, 0) << r2.err;
    EXPECT_GE(outputs_in(one), 3);
    expect_same_snapshots(one / "snapshots.h5", two / "snapshots.h5");
    for (const char* f : {"series.csv", "summary.csv", "removals.csv", "checkpoint.bin"})
      if (fs::exists(one / f) || fs::exists(two / f)) expect_same_bytes(one / f, two / f);
    if (name == "wedge_switching") {  // it did step on both counts
      const std::string log = slurp(two / "run.log");
      EXPECT_NE(log.find("threads: 2 thread(s) for"), std::string::npos) << log;
      EXPECT_NE(log.find(", 1 thread(s) for"), std::string::npos) << log;
    }
  }
  const auto bad = run_orogen("run --out '" + (dir_ / "bad").string() + "' " + kTiny, dir_,
                              "OROGEN_MIN_PARALLEL_ITEMS=lots ");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("OROGEN_MIN_PARALLEL_ITEMS = 'lots'"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

TEST_F(Cli, ResumeAfterKillIsBitwiseIdentical) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  const auto ra = run_orogen("run --out '" + a.string() + "' " + kTiny, dir_);
  ASSERT_EQ(ra.status, 0) << ra.err;
  ASSERT_GE(outputs_in(a), 5);

  // Dies right after its third output; the last checkpoint was taken after the second, so
  // the third (snapshot group, vtp file, series row) must be dropped and written again.
  const auto rb = run_orogen("run --out '" + b.string() + "' --abort-after-outputs 3 " + kTiny, dir_);
  ASSERT_EQ(rb.status, 137) << rb.err;
  EXPECT_FALSE(fs::exists(b / "packing.h5"));
  EXPECT_EQ(outputs_in(b), 3);
  EXPECT_TRUE(fs::exists(b / "vtp" / "output_000002.vtp"));
  EXPECT_FALSE(fs::exists(b / "vtp" / "output_000003.vtp"));

  const auto rr = run_orogen("run --resume '" + b.string() + "'", dir_);
  ASSERT_EQ(rr.status, 0) << rr.err;
  EXPECT_NE(slurp(b / "run.log").find("resumed at step"), std::string::npos);
  EXPECT_EQ(outputs_in(b), outputs_in(a));
  expect_same_run(a, b);
  expect_same_bytes(a / "config.toml", b / "config.toml");

  // A finished run cannot be resumed again.
  const auto again = run_orogen("run --resume '" + b.string() + "'", dir_);
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("already finished"), std::string::npos) << again.err;
}

// Starts `orogen run ARGS` (words split on blanks, quotes stripped), sends `sig` as soon as
// `marker` exists, and returns the exit status (128 + signal when killed); stderr goes to
// `err`. Returns 0 if the run finished before the marker appeared.
int signal_when_written(const std::string& args_text, const fs::path& marker, int sig, const fs::path& err) {
  std::vector<std::string> args = {OROGEN_BINARY, "run"};
  {
    std::istringstream in(args_text);
    for (std::string w; in >> w;) {
      w.erase(std::remove(w.begin(), w.end(), '\''), w.end());
      args.push_back(w);
    }
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  if (posix_spawn(&pid, OROGEN_BINARY, &actions, nullptr, argv.data(), environ) != 0) return -1;
  posix_spawn_file_actions_destroy(&actions);
  int raw = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(marker) && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &raw, WNOHANG) == pid) return decode_exit_status(raw);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(pid, sig);
  ::waitpid(pid, &raw, 0);
  return decode_exit_status(raw);
}

// A real SIGKILL at an arbitrary point while output 4 (after the checkpoint taken at 4
// outputs) is being written or just after.
TEST_F(Cli, ResumeAfterSigkillIsBitwiseIdentical) {
  const std::string slow = kTiny + " --set settle.relax_time=20";  // ~5000 steps left after the kill
  const fs::path a = dir_ / "a", b = dir_ / "b";
  const auto ra = run_orogen("run --out '" + a.string() + "' " + slow, dir_);
  ASSERT_EQ(ra.status, 0) << ra.err;

  const int status = signal_when_written(slow + " --out '" + b.string() + "'", b / "vtp" / "output_000004.vtp",
                                         SIGKILL, dir_ / "killed.err");
  if (status == 0) GTEST_SKIP() << "the run finished before it could be killed (machine too loaded?)";
  ASSERT_EQ(status, 128 + SIGKILL) << slurp(dir_ / "killed.err");
  ASSERT_TRUE(fs::exists(b / "checkpoint.bin"));
  EXPECT_FALSE(fs::exists(b / "packing.h5"));

  const auto rr = run_orogen("run --resume '" + b.string() + "'", dir_);
  ASSERT_EQ(rr.status, 0) << rr.err;
  expect_same_run(a, b);
}

TEST_F(Cli, BadInputsExitWith2AndWriteNothing) {
  // A finished run and one killed before its first checkpoint, for the cases that need one.
  const fs::path done = dir_ / "done", early = dir_ / "early";
  ASSERT_EQ(run_orogen("run --out '" + done.string() + "' " + kTiny, dir_).status, 0);
  ASSERT_EQ(run_orogen("run --out '" + early.string() + "' --abort-after-outputs 1 " + kTiny, dir_).status, 137);
  ASSERT_FALSE(fs::exists(early / "checkpoint.bin"));
  auto fingerprint = [](const fs::path& run) {
    std::map<std::string, std::string> files;  // run.log may grow: refused resumes are logged
    for (const auto& f : names_in(run))
      if (f != "run.log" && fs::is_regular_file(run / f)) files[f] = slurp(run / f);
    return files;
  };
  const auto done_before = fingerprint(done), early_before = fingerprint(early);
  ASSERT_FALSE(done_before.empty());

  spit(dir_ / "syntax.toml", "[layer]\nlength = = 3\n");
  spit(dir_ / "type.toml", "[contact]\nmu = \"high\"\n");
  spit(dir_ / "key.toml", "[contact]\nfoo = 1\n");
  spit(dir_ / "a_file", "");
  const std::string d = "'" + dir_.string() + "/";

  struct Case {
    std::string args;
    std::vector<std::string> expect;  // in stderr
    bool fresh = true;                // --out 'new' must stay absent
  };
  const std::vector<Case> cases = {
      {d + "syntax.toml' --out " + d + "new'", {"syntax.toml, line 2", "TOML syntax error"}},
      {d + "type.toml' --out " + d + "new'", {"contact.mu = \"high\"", "expected a number >= 0"}},
      {d + "key.toml' --out " + d + "new'", {"contact.foo", "unknown key", "mu_wall"}},
      {d + "missing.toml' --out " + d + "new'", {"missing.toml", "cannot read the file"}},
      {"--out " + d + "new' --set contact.mu=-1", {"contact.mu = -1", "must be >= 0"}},
      {"--out " + d + "new' --set output.checkpoint_every=1.5", {"output.checkpoint_every = 1.5", "integer"}},
      {"--out " + d + "new' --set output.vtp=maybe", {"output.vtp = maybe", "true or false"}},
      {"--out " + d + "new' --set particles.packing=square",
       {"particles.packing = square", "\"hexagonal\", \"random_discs\", \"random_clusters\""}},
      {"--out " + d + "new' --set contact.foo=1", {"--set", "contact.foo", "unknown key"}},
      {"--out " + d + "new' --set nosuch.x=1", {"unknown section [nosuch]"}},
      {"--out " + d + "new' --set contact.mu", {"contact.mu", "section.key=value"}},
      {"--out " + d + "new' --set particles.d_min=0.9 --set particles.d_max=0.8",
       {"particles.d_min = 0.9", "must not exceed particles.d_max = 0.8"}},
      {"--out " + d + "new' --set time.dt=1", {"time.dt = 1", "stability limit"}},
      {"--out " + d + "new' --set contact.normal_force=hooke_cubic",
       {"contact.normal_force = hooke_cubic", "\"linear\", \"linear_pull\", \"hertz\""}},
      {"--out " + d + "new' --set contact.normal_force=linear_pull",
       {"contact.damping = restitution", "\"per_mass\" with contact.normal_force = \"linear_pull\""}},
      {"--out " + d + "new' --set contact.damping=per_mass --set contact.damping_rate=-1",
       {"contact.damping_rate = -1", "must be >= 0"}},
      {"--out " + d + "new' --set run.experiment=singly_vergent --set singly.speed=0.5 --set singly.speed_bound=refuse",
       {"singly.speed = 0.5", "thesis eq. 4.3"}},
      {"--out " + d + "new' --set particles.packing=hexagonal --set particles.placement=rain",
       {"particles.placement = rain", "applies to the random packings"}},
      {"--out " + d + "new' --set wedge.gamma_b=30", {"wedge.gamma_b = 30.0", "wedge.traction_law = \"drag\""}},
      {"--out " + d + "new' --set wedge.traction_law=viscous", {"wedge.traction_law = viscous", "\"spring\", \"drag\""}},
      {"--out " + d + "new' --threads abc", {"--threads"}},
      {"--out " + d + "new' --bogus", {"--bogus"}},
      {"--out " + d + "a_file'", {"a_file", "cannot create the run folder"}},
      {"--out ''", {"--out needs a folder"}},
      {"--out " + d + "done'", {"already holds a run", "--resume"}},
      {"--resume " + d + "new'", {"no such folder"}},
      {"--resume " + d + "done' --set contact.mu=0.2", {"--set contact.mu=0.2 would change what the run computes"}},
      {"--resume " + d + "done' " + d + "type.toml'", {"drop CONFIG"}},
      {"--resume " + d + "done'", {"already finished"}, false},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("orogen run " + c.args);
    const auto r = run_orogen("run " + c.args, dir_);
    EXPECT_EQ(r.status, 2) << r.err;
    for (const auto& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << "expected '" << e << "' in: " << r.err;
    if (c.fresh) {
      EXPECT_FALSE(fs::exists(dir_ / "new")) << "written: " << ::testing::PrintToString(names_in(dir_ / "new"));
    }
    fs::remove_all(dir_ / "new");
  }

  // An empty folder given to --resume stays empty.
  fs::create_directories(dir_ / "empty");
  const auto r = run_orogen("run --resume " + d + "empty'", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no run there"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir_ / "empty"));

  // The runs that were refused are untouched.
  EXPECT_TRUE(fingerprint(done) == done_before);
  EXPECT_TRUE(fingerprint(early) == early_before);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "a_file") && fs::file_size(dir_ / "a_file") == 0);
}

TEST_F(Cli, DefaultRunNeedsNoConfig) {
  const auto printed = run_orogen("config", dir_);
  ASSERT_EQ(printed.status, 0) << printed.err;
  EXPECT_NE(printed.out.find("[run]"), std::string::npos);
  EXPECT_NE(printed.out.find("experiment = \"wedge\""), std::string::npos);
  spit(dir_ / "default.toml", printed.out);

  // The printed default reads back and runs ...
  const fs::path from_file = dir_ / "from_file", built_in = dir_ / "built_in";
  const auto r1 = run_orogen("run '" + (dir_ / "default.toml").string() + "' --out '" + from_file.string() + "' " + kTiny,
                             dir_);
  ASSERT_EQ(r1.status, 0) << r1.err;
  EXPECT_GE(outputs_in(from_file), 2);
  EXPECT_TRUE(fs::exists(from_file / "packing.h5"));
  // ... and is the built-in default: no CONFIG, same overrides, same resolved config and results.
  const auto r2 = run_orogen("run --out '" + built_in.string() + "' " + kTiny, dir_);
  ASSERT_EQ(r2.status, 0) << r2.err;
  expect_same_bytes(from_file / "config.toml", built_in / "config.toml");
  expect_same_run(from_file, built_in);
  EXPECT_NE(slurp(built_in / "config.toml").find("length = 10"), std::string::npos);

  // The config.toml a run writes is itself a valid CONFIG that resolves to the same text.
  const fs::path again = dir_ / "again";
  const auto r3 = run_orogen("run '" + (built_in / "config.toml").string() + "' --out '" + again.string() +
                                 "' --threads 1",
                             dir_);
  ASSERT_EQ(r3.status, 0) << r3.err;
  expect_same_bytes(built_in / "config.toml", again / "config.toml");
  expect_same_run(built_in, again);
}

}  // namespace

TEST_F(Cli, UnstableRunStopsWithExit3AndNamesTheCause) {
  // Contacts far too soft for the weight: the discs sink into each other.
  const auto r = run_orogen("run --out '" + (dir_ / "soft").string() +
                                "' --set run.experiment=packing --set layer.length=20 --set layer.thickness=4"
                                " --set contact.kn=3 --set output.progress=never",
                            dir_);
  EXPECT_EQ(r.status, 3);
  const std::string log = slurp(dir_ / "soft" / "run.log");
  EXPECT_NE(log.find("became unstable"), std::string::npos) << log;
  EXPECT_NE(log.find("k_n = 3 is too soft for the load"), std::string::npos) << log;
}

TEST_F(Cli, WedgeStartsFromAPackingFileAndRefusesAWrongOne) {
  const std::string quiet = " --set output.progress=never --set output.vtp=false --threads 1";
  const auto packing = run_orogen("run --out '" + (dir_ / "layer").string() +
                                      "' --set run.experiment=packing --set layer.length=40"
                                      " --set layer.thickness=6" + quiet,
                                  dir_);
  ASSERT_EQ(packing.status, 0) << packing.err;
  const std::string file = (dir_ / "layer" / "packing.h5").string();
  const auto wedge = run_orogen("run --out '" + (dir_ / "wedge").string() + "' --set layer.thickness=6"
                                    " --set wedge.packing_file='" + file + "' --set wedge.s_end=0.02"
                                    " --set wedge.outputs=2" + quiet,
                                dir_);
  ASSERT_EQ(wedge.status, 0) << wedge.err;
  EXPECT_EQ(outputs_in(dir_ / "wedge"), 3);
  // A packing of another thickness, and a file that is no packing: exit 2, nothing written.
  const auto thick = run_orogen("run --out '" + (dir_ / "bad1").string() + "' --set layer.thickness=8"
                                    " --set wedge.packing_file='" + file + "'" + quiet,
                                dir_);
  EXPECT_EQ(thick.status, 2);
  EXPECT_NE(thick.err.find("set layer.thickness = 6"), std::string::npos) << thick.err;
  const auto junk = run_orogen("run --out '" + (dir_ / "bad2").string() + "' --set wedge.packing_file='" +
                                   (dir_ / "layer" / "config.toml").string() + "'" + quiet,
                               dir_);
  EXPECT_EQ(junk.status, 2);
  EXPECT_NE(junk.err.find("wedge.packing_file"), std::string::npos) << junk.err;
  // An HDF5 file of another kind (a run's snapshots): said once, with what the file holds.
  const auto other = run_orogen("run --out '" + (dir_ / "bad3").string() + "' --set wedge.packing_file='" +
                                    (dir_ / "wedge" / "snapshots.h5").string() + "'" + quiet,
                                dir_);
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.err.find("has no content attribute"), std::string::npos) << other.err;
  const auto first = other.err.find("packing run");
  EXPECT_NE(first, std::string::npos) << other.err;
  EXPECT_EQ(other.err.find("packing run", first + 1), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad1"));
  EXPECT_FALSE(fs::exists(dir_ / "bad2"));
  EXPECT_FALSE(fs::exists(dir_ / "bad3"));
}

TEST_F(Cli, WedgeResumeAfterKillIsBitwiseIdentical) {
  // Inflow (a tile stamped after the kill), erosion and per-output fields all cross the resume.
  const std::string small =
      " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4 --set wedge.window=3"
      " --set wedge.s_end=0.3 --set wedge.outputs=6 --set wedge.erosion_height=0.9 --set output.checkpoint_every=2"
      " --set output.progress=never --set output.vtp=false --threads 1";
  const fs::path a = dir_ / "whole", b = dir_ / "killed";
  ASSERT_EQ(run_orogen("run --out '" + a.string() + "'" + small, dir_).status, 0);
  EXPECT_NE(run_orogen("run --out '" + b.string() + "'" + small + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("run --resume '" + b.string() + "'", dir_).status, 0);
  EXPECT_NE(slurp(a / "removals.csv").find("eroded"), std::string::npos);
  expect_same_bytes(a / "series.csv", b / "series.csv");
  expect_same_bytes(a / "removals.csv", b / "removals.csv");
  expect_same_bytes(a / "checkpoint.bin", b / "checkpoint.bin");
  expect_same_snapshots(a / "snapshots.h5", b / "snapshots.h5");
}

TEST_F(Cli, ConstantVelocityWedgeResumeIsBitwiseIdentical) {
  // The pinning hook is added again after the checkpoint is loaded; what it depends on (the
  // pinned discs, their motion, the wall contacts) crosses the resume.
  const std::string small =
      " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
      " --set wedge.basal=constant_velocity --set wedge.s_end=0.3 --set wedge.outputs=6 --set output.checkpoint_every=2"
      " --set output.progress=never --set output.vtp=false --threads 2";
  const fs::path a = dir_ / "whole", b = dir_ / "killed";
  ASSERT_EQ(run_orogen("run --out '" + a.string() + "'" + small, dir_).status, 0);
  EXPECT_NE(run_orogen("run --out '" + b.string() + "'" + small + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("run --resume '" + b.string() + "'", dir_).status, 0);
  expect_same_bytes(a / "series.csv", b / "series.csv");
  expect_same_bytes(a / "checkpoint.bin", b / "checkpoint.bin");
  expect_same_snapshots(a / "snapshots.h5", b / "snapshots.h5");
}

// ---- A run folder is owned by one run, and every failure leaves it resumable (issue 14) ----

namespace {

using orogen::testing::mount_tmpfs;
using orogen::testing::remount;
using orogen::testing::Unmount;

std::vector<std::string> temporary_files_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& name : names_in(dir))
    if (name.find(".tmp-") != std::string::npos) out.push_back(name);
  return out;
}

}  // namespace

TEST_F(Cli, ResumeRemovesTheTemporaryFilesOfAKilledWrite) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run_orogen("run --out '" + a.string() + "' " + kTiny, dir_).status, 0);
  ASSERT_EQ(run_orogen("run --out '" + b.string() + "' --abort-after-outputs 3 " + kTiny, dir_).status, 137);
  // What a kill in the middle of each kind of write leaves.
  for (const fs::path& stray : {b / "series.csv.tmp-4242", b / "checkpoint.bin.tmp-4242",
                                b / "snapshots" / "output_000003.h5.tmp-4242", b / "vtp" / "output_000003.vtp.tmp-7"})
    spit(stray, "half written");
  const auto r = run_orogen("run --resume '" + b.string() + "'", dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(temporary_files_in(b), std::vector<std::string>{});
  EXPECT_NE(slurp(b / "run.log").find("removed 4 temporary file(s)"), std::string::npos);
  expect_same_run(a, b);
}

TEST_F(Cli, AFolderWithRunFilesButNoConfigIsRefusedAndKept) {
  const fs::path run = dir_ / "orphan";
  fs::create_directories(run);
  spit(run / "snapshots.h5", "precious");
  spit(run / "series.csv", "precious too");
  const auto r = run_orogen("run --out '" + run.string() + "' " + kTiny, dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("holds files of a run (snapshots.h5, series.csv) but no config.toml"), std::string::npos)
      << r.err;
  EXPECT_EQ(names_in(run), (std::vector<std::string>{"series.csv", "snapshots.h5"}));
  EXPECT_EQ(slurp(run / "snapshots.h5"), "precious");
}

TEST_F(Cli, AFolderHeldByAnotherRunIsRefused) {
  const fs::path run = dir_ / "busy";
  fs::create_directories(run);
  const int fd = ::open((run / "run.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);  // as a running orogen holds it
  const auto r = run_orogen("run --out '" + run.string() + "' " + kTiny, dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("in use by another orogen process"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(run), std::vector<std::string>{"run.lock"});
  ::close(fd);
}

TEST_F(Cli, TwoRunsStartedIntoOneNewFolderCannotBothRun) {
  const fs::path run = dir_ / "shared";
  const std::string cmd = "'" + std::string(OROGEN_BINARY) + "' run --out '" + run.string() + "' " + kTiny;
  // Both start at once; whichever claims the folder first runs, the other is refused.
  const std::string both = "(" + cmd + " >'" + (dir_ / "out1").string() + "' 2>&1; echo $? >'" +
                           (dir_ / "rc1").string() + "') & (" + cmd + " >'" + (dir_ / "out2").string() +
                           "' 2>&1; echo $? >'" + (dir_ / "rc2").string() + "') & wait";
  spit(dir_ / "both.sh", both + "\n");
  ASSERT_EQ(std::system(("bash '" + (dir_ / "both.sh").string() + "'").c_str()), 0);
  std::vector<std::string> codes = {slurp(dir_ / "rc1"), slurp(dir_ / "rc2")};
  std::sort(codes.begin(), codes.end());
  EXPECT_EQ(codes, (std::vector<std::string>{"0\n", "2\n"}));
  const std::string refused = slurp(dir_ / (slurp(dir_ / "rc1") == "2\n" ? "out1" : "out2"));
  EXPECT_TRUE(refused.find("in use by another orogen process") != std::string::npos ||
              refused.find("already holds a run") != std::string::npos)
      << refused;
  const std::string log = slurp(run / "run.log");
  EXPECT_EQ(log.find("orogen " OROGEN_VERSION " run in"), log.rfind("orogen " OROGEN_VERSION " run in")) << log;
}

TEST_F(Cli, ResumeRefusesFilesOfAnotherRunNamingWhatDiffers) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run_orogen("run --out '" + a.string() + "' --abort-after-outputs 3 " + kTiny, dir_).status, 137);
  ASSERT_EQ(run_orogen("run --out '" + b.string() + "' --abort-after-outputs 3 --set run.seed=2 " + kTiny, dir_).status,
            137);
  const auto before = names_in(a);
  auto resume_a = [&] { return run_orogen("run --resume '" + a.string() + "'", dir_); };

  // A checkpoint copied from another seed's run.
  fs::copy_file(a / "checkpoint.bin", dir_ / "own.bin");
  fs::copy_file(b / "checkpoint.bin", a / "checkpoint.bin", fs::copy_options::overwrite_existing);
  auto r = resume_a();
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("run.seed = 1 in config.toml, 2 in the checkpoint"), std::string::npos) << r.err;
  fs::copy_file(dir_ / "own.bin", a / "checkpoint.bin", fs::copy_options::overwrite_existing);

  // A config.toml edited after the start.
  const std::string config = slurp(a / "config.toml");
  std::string edited = config;
  edited.replace(edited.find("kn = 1000.0"), 11, "kn = 2000.0");
  spit(a / "config.toml", edited);
  r = resume_a();
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("contact.kn = 2000.0 in config.toml, 1000.0 in the checkpoint"), std::string::npos) << r.err;
  spit(a / "config.toml", config);

  // Outputs of another run.
  fs::copy_file(a / "snapshots.h5", dir_ / "own.h5");
  fs::copy_file(b / "snapshots.h5", a / "snapshots.h5", fs::copy_options::overwrite_existing);
  r = resume_a();
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("snapshots.h5 comes from another run"), std::string::npos) << r.err;
  fs::copy_file(dir_ / "own.h5", a / "snapshots.h5", fs::copy_options::overwrite_existing);

  EXPECT_EQ(names_in(a), before);  // every refusal left the folder as it was
  r = resume_a();
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(Cli, ARunKilledDuringItsSetUpResumesFromTheStart) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run_orogen("run --out '" + a.string() + "' " + kTiny, dir_).status, 0);
  // Killed before the first checkpoint: only config.toml (and the lock) describe the run.
  ASSERT_EQ(run_orogen("run --out '" + b.string() + "' --abort-after-outputs 1 " + kTiny, dir_).status, 137);
  ASSERT_FALSE(fs::exists(b / "checkpoint.bin"));
  const auto r = run_orogen("run --resume '" + b.string() + "'", dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(b / "run.log").find("starting it again"), std::string::npos);
  expect_same_run(a, b);
}

TEST_F(Cli, AnUnstableSetUpExitsWith3AndLeavesNothing) {
  const fs::path run = dir_ / "soft";
  const auto r = run_orogen("run --out '" + run.string() + "' --set contact.kn=16 --set output.progress=never", dir_);
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("set-up became unstable"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise contact.kn"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run));
}

TEST_F(Cli, AFullDiskStopsTheRunWithExit1AndItResumesBitForBit) {
  const fs::path disk = dir_ / "disk";
  if (!mount_tmpfs(disk, "600k")) GTEST_SKIP() << "cannot mount a tmpfs here (needs root): full-disk test skipped";
  Unmount unmount{disk};
  const std::string args = kTiny + " --set layer.length=30 --set output.interval=0.5 --set output.vtp=false";
  const fs::path whole = dir_ / "whole", run = disk / "run";
  ASSERT_EQ(run_orogen("run --out '" + whole.string() + "' " + args, dir_).status, 0);
  const auto r = run_orogen("run --out '" + run.string() + "' " + args, dir_);
  ASSERT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("orogen run --resume " + run.string()), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << r.err;
  ASSERT_TRUE(remount(disk, "size=50m"));
  const auto resumed = run_orogen("run --resume '" + run.string() + "'", dir_);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_EQ(temporary_files_in(run), std::vector<std::string>{});
  expect_same_run(whole, run);
}

TEST_F(Cli, AReadOnlyFolderIsRefusedWithExit1AndLeftAsItWas) {
  const fs::path disk = dir_ / "disk";
  if (!mount_tmpfs(disk, "20m")) GTEST_SKIP() << "cannot mount a tmpfs here (needs root): read-only test skipped";
  Unmount unmount{disk};
  const fs::path run = disk / "run";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "' --abort-after-outputs 3 " + kTiny, dir_).status, 137);
  const auto before = names_in(disk);
  ASSERT_TRUE(remount(disk, "ro"));
  auto r = run_orogen("run --out '" + (disk / "new").string() + "' " + kTiny, dir_);
  EXPECT_EQ(r.status, 1);  // I/O, as for every command (docs/exit-codes.md)
  EXPECT_NE(r.err.find("Read-only file system"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find((disk / "new").string()), std::string::npos) << r.err;
  r = run_orogen("run --resume '" + run.string() + "'", dir_);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot write in the run folder " + run.string()), std::string::npos) << r.err;
  EXPECT_EQ(names_in(disk), before);
  ASSERT_TRUE(remount(disk, "rw"));
  r = run_orogen("run --resume '" + run.string() + "'", dir_);
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(Cli, SigintAndSigtermStopAtAStepWithACheckpointAndResumeBitForBit) {
  const std::string slow = kTiny + " --set settle.relax_time=20";
  const fs::path whole = dir_ / "whole";
  ASSERT_EQ(run_orogen("run --out '" + whole.string() + "' " + slow, dir_).status, 0);
  for (const int sig : {SIGINT, SIGTERM}) {
    const fs::path run = dir_ / (sig == SIGINT ? "int" : "term");
    const int status = signal_when_written(slow + " --out '" + run.string() + "'", run / "vtp" / "output_000003.vtp",
                                           sig, dir_ / "stopped.err");
    if (status == 0) GTEST_SKIP() << "the run finished before the signal (machine too loaded?)";
    EXPECT_EQ(status, 128 + sig) << slurp(dir_ / "stopped.err");
    const std::string log = slurp(run / "run.log");
    EXPECT_NE(log.find(sig == SIGINT ? "stopped by SIGINT at step" : "stopped by SIGTERM at step"), std::string::npos)
        << log;
    EXPECT_NE(log.find("continue with orogen run --resume"), std::string::npos) << log;
    // A resume may set how it shows progress; the run's configuration stays as it was.
    const std::string config_before = slurp(run / "config.toml");
    const auto resumed = run_orogen("run --resume '" + run.string() + "' --set output.progress=never", dir_);
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    expect_same_run(whole, run);
    EXPECT_EQ(slurp(run / "config.toml"), config_before);
  }
}

// Issue 36: a signal during the set-up (seconds to minutes of settling) stops the run cleanly,
// saying so, and leaves a folder that --resume starts again from its set-up.
TEST_F(Cli, ASignalDuringTheSetUpStopsCleanlyAndTheRunResumesFromItsSetUp) {
  const std::string small =
      " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
      " --set wedge.s_end=0.1 --set wedge.outputs=2 --set output.progress=never --threads 1";
  const fs::path whole = dir_ / "whole", run = dir_ / "run";
  ASSERT_EQ(run_orogen("run --out '" + whole.string() + "'" + small, dir_).status, 0);
  // run.log is opened just before the set-up starts.
  const int status = signal_when_written(small + " --out '" + run.string() + "'", run / "run.log", SIGTERM,
                                         dir_ / "stopped.err");
  EXPECT_EQ(status, 128 + SIGTERM) << slurp(dir_ / "stopped.err");
  const std::string log = slurp(run / "run.log");
  EXPECT_NE(log.find("set-up: building the initial state"), std::string::npos) << log;
  EXPECT_NE(log.find("stopped by SIGTERM during the set-up"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(run / "checkpoint.bin"));
  const auto resumed = run_orogen("run --resume '" + run.string() + "'", dir_);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  expect_same_run(whole, run);
  EXPECT_NE(slurp(run / "run.log").find("set-up done in"), std::string::npos);
}

TEST_F(Cli, AFinishedWedgeExtendedWithResumeEqualsOneRunToTheNewEnd) {
  const std::string small =
      " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
      " --set wedge.window=3 --set wedge.erosion_height=0.9 --set output.checkpoint_every=2"
      " --set output.progress=never --threads 1";
  const fs::path whole = dir_ / "whole", extended = dir_ / "extended";
  ASSERT_EQ(run_orogen("run --out '" + whole.string() + "'" + small + " --set wedge.s_end=0.4 --set wedge.outputs=8",
                       dir_).status,
            0);
  ASSERT_EQ(run_orogen("run --out '" + extended.string() + "'" + small + " --set wedge.s_end=0.2 --set wedge.outputs=4",
                       dir_).status,
            0);
  // A key that changes the physics is refused, naming it; the run is left as it was.
  auto r = run_orogen("run --resume '" + extended.string() + "' --set contact.mu=0.5", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--set contact.mu=0.5 would change what the run computes"), std::string::npos) << r.err;
  r = run_orogen("run --resume '" + extended.string() + "'", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--set wedge.s_end="), std::string::npos) << r.err;

  // A new end alone keeps the output spacing; an end between two outputs is refused, naming one that fits.
  const std::string config_before = slurp(extended / "config.toml");
  r = run_orogen("run --resume '" + extended.string() + "' --set wedge.s_end=0.43", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("0.43 is not a whole number of it: give an end that is (0.45 gives 9 outputs)"),
            std::string::npos) << r.err;
  EXPECT_EQ(slurp(extended / "config.toml"), config_before);
  // An earlier end would leave outputs past it: refused, nothing written.
  r = run_orogen("run --resume '" + extended.string() + "' --set wedge.s_end=0.1", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("wedge.s_end = 0.1 is before the run's end, 0.2"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(extended / "config.toml"), config_before);
  // Keys of speed and display may come along; they hold for this resume and are not stored.
  r = run_orogen("run --resume '" + extended.string() +
                     "' --set wedge.s_end=0.4 --set output.checkpoint_every=3 --set run.threads=2",
                 dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(extended / "run.log").find("extended: wedge.s_end 0.2 -> 0.4, wedge.outputs 4 -> 8"),
            std::string::npos);
  expect_same_run(whole, extended);
  expect_same_bytes(whole / "config.toml", extended / "config.toml");
}

TEST_F(Cli, ReportRefusesBadFoldersNamingThem) {
  // The atlas itself is tested end to end in tests/python/test_atlas.py; here the checks the
  // C++ side makes before it starts Python.
  const auto missing = run_orogen("report '" + (dir_ / "missing").string() + "'", dir_);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("no such folder"), std::string::npos) << missing.err;
  const fs::path file = dir_ / "file.txt";
  spit(file, "x");
  const auto not_dir = run_orogen("report '" + file.string() + "'", dir_);
  EXPECT_EQ(not_dir.status, 2);
  EXPECT_NE(not_dir.err.find("not a folder"), std::string::npos) << not_dir.err;
  const auto out_file = run_orogen("report '" + dir_.string() + "' --out '" + file.string() + "'", dir_);
  EXPECT_EQ(out_file.status, 2);
  EXPECT_NE(out_file.err.find("a file is there"), std::string::npos) << out_file.err;
  EXPECT_EQ(run_orogen("report", dir_).status, 2);  // DIR is required
}

TEST_F(Cli, AnUnknownCommandIsNamedAndTheHelpIsClean) {
  const auto r = run_orogen("frobnicate --out x", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown command 'frobnicate'; orogen takes a command first: run, render"), std::string::npos)
      << r.err;
  const auto option = run_orogen("--frob run", dir_);
  EXPECT_EQ(option.status, 2);
  EXPECT_NE(option.err.find("unknown option '--frob'"), std::string::npos) << option.err;
  const auto help = run_orogen("render --help", dir_);
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--no-animation"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("{false}"), std::string::npos) << help.out;
}
