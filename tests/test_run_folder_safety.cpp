// A run folder holds one run's files, and no command mixes in another's or writes over them:
// a resume, a branch and `orogen analyze` refuse files of another run naming the file, export,
// render and report refuse targets that are a run's own files, analyze survives a full disk
// and owns the folder while it writes, and the OpenMP environment is checked like the keys.
#include <gtest/gtest.h>
#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_dir_fixture.hpp"
#include "tmpfs_mount.hpp"

namespace fs = std::filesystem;
using orogen::testing::CliResult;
using orogen::testing::slurp;

namespace {

// 45 discs settle in about 2800 steps; discs above the layer are trimmed at step 2200
// (removals.csv), and every output is checkpointed.
const std::string kPacking =
    "--set run.experiment=packing --set particles.packing=random_discs --set layer.length=10"
    " --set layer.thickness=3 --set contact.kn=1000 --set settle.relax_time=1 --set settle.ke_threshold=1e-3"
    " --set output.interval=2 --set output.checkpoint_every=1 --set output.progress=never --threads 1";

// A wedge short enough for a test (a few seconds), with outputs the analysis can read.
const std::string kWedge =
    "--set wedge.s_end=0.1 --set wedge.outputs=3 --set layer.length=30 --set output.progress=never --threads 1";

class RunFolderSafety : public orogen::testing::TempDirTest {
 protected:
  CliResult orogen(const std::string& args, const std::string& env = "") {
    return orogen::testing::run_orogen(args, dir_, env);
  }
  std::string q(const fs::path& p) const { return "'" + p.string() + "'"; }
};

// Every file under `dir` with its bytes: what a refusal must leave as it was.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return out;
}

void copy_tree(const fs::path& from, const fs::path& to) {
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

}  // namespace

// Issue 35.1: a file of another run (same configuration, another seed) copied into a stopped
// run's folder is refused by the resume, naming it, and the folder is left byte for byte.
TEST_F(RunFolderSafety, AResumeRefusesEachKindOfForeignFileAndChangesNothing) {
  const fs::path a = dir_ / "a", b = dir_ / "b", whole = dir_ / "whole";
  ASSERT_EQ(orogen("run --out " + q(a) + " --abort-after-outputs 6 --set output.vtp=true " + kPacking).status, 137);
  ASSERT_EQ(orogen("run --out " + q(b) + " --set run.seed=2 --set output.vtp=true " + kPacking).status, 0);
  ASSERT_EQ(orogen("run --out " + q(whole) + " --set output.vtp=true " + kPacking).status, 0);
  ASSERT_NE(slurp(a / "removals.csv").find(",other"), std::string::npos) << "no removal before the checkpoint";
  const fs::path pristine = dir_ / "pristine";
  copy_tree(a, pristine);
  const auto before = contents(a);

  const std::vector<std::pair<std::string, std::string>> foreign = {
      {"snapshots/output_000003.h5", "comes from another run"},
      {"series.csv", "comes from another run"},
      {"removals.csv", "comes from another run"},
      {"vtp/output_000002.vtp", "comes from another run"}};
  for (const auto& [file, says] : foreign) {
    fs::copy_file(b / file, a / file, fs::copy_options::overwrite_existing);
    auto mixed = contents(a);
    const CliResult r = orogen("run --resume " + q(a));
    EXPECT_EQ(r.status, 2) << file << ": " << r.err;
    EXPECT_NE(r.err.find((a / file).string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(contents(a), mixed) << file << ": the refused resume changed the folder";
    fs::copy_file(pristine / file, a / file, fs::copy_options::overwrite_existing);
  }
  // An output of this run under another output's name: the right run, the wrong time.
  fs::copy_file(a / "snapshots/output_000001.h5", a / "snapshots/output_000002.h5", fs::copy_options::overwrite_existing);
  CliResult r = orogen("run --resume " + q(a));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is not this run's output 2"), std::string::npos) << r.err;
  fs::copy_file(pristine / "snapshots/output_000002.h5", a / "snapshots/output_000002.h5",
                fs::copy_options::overwrite_existing);

  EXPECT_EQ(contents(a), before);
  r = orogen("run --resume " + q(a));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(a / "series.csv"), slurp(whole / "series.csv"));
  EXPECT_EQ(slurp(a / "removals.csv"), slurp(whole / "removals.csv"));
}

// Issue 35.5: a damaged series.csv fails the resume (exit 1, a file that cannot be read)
// before anything is changed: the outputs beyond the checkpoint are still there.
TEST_F(RunFolderSafety, AResumeThatFailsChangesNothing) {
  const fs::path a = dir_ / "a";
  ASSERT_EQ(orogen("run --out " + q(a) + " --abort-after-outputs 4 " + kPacking + " --set output.checkpoint_every=2")
                .status,
            137);
  ASSERT_TRUE(fs::exists(a / "snapshots/output_000003.h5"));  // beyond the checkpoint (after output 1)
  std::ofstream(a / "series.csv", std::ios::app) << "1,2,not a number\n";
  const auto before = contents(a);
  const CliResult r = orogen("run --resume " + q(a));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("series.csv"), std::string::npos) << r.err;
  EXPECT_EQ(contents(a), before);
}

