// `orogen analyze` end to end on tiny eroding wedge runs: a growing run analysed twice gives
// what one analysis of the finished run gives (the values of analysis.h5, which is extended in
// place, and the bytes of the CSV tables), a call killed before it saved its state is made
// good by the next, a running run (lock held) is read without waiting, and bad input is
// refused with exit 2 leaving every file of the run as it was.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "io/hdf5_file.hpp"
#include "cli_runner.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using orogen::testing::CliResult;
using orogen::testing::run_orogen;
using orogen::testing::slurp;

namespace {

class AnalyzeCli : public orogen::testing::TempDirTest {};

// A wedge run of a few hundred discs that erodes from the start (about a second).
const std::string kSmall =
    " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
    " --set wedge.window=3 --set wedge.s_end=0.3 --set wedge.outputs=6 --set wedge.erosion_height=0.9"
    " --set output.checkpoint_every=1 --set output.progress=never --set output.vtp=false --threads 1";

// Every file under `dir` with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) m[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return m;
}

const char* kTables[] = {"analysis_flux.csv", "analysis_columns.csv", "analysis_removals.csv"};
const char* kAnalysisFiles[] = {"analysis.h5", "analysis_flux.csv", "analysis_columns.csv", "analysis_removals.csv"};

// What a reader of an HDF5 file sees: per dataset its shape, values (native bytes), units and
// description; per root attribute its value. Not the file's bytes, which depend on how often
// the file was extended.
std::map<std::string, std::string> h5_values(const fs::path& path) {
  namespace h5 = orogen::h5;
  std::map<std::string, std::string> m;
  const h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
  for (const auto& name : h5::list(f.id())) {
    const h5::Object set(H5Dopen2(f.id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    const h5::Object file_type(H5Dget_type(set.id()), H5Tclose);
    const h5::Object type(H5Tget_native_type(file_type.id(), H5T_DIR_ASCEND), H5Tclose);
    const h5::Object space(H5Dget_space(set.id()), H5Sclose);
    std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.id())));
    H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
    std::string v = "shape";
    std::size_t n = 1;
    for (auto d : dims) {
      v += ' ';
      v += std::to_string(d);
      n *= d;
    }
    std::string bytes(n * H5Tget_size(type.id()), '\0');
    if (n > 0) {
      EXPECT_GE(H5Dread(set.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0) << name;
    }
    m[name] = v + "|" + bytes + "|" + h5::get_dataset_attr_string(f.id(), name, "units") + "|" +
              h5::get_dataset_attr_string(f.id(), name, "description");
  }
  for (const auto& a : h5::list_attrs(f.id()))
    m["@" + a.name] = a.kind == h5::Kind::String ? h5::get_attr_string(f.id(), a.name)
                                                 : std::to_string(h5::get_attr_double(f.id(), a.name));
  return m;
}

// The analysis of two run folders is the same: analysis.h5's values, the tables' bytes.
void expect_same_analysis(const fs::path& a, const fs::path& b) {
  const auto va = h5_values(a / "analysis.h5"), vb = h5_values(b / "analysis.h5");
  EXPECT_EQ(va.size(), vb.size());
  for (const auto& [name, v] : va) {
    const auto it = vb.find(name);
    EXPECT_TRUE(it != vb.end() && it->second == v) << "analysis.h5: " << name << " differs";
  }
  for (const char* f : kTables) EXPECT_TRUE(slurp(a / f) == slurp(b / f)) << f << " differs";
}

}  // namespace

TEST_F(AnalyzeCli, GrowingRunAnalysedTwiceEqualsOnceOnTheFinishedRun) {
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  const CliResult first = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("(3 new)"), std::string::npos) << first.out;
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  const CliResult second = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_NE(second.out.find("7 outputs (4 new)"), std::string::npos) << second.out;

  fs::copy(run, copy, fs::copy_options::recursive);
  for (const char* f : kAnalysisFiles) fs::remove(copy / f);
  fs::remove(copy / "analysis_state.bin");
  const CliResult once = run_orogen("analyze '" + copy.string() + "'", dir_);
  ASSERT_EQ(once.status, 0) << once.err;
  EXPECT_NE(once.out.find("(7 new)"), std::string::npos) << once.out;
  expect_same_analysis(run, copy);
  EXPECT_NE(slurp(copy / "analysis_removals.csv").find("\n"), std::string::npos);
  // The run eroded, and the analysis saw it.
  EXPECT_NE(slurp(run / "removals.csv").find("eroded"), std::string::npos);
  const std::string removals = slurp(run / "analysis_removals.csv");
  EXPECT_GT(std::count(removals.begin(), removals.end(), '\n'), 3);

  // Nothing new: a third call adds nothing and changes nothing.
  const auto before = contents(run);
  const CliResult third = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_NE(third.out.find("(0 new)"), std::string::npos) << third.out;
  for (const char* f : kAnalysisFiles) EXPECT_TRUE(before.at(f) == slurp(run / f)) << f << " changed";
}

