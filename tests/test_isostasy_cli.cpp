// A wedge on a deflecting base end to end (docs/isostasy.md): the elastic plate with sediment
// laid in its basins gives the same bits for one and two threads and across a kill and resume;
// the base sinks under the wedge, its segments stay joined, the kinematic slab rides on it;
// bad [isostasy] input is refused with exit 2 and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "io/snapshot_reader.hpp"
#include "refused_input.hpp"
#include "same_outputs.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using namespace orogen;
using orogen::testing::expect_same_outputs;
using orogen::testing::run_orogen;
using orogen::testing::slurp;

namespace {

class IsostasyCli : public orogen::testing::TempDirTest {
 protected:
  void SetUp() override {
    ::setenv("OMP_WAIT_POLICY", "passive", 0);  // see test_cli.cpp
    TempDirTest::SetUp();
  }
};

// A small wedge (h0 = 5) on a plate of flexural parameter 2 h0, solved every 100 steps, with
// hillslopes, a river and deposition so that basins fill while the base moves (3 s on one core).
const std::string kRigid =
    " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
    " --set wedge.window=3 --set wedge.s_end=1.0 --set wedge.outputs=6"
    " --set output.progress=never --set output.vtp=false --set output.checkpoint_every=2";
const std::string kPlate = " --set isostasy.model=flexure --set isostasy.rigidity=5 --set isostasy.every=100";
const std::string kFlexure =
    kRigid + kPlate +
    " --set surface.every=100 --set surface.diffusivity=0.2 --set surface.erodibility=0.02"
    " --set surface.deposition=true"
    " --set surface.base_level=1.02";

// The last output's base: sunk under the wedge, its segments joined end to end, no disc below
// its deepest point (the kinematic slab rides on it, none is lost below it).
void expect_base_in_one_piece(const fs::path& run) {
  SCOPED_TRACE(run.string());
  const SnapshotReader reader(run / "snapshots.h5");
  const Snapshot last = reader.read(reader.count() - 1);
  double deepest = 0;
  const std::array<double, 4>* before = nullptr;
  std::size_t segments = 0;
  for (std::size_t k = 0; k < last.walls.size(); ++k) {
    const auto& wall = last.walls[k];
    if (wall[0] == wall[2]) continue;  // the vertical end wall
    deepest = std::min({deepest, wall[1], wall[3]});
    EXPECT_LT(std::fabs(wall[1]), 5.0) << "segment " << k;  // within h0 of where it started
    if (before) {
      EXPECT_EQ((*before)[3], wall[1]) << "segment " << k;
      EXPECT_EQ((*before)[2], wall[0]) << "segment " << k;
    }
    before = &wall;
    ++segments;
  }
  EXPECT_GT(segments, 20u);
  EXPECT_LT(deepest, -0.2);  // d: under a wedge 0.25 h0 high
  const auto& y = last.field("y");
  for (std::size_t i = 0; i < last.size(); ++i) EXPECT_GT(y[i], deepest) << "disc " << last.id[i];
}

}  // namespace

TEST_F(IsostasyCli, AFlexedBaseIsTheSameForOneAndTwoThreadsAndAcrossAResume) {
  // Killed after its third output (checkpoint after the second): the base's move crosses it.
  ASSERT_NO_FATAL_FAILURE(orogen::testing::expect_same_runs(kFlexure, dir_));
  const fs::path one = dir_ / "one", killed = dir_ / "killed";

  // Extended (a larger wedge.s_end, whose node grid would reach farther): the base keeps its nodes.
  const auto r = run_orogen("run --resume '" + killed.string() + "' --set wedge.s_end=1.5", dir_);
  ASSERT_EQ(r.status, 0) << r.err;

  // The base sank under the wedge, in one piece, with no disc below it; so it did in the
  // extended run.
  expect_base_in_one_piece(one);
  expect_base_in_one_piece(killed);
  const std::string series = slurp(one / "series.csv");
  EXPECT_NE(series.find("base_s_point"), std::string::npos);
  EXPECT_NE(series.find("basin_pro"), std::string::npos);
}

// A branch (orogen run --from) of a run on a rigid base may switch the plate on: the base becomes
// segments there and sinks under the wedge from then on, the same for one and two threads and
// across a resume. The segment length is the set-up's (exit 2).
TEST_F(IsostasyCli, APlateSwitchedOnInABranchSinksFromThere) {
  const fs::path source = dir_ / "source";
  auto r = run_orogen("run --out '" + source.string() + "' --threads 1" + kRigid, dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_orogen("run --out '" + (dir_ / "refused").string() + "' --from '" + source.string() + "'" + kRigid + kPlate +
                     " --set isostasy.segment_length=1",
                 dir_);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("isostasy.segment_length"), std::string::npos) << r.err;
  ASSERT_NO_FATAL_FAILURE(
      orogen::testing::expect_same_runs(" --from '" + source.string() + ":2'" + kRigid + kPlate, dir_));
  expect_base_in_one_piece(dir_ / "one");
  // Output 0 is the source's state on the new base, still flat.
  const SnapshotReader reader(dir_ / "one" / "snapshots.h5");
  const Snapshot first = reader.read(0);
  EXPECT_GT(first.walls.size(), 20u);
  for (const auto& wall : first.walls) {
    if (wall[0] != wall[2]) {
      EXPECT_EQ(wall[1], 0.0);
    }
  }
}

TEST_F(IsostasyCli, BadIsostasyInputExitsWith2AndWritesNothing) {
  orogen::testing::expect_refused({
      {"--set isostasy.model=flexure", {"isostasy.rigidity", "greater than 0", "airy"}},
      {"--set isostasy.model=airy --set isostasy.rigidity=10", {"isostasy.rigidity", "10", "flexure"}},
      {"--set isostasy.model=flexure --set isostasy.rigidity=1e9", {"isostasy.rigidity", "1e+09", "beyond the model"}},
      {"--set isostasy.model=airy --set isostasy.every=150", {"isostasy.every", "150", "multiple of 100"}},
      {"--set isostasy.model=airy --set isostasy.mantle_density=0.8", {"isostasy.mantle_density", "0.8", ">= 1"}},
      {"--set isostasy.model=elastic", {"isostasy.model", "elastic", "\"flexure\""}},
  }, dir_);
}