// Issue 35.1: a branch refuses a source output copied in from another run.
TEST_F(RunFolderSafety, ABranchRefusesAForeignSourceOutput) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(orogen("run --out " + q(a) + " " + kPacking).status, 0);
  ASSERT_EQ(orogen("run --out " + q(b) + " --set run.seed=2 " + kPacking).status, 0);
  fs::copy_file(b / "snapshots/output_000002.h5", a / "snapshots/output_000002.h5", fs::copy_options::overwrite_existing);
  const CliResult r = orogen("run --from " + q(a) + ":2 --out " + q(dir_ / "branch") + " " + kPacking);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("output_000002.h5 comes from another run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "branch"));
}

// Issue 35.3: export, render and report never write over a run's own files.
TEST_F(RunFolderSafety, NoCommandWritesOverTheFilesOfARun) {
  const fs::path a = dir_ / "a";
  ASSERT_EQ(orogen("run --out " + q(a) + " " + kPacking).status, 0);
  fs::create_symlink(a, dir_ / "link");
  const auto before = contents(a);
  for (const std::string target : {"snapshots.h5", "checkpoint.bin", "snapshots/output_000001.h5", "series.csv",
                                   "config.toml", "run.lock", "analysis.h5", ""}) {
    const CliResult r = orogen("export " + q(a) + " --format csv --to " + q(a / target));
    EXPECT_EQ(r.status, 2) << target << ": " << r.err;
    EXPECT_NE(r.err.find("--to"), std::string::npos) << r.err;
  }
  CliResult r = orogen("export " + q(a) + " --format csv --to " + q(dir_ / "link" / "series.csv"));
  EXPECT_EQ(r.status, 2) << "through a symbolic link: " << r.err;
  r = orogen("render " + q(a) + " --frames-dir snapshots --no-animation");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--frames-dir"), std::string::npos) << r.err;
  r = orogen("report " + q(dir_) + " --out " + q(a));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(contents(a), before);
  // A file of its own beside the run's is the user's to write.
  r = orogen("export " + q(a) + " --format csv --to " + q(a / "last_output.csv"));
  EXPECT_EQ(r.status, 0) << r.err;
}