TEST_F(AnalyzeCli, OutputsNotYetCoveredByRemovalsWaitForTheNextCall) {
  // A running run writes removals.csv just after each snapshot: an index one output ahead of
  // removals.csv must not lose that output's erosion.
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall, dir_).status, 0);
  fs::copy(run, copy, fs::copy_options::recursive);
  const std::string removals = slurp(run / "removals.csv");
  const auto at = removals.find("# through_step: ");
  ASSERT_NE(at, std::string::npos);
  const auto end = removals.find(' ', at + 16);
  // Covers output 0 only (step 0).
  const std::string early = removals.substr(0, at + 16) + "1" + removals.substr(end);
  std::ofstream(run / "removals.csv", std::ios::trunc) << early;
  const CliResult first = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("1 outputs (1 new)"), std::string::npos) << first.out;
  std::ofstream(run / "removals.csv", std::ios::trunc) << removals;
  const CliResult second = run_orogen("analyze '" + run.string() + "'", dir_);
  EXPECT_NE(second.out.find("7 outputs (6 new)"), std::string::npos) << second.out;
  ASSERT_EQ(run_orogen("analyze '" + copy.string() + "'", dir_).status, 0);
  expect_same_analysis(run, copy);
}

TEST_F(AnalyzeCli, ACallKilledBeforeSavingItsStateIsMadeGoodByTheNext) {
  // A call killed after it extended the files but before it saved analysis_state.bin leaves
  // rows beyond the state's count: the next call cuts them off and writes them again.
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  const std::string state3 = slurp(run / "analysis_state.bin");
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  fs::copy(run, copy, fs::copy_options::recursive);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  std::ofstream(run / "analysis_state.bin", std::ios::binary | std::ios::trunc) << state3;  // as if killed
  const CliResult again = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("7 outputs (4 new)"), std::string::npos) << again.out;
  ASSERT_EQ(run_orogen("analyze '" + copy.string() + "'", dir_).status, 0);
  expect_same_analysis(run, copy);

  // A call killed while analysis.h5 was open for writing leaves it marked incomplete (HDF5's
  // metadata may be half written): the next call starts over.
  {
    namespace h5 = orogen::h5;
    h5::File f = h5::File::open(run / "analysis.h5", h5::File::Mode::ReadWrite);
    h5::set_attr_int64(f.id(), "incomplete", 1);
  }
  const CliResult marked = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(marked.status, 0) << marked.err;
  EXPECT_NE(marked.out.find("7 outputs (7 new)"), std::string::npos) << marked.out;
  EXPECT_NE(marked.err.find("was being written when its call stopped"), std::string::npos) << marked.err;
  expect_same_analysis(run, copy);

  // Files that do not continue the state (here: analysis.h5 gone) make the call start over.
  fs::remove(run / "analysis.h5");
  const CliResult over = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(over.status, 0) << over.err;
  EXPECT_NE(over.out.find("7 outputs (7 new)"), std::string::npos) << over.out;
  expect_same_analysis(run, copy);
}

TEST_F(AnalyzeCli, ADamagedNewOutputLeavesAContinuedAnalysisAsItWas) {
  // The outputs before the damaged one are appended, then cut off again: the state and the
  // tables keep their bytes, analysis.h5 its values.
  const fs::path run = dir_ / "run";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  const auto values = h5_values(run / "analysis.h5");
  const std::string state = slurp(run / "analysis_state.bin");
  std::map<std::string, std::string> tables;
  for (const char* f : kTables) tables[f] = slurp(run / f);
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  fs::resize_file(run / "snapshots" / "output_000005.h5", 100);
  const CliResult r = run_orogen("analyze '" + run.string() + "'", dir_);
  EXPECT_EQ(r.status, 1) << r.err;  // a damaged file: I/O (docs/exit-codes.md)
  EXPECT_NE(r.err.find("output 5 cannot be read"), std::string::npos) << r.err;
  EXPECT_TRUE(h5_values(run / "analysis.h5") == values);
  EXPECT_TRUE(slurp(run / "analysis_state.bin") == state);
  for (const char* f : kTables) EXPECT_TRUE(slurp(run / f) == tables[f]) << f;
  for (const auto& e : fs::directory_iterator(run))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST_F(AnalyzeCli, ReadsARunningRunWithoutTakingItsLock) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall + " --set wedge.outputs=2", dir_).status, 0);
  const int fd = ::open((run / "run.lock").c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as the running process holds it
  const CliResult r = run_orogen("analyze '" + run.string() + "'", dir_);
  ::close(fd);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(run / "analysis.h5"));
}

