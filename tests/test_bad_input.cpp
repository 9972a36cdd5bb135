// Hostile input (issue 14): every case a campaign found crashing Orogen, running an empty or
// NaN run, or blaming the wrong key must end with exit 2 before the run and a message naming
// the key (or file, or argument) and what is allowed. Each run here is refused at once.
#include <gtest/gtest.h>
#include <omp.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "config/config.hpp"
#include "config/schema.hpp"
#include "experiments/experiment.hpp"
#include "temp_dir_fixture.hpp"
#include "util/thread_tuner.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

const std::string kExamples = std::string(OROGEN_SOURCE_DIR) + "/examples/";

class BadInput : public testing::TempDirTest {
 protected:
  // `orogen run ARGS --out DIR/run`: must exit 2, name every one of `wants` on stderr and
  // leave no run folder.
  void expect_refused(const std::string& args, const std::vector<std::string>& wants, const std::string& env = "") {
    SCOPED_TRACE(args);
    const fs::path out = dir_ / "run";
    const auto r = testing::run_orogen("run " + args + " --out '" + out.string() + "'", dir_, env);
    EXPECT_EQ(r.status, 2) << r.err;
    for (const auto& want : wants) EXPECT_NE(r.err.find(want), std::string::npos) << "want: " << want << "\ngot: " << r.err;
    EXPECT_FALSE(fs::exists(out / "config.toml"));
  }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
};