// Issue 35.2 and 35.4: analyze owns the folder while it writes, cleans up after a killed call,
// refuses outputs of another run, and a full disk ends it with exit 1, never a signal.
TEST_F(RunFolderSafety, AnalyzeLocksCleansRefusesForeignOutputsAndSurvivesAFullDisk) {
  const fs::path w = dir_ / "w", other = dir_ / "other";
  ASSERT_EQ(orogen("run --out " + q(w) + " " + kWedge).status, 0);
  // Held by another call: refused, nothing written.
  {
    const int fd = ::open(w.c_str(), O_RDONLY | O_DIRECTORY);  // what analyze locks: the folder
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    const CliResult r = orogen("analyze " + q(w));
    ::close(fd);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("being analysed by another orogen process"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(w / "analysis.h5"));
  }
  // What a killed call leaves goes with the next call.
  for (const char* stray : {"analysis.h5.tmp-4242", "analysis_columns.csv.tmp-4242", "analysis_state.bin.tmp-7"})
    std::ofstream(w / stray) << "half written";
  CliResult r = orogen("analyze " + q(w));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const auto& e : fs::directory_iterator(w))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  // An output of another run.
  ASSERT_EQ(orogen("run --out " + q(other) + " --set run.seed=2 " + kWedge).status, 0);
  fs::copy_file(other / "snapshots/output_000002.h5", w / "snapshots/output_000002.h5",
                fs::copy_options::overwrite_existing);
  for (const auto& e : fs::directory_iterator(w))
    if (e.path().filename().string().starts_with("analysis"))
      fs::remove(e.path());
  r = orogen("analyze " + q(w));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("output_000002.h5 comes from another run"), std::string::npos) << r.err;

  // A full disk at several points of the analysis.
  const fs::path disk = dir_ / "disk";
  if (!orogen::testing::mount_tmpfs(disk, "40m"))
    GTEST_SKIP() << "cannot mount a tmpfs here (needs root): analyze's full-disk test skipped";
  orogen::testing::Unmount unmount{disk};
  copy_tree(other, disk / "run");
  int full = 0;  // calls that met the full disk
  for (const char* free_kb : {"20", "200", "600", "1500"}) {
    const std::string fill = "dd if=/dev/zero of='" + (disk / "fill").string() + "' bs=1k 2>/dev/null; truncate -s -" +
                             free_kb + "K '" + (disk / "fill").string() + "'";
    fs::remove(disk / "fill");
    ASSERT_EQ(std::system(fill.c_str()), 0);
    r = orogen("analyze " + q(disk / "run"));
    EXPECT_TRUE(r.status == 1 || r.status == 0) << free_kb << " kB free: exit " << r.status << " " << r.err;
    if (r.status == 1) {
      ++full;
      EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
    }
    for (const auto& e : fs::directory_iterator(disk / "run"))
      EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << free_kb << " kB: " << e.path();
  }
  EXPECT_GE(full, 3) << "the disk was not full enough to test anything";
  fs::remove(disk / "fill");
  r = orogen("analyze " + q(disk / "run"));
  EXPECT_EQ(r.status, 0) << "after the disk was freed: " << r.err;
}

// Issue 35.2: OpenMP's variables are checked like keys, before anything is written.
TEST_F(RunFolderSafety, OpenMpSettingsAreCheckedLikeKeys) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"OMP_NUM_THREADS=100000", "OMP_NUM_THREADS"}, {"OMP_NUM_THREADS=1025", "OMP_NUM_THREADS"},
      {"OMP_NUM_THREADS=abc", "OMP_NUM_THREADS"},    {"OMP_NUM_THREADS=0", "OMP_NUM_THREADS"},
      {"OMP_PROC_BIND=sideways", "OMP_PROC_BIND"},   {"OMP_WAIT_POLICY=lazy", "OMP_WAIT_POLICY"},
      {"OMP_STACKSIZE=big", "OMP_STACKSIZE"}};
  for (const auto& [env, name] : bad) {
    const CliResult r = orogen("run --out " + q(dir_ / "r") + " " + kPacking, env + " ");
    EXPECT_EQ(r.status, 2) << env << ": " << r.err;
    EXPECT_NE(r.err.find("environment variable " + name), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "r")) << env;
  }
  for (const std::string env : {"OMP_NUM_THREADS=2", "OMP_NUM_THREADS='2,1'", "OMP_PROC_BIND=true",
                                "OMP_WAIT_POLICY=PASSIVE", "OMP_STACKSIZE=8M"}) {
    EXPECT_EQ(orogen("config", env + " ").status, 0) << env;
  }
}

// Issue 35.5: command-line counts, the [analysis] keys and a run that could only be empty are
// refused before anything is written.
TEST_F(RunFolderSafety, BadCountsAnalysisKeysAndEmptyRunsAreRefusedUpFront) {
  for (const std::string threads : {"1e3", "1.5", "abc", "'1 '"}) {
    const CliResult r = orogen("run --threads " + threads + " --out " + q(dir_ / "r") + " " + kPacking);
    EXPECT_EQ(r.status, 2) << threads;
    EXPECT_NE(r.err.find("must be a whole number from 0 to 1024"), std::string::npos) << r.err;
  }
  for (const std::string depths : {"x", "-1", "nan"}) {
    const CliResult r = orogen("run --out " + q(dir_ / "r") + " --set analysis.closure_depths=" + depths);
    EXPECT_EQ(r.status, 2) << depths << ": " << r.err;
    EXPECT_NE(r.err.find("analysis.closure_depths"), std::string::npos) << r.err;
  }
  const CliResult r =
      orogen("run --out " + q(dir_ / "r") + " --set run.experiment=scripted --set scripted.duration=1");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("Python setup function"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "r"));
}
