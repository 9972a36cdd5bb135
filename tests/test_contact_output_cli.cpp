// The contact and stress outputs of a whole run: switching them on changes no bit of what the
// run computes, they land in every output with their units, bad keys are refused, and
// `orogen render --color forces` draws them or names output.contacts.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "io/snapshot_reader.hpp"

namespace orogen {
namespace {

namespace fs = std::filesystem;
using testing::run_orogen;
using testing::slurp;

class ContactOutputCli : public testing::TempDirTest {};

// A small wedge (clusters, walls, erosion), 5 outputs, about a second.
const std::string kWedge =
    "--set run.experiment=wedge --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4"
    " --set wedge.initial_active=4 --set wedge.s_end=0.2 --set wedge.outputs=4 --set wedge.erosion_height=0.9"
    " --set output.progress=never --set output.vtp=false";
const std::string kAllOn = " --set output.contacts=true --set output.stress=true --set output.stress_grid=2";

TEST_F(ContactOutputCli, SwitchedOnChangesNoBitAndStoresEveryOutput) {
  const fs::path on = dir_ / "on", off = dir_ / "off";
  // Two threads against one: the forces are taken outside the thread team as well.
  const auto r_on = run_orogen("run --out '" + on.string() + "' --threads 2 " + kWedge + kAllOn, dir_,
                               "OROGEN_MIN_PARALLEL_ITEMS=16 ");
  ASSERT_EQ(r_on.status, 0) << r_on.err;
  const auto r_off = run_orogen("run --out '" + off.string() + "' --threads 1 " + kWedge, dir_);
  ASSERT_EQ(r_off.status, 0) << r_off.err;
  EXPECT_EQ(slurp(on / "series.csv"), slurp(off / "series.csv"));
  EXPECT_EQ(slurp(on / "removals.csv"), slurp(off / "removals.csv"));
  const SnapshotReader a(on / "snapshots.h5"), b(off / "snapshots.h5");
  ASSERT_EQ(a.count(), b.count());
  ASSERT_GE(a.count(), 4);
  for (std::int64_t k = 0; k < a.count(); ++k) {
    const Snapshot sa = a.read(k), sb = b.read(k);
    EXPECT_EQ(sa.id, sb.id) << k;
    for (const char* name : {"x", "y", "theta", "vx", "vy", "omega"})
      EXPECT_TRUE(sa.field(name) == sb.field(name)) << name << " differs at output " << k;
    for (const char* group : {"contacts", "stress", "stress_grid"}) {
      EXPECT_TRUE(a.has_group(k, group)) << group << " missing at output " << k;
      EXPECT_FALSE(b.has_group(k, group)) << group << " written although off, output " << k;
    }
    EXPECT_TRUE(a.has_group(k, "clusters"));  // the wedge's clusters: always
    EXPECT_EQ(a.read_group_dataset(k, "stress", "yy").rows, sa.size());
    const auto fn = a.read_group_dataset(k, "contacts", "fn");
    for (double v : fn.data) EXPECT_GE(v, 0.0);
  }
  // The last output is loaded: its discs press on each other.
  EXPECT_GT(a.read_group_dataset(a.count() - 1, "contacts", "fn").rows, 100u);

  const auto drawn = run_orogen("render '" + on.string() + "' --color forces --no-animation --width 400", dir_);
  EXPECT_EQ(drawn.status, 0) << drawn.err;
  EXPECT_TRUE(fs::exists(on / "frames" / "frame_000004.png"));
  const auto refused = run_orogen("render '" + off.string() + "' --color forces --no-animation", dir_);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("output.contacts"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(off / "frames"));
}

TEST_F(ContactOutputCli, TooFineAStressGridIsRefusedNamingTheKey) {
  for (const char* value : {"0.1", "-1", "1e300"}) {
    const auto r = run_orogen("run --out '" + (dir_ / "bad").string() + "' " + kWedge +
                                  " --set output.stress_grid=" + value,
                              dir_);
    EXPECT_EQ(r.status, 2) << value << ": " << r.err;
    EXPECT_NE(r.err.find("output.stress_grid"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad" / "snapshots.h5")) << value;
  }
}

}  // namespace
}  // namespace orogen