// Error text of loading and building the experiment in-process ("" when accepted).
std::string refusal(const std::vector<std::string>& overrides) {
  try {
    make_experiment(Config::load(std::nullopt, overrides));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(BadInputSchema, EveryIntegerKeyHasBoundsInsideInt) {
  for (const auto& k : schema()) {
    if (k.type != KeyType::Int) continue;
    ASSERT_TRUE(k.min && k.max) << k.name;
    EXPECT_GE(k.min->value, INT_MIN) << k.name;
    EXPECT_LE(k.max->value, INT_MAX) << k.name;
  }
}

// Case 1: integers beyond int became 0 (SIGFPE) or a negative output count.
TEST_F(BadInput, IntegerKeysBeyondTheirRange) {
  expect_refused("--set wedge.erosion_every=4294967296 --set wedge.erosion_height=1.2",
                 {"wedge.erosion_every = 4294967296", "<= 1e+06"});
  expect_refused("--set wedge.outputs=4294967296", {"wedge.outputs = 4294967296", "<= 1e+05"});
  expect_refused("--set wedge.outputs=2147483648", {"wedge.outputs = 2147483648"});
  expect_refused("--set neighbor.sort_every=99999999999", {"neighbor.sort_every"});
  expect_refused("--set run.threads=4294967297", {"run.threads", "<= 1024"});
}

// Case 2: a box narrower than one grid cell divided by zero in the packing generator.
TEST_F(BadInput, BoxTooSmallForTheGrid) {
  expect_refused("'" + kExamples + "packing_discs.toml' --set layer.length=1", {"layer.length = 1", ">= 3"});
  expect_refused("'" + kExamples + "repose_slump.toml' --set repose.size=1", {"repose.size = 1", ">= 8"});
}

// Case 3: columns of width 1e-20 mean radii overflowed the column count.
TEST_F(BadInput, SurfaceColumnsTooNarrow) {
  expect_refused("'" + kExamples + "packing_discs.toml' --set layer.column_width_factor=1e-20",
                 {"layer.column_width_factor = 1e-20", ">= 0.5"});
  // Allowed width, yet too many columns over a long layer of tiny discs: the derived limit.
  const std::string msg = refusal({"run.experiment=packing", "layer.length=1e6", "layer.thickness=3",
                                   "particles.d_min=0.01", "layer.column_width_factor=0.5"});
  EXPECT_NE(msg.find("config error in --set: layer.column_width_factor = 0.5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("layer.length = 1e+06 (--set)"), std::string::npos) << msg;
}

// Case 4: a header 50,000 levels deep overflowed the stack inside toml++.
TEST_F(BadInput, DeeplyNestedTomlIsRefusedBeforeParsing) {
  std::string header = "[run]\nseed = 1\n[a";
  for (int i = 0; i < 50000; ++i) header += ".a";
  const auto deep = write("deep.toml", header + "]\n");
  expect_refused("'" + deep.string() + "'", {deep.string() + ", line 3", "nested too deeply"});
  const auto arrays = write("arrays.toml", "[run]\nseed = " + std::string(50000, '[') + std::string(50000, ']') + "\n");
  expect_refused("'" + arrays.string() + "'", {arrays.string() + ", line 2", "nested too deeply"});
  expect_refused("--set 'run.seed=" + std::string(100, '[') + "1" + std::string(100, ']') + "'",
                 {"--set: run.seed", "nested too deeply"});
  // Ordinary nesting (a float array, a dotted key) is not affected.
  const auto fine = write("fine.toml", "# a.b.c.d.e.f\n[contact]\nmu = 0.25\n");
  EXPECT_EQ(Config::load(fine, {}).get_float("contact.mu"), 0.25);
}

// Case 5: /dev/zero was read until memory ran out.
TEST_F(BadInput, ConfigMustBeARegularFileOfAtMostOneMiB) {
  expect_refused("/dev/zero", {"/dev/zero", "not a regular file"});
  expect_refused("'" + dir_.string() + "'", {dir_.string(), "not a regular file"});
  const auto big = write("big.toml", "[run]\nseed = 1\n" + std::string(kMaxConfigBytes, '#') + "\n");
  expect_refused("'" + big.string() + "'", {big.string(), "1 MiB"});
}

// Case 6: runs with no discs (or an absurd number) exited 0.
TEST_F(BadInput, EmptyOrAbsurdLayersAreRefused) {
  expect_refused("--set layer.thickness=1 --set wedge.s_end=0.5", {"layer.thickness = 1", ">= 3"});
  const std::string hex = "'" + kExamples + "packing_hexagonal.toml'";
  expect_refused(hex + " --set layer.thickness=1e19", {"layer.thickness = 1e+19 (--set)", "50 million"});
  expect_refused(hex + " --set layer.length=5e-324", {"layer.length = 5e-324", ">= 3"});
  expect_refused(hex + " --set layer.length=1.8e308", {"layer.length = 1.8e308"});
  expect_refused("'" + kExamples + "repose_slump.toml' --set repose.size=1e300",
                 {"repose.size = 1e+300 (--set)", "50 million"});
}

// Case 7: a block of side 2 or 3 gave angle_deg = nan with exit 0.
TEST_F(BadInput, ReposeBlockTooSmallToMeasure) {
  const std::string slump = "'" + kExamples + "repose_slump.toml'";
  expect_refused(slump + " --set repose.size=2", {"repose.size = 2", ">= 8"});
  expect_refused(slump + " --set repose.size=3", {"repose.size = 3", ">= 8"});
  expect_refused(slump + " --set repose.size=8 --set repose.fixed_height=6",
                 {"repose.size = 8.0", "repose.fixed_height = 6.0 (--set)", "at least 3 d"});
}

// Case 8: a derived bound blamed wedge.speed "in default" with "< -nan".
TEST_F(BadInput, DerivedBoundsNameTheirSourceKeys) {
  expect_refused("--set particles.d_min=1e-300", {"particles.d_min = 1e-300", ">= 0.01"});
  expect_refused("--set contact.kn=1e300", {"contact.kn = 1e300", "<= 1e+12"});
  expect_refused("--set time.dt_fraction=1",
                 {"config error in --set: wedge.speed", "time.dt_fraction = 1.0 (--set)", "contact.kn = 10000.0 (default)"});
  const auto file = write("dt.toml", "[time]\ndt = 1.0\n");
  expect_refused("'" + file.string() + "'", {"config error in " + file.string() + ": time.dt", "contact.kn = 10000.0 (default)"});
}

// Case 9: "cannot create std::vector larger than max_size()" named no key.
TEST_F(BadInput, ParticleCountLimit) {
  expect_refused("--set run.experiment=packing --set layer.length=9.2e18",
                 {"layer.length = 9.2e+18 (--set)", "layer.thickness = 10.0 (default)", "50 million"});
  expect_refused("--set wedge.s_end=1e9", {"wedge.s_end = 1e+09 (--set)", "50 million"});
  expect_refused("--set run.experiment=biaxial --set biaxial.width=1e5 --set biaxial.height=1e5", {"biaxial.width"});
}

// Case 10: command-line and environment values that were accepted.
TEST_F(BadInput, ThreadsResumeAndEnvironment) {
  const std::string tiny = "--set run.experiment=packing --set layer.length=3 --set layer.thickness=3";
  expect_refused(tiny + " --threads -1", {"--threads", "0 to 1024"});
  expect_refused(tiny + " --threads ''", {"--threads", "empty"});
  expect_refused(tiny + " --threads 100000", {"--threads"});
  expect_refused(tiny, {"OROGEN_MIN_PARALLEL_ITEMS", "99999999999999999999999"},
                 "OROGEN_MIN_PARALLEL_ITEMS=99999999999999999999999 ");
  // Run from dir_: it used to start a default run in ./out.
  const auto r = testing::run_orogen("run --resume ''", dir_, "cd '" + dir_.string() + "' && ");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--resume needs a run folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Render options out of range aborted in the renderer (--width -5) or were taken (--every 0).
TEST_F(BadInput, RenderOptionsOutOfRange) {
  for (const std::string arg : {"--width -5", "--width ''", "--every 0", "--fps 0"}) {
    SCOPED_TRACE(arg);
    const auto r = testing::run_orogen("render '" + dir_.string() + "' " + arg, dir_);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(arg.substr(0, arg.find(' '))), std::string::npos) << r.err;
  }
}

// Case 11: set-up's settling loops step under the thread tuner (step_with_tuning); it steps
// until done, switches counts with a tiny slice, and leaves the team size as it found it, also
// when a step throws.
TEST(SetupTuning, StepsUntilDoneAndRestoresTheTeamSize) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  int steps = 0;
  bool saw_one = false;
  step_with_tuning(true, 1e-9, [&] {
    saw_one |= omp_get_max_threads() == 1;
    return ++steps < 200;
  }, [] { return 100.0; });
  EXPECT_EQ(steps, 200);
  EXPECT_TRUE(saw_one);  // it probed one thread
  EXPECT_EQ(omp_get_max_threads(), 2);
  EXPECT_THROW(step_with_tuning(true, 1e-9, [&]() -> bool {
    if (omp_get_max_threads() == 1) throw std::runtime_error("unstable");
    return true;
  }, [] { return 100.0; }), std::runtime_error);
  EXPECT_EQ(omp_get_max_threads(), 2);
  omp_set_num_threads(before);
}

}  // namespace
}  // namespace orogen