TEST_F(AnalyzeCli, BadInputIsRefusedAndChangesNothing) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall + " --set wedge.outputs=2", dir_).status, 0);
  const auto expect_refused = [&](const fs::path& dir, const std::string& options, const std::string& named,
                                  int status = 2) {
    const auto before = fs::exists(dir) ? contents(dir) : std::map<std::string, std::string>{};
    const CliResult r = run_orogen("analyze '" + dir.string() + "'" + options, dir_);
    EXPECT_EQ(r.status, status) << options << ": " << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    if (fs::exists(dir)) {
      EXPECT_EQ(contents(dir), before) << options;
    }
  };
  expect_refused(dir_ / "missing", "", "no such folder");
  fs::create_directories(dir_ / "empty");
  expect_refused(dir_ / "empty", "", "is not a run folder");
  expect_refused(run, " --closure-depths -0.1,0.3", "-0.1 is not positive");
  expect_refused(run, " --closure-depths 0.5,0.3", "not in strictly ascending order");
  expect_refused(run, " --closure-depths 0.5,1.2", "1.2 h0 is below the base of the layer");
  expect_refused(run, " --closure-depths 0.5,x", "--closure-depths 0.5,x: not a comma-separated list of numbers");
  expect_refused(run, " --flux-window 0", "--flux-window 0");

  const fs::path packing = dir_ / "packing";
  fs::copy(run, packing, fs::copy_options::recursive);
  std::string config = slurp(packing / "config.toml");
  const auto at = config.find("experiment = \"wedge\"");
  ASSERT_NE(at, std::string::npos);
  config.replace(at, 20, "experiment = \"packing\"");
  std::ofstream(packing / "config.toml") << config;
  expect_refused(packing, "", "is a packing run");

  const fs::path broken = dir_ / "broken";
  fs::copy(run, broken, fs::copy_options::recursive);
  fs::resize_file(broken / "snapshots.h5", fs::file_size(broken / "snapshots.h5") / 2);
  expect_refused(broken, "", "snapshots.h5", 1);  // damaged files: I/O, exit 1 (docs/exit-codes.md)
  const fs::path lost = dir_ / "lost";
  fs::copy(run, lost, fs::copy_options::recursive);
  fs::resize_file(lost / "snapshots" / "output_000001.h5", 100);
  expect_refused(lost, "", "output 1 cannot be read", 1);
}

TEST_F(AnalyzeCli, InRunAnalysisEqualsAnalyzeAfterwards) {
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  const std::string keys = " --set analysis.in_run=true --set analysis.every=2 --set analysis.closure_depths=0.2,0.6"
                           " --set analysis.flux_window=2";
  // Killed after 3 outputs and resumed: the in-run analysis continues across the resume.
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + keys + " --abort-after-outputs 3", dir_).status, 0);
  const CliResult resumed = run_orogen("run --resume '" + run.string() + "'", dir_);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  ASSERT_TRUE(fs::exists(run / "analysis.h5"));
  fs::copy(run, copy, fs::copy_options::recursive);
  for (const char* f : kAnalysisFiles) fs::remove(copy / f);
  fs::remove(copy / "analysis_state.bin");
  const CliResult after = run_orogen("analyze '" + copy.string() + "'", dir_);  // the run's [analysis] keys
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_NE(after.out.find("7 outputs (7 new)"), std::string::npos) << after.out;
  expect_same_analysis(run, copy);
  EXPECT_NE(slurp(run / "analysis_columns.csv").find("surface_age_0.6"), std::string::npos);
}

TEST_F(AnalyzeCli, BadAnalysisKeysRefuseTheRun) {
  const fs::path run = dir_ / "run";
  const CliResult r = run_orogen("run --out '" + run.string() + "'" + kSmall +
                                  " --set analysis.in_run=true --set analysis.closure_depths=0.6,0.2",
                              dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("analysis.closure_depths = 0.6,0.2: not in strictly ascending order"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "config.toml"));  // refused before the folder was claimed
  const CliResult packing = run_orogen("run --out '" + (dir_ / "p").string() +
                                        "' --set run.experiment=packing --set analysis.in_run=true",
                                    dir_);
  EXPECT_EQ(packing.status, 2);
  EXPECT_NE(packing.err.find("analysis.in_run = true needs run.experiment = \"wedge\""), std::string::npos)
      << packing.err;
}
