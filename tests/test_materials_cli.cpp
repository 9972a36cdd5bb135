// A layered, bonded crust end to end (docs/materials.md): the same results for one and two
// threads and across a kill and resume with bonds breaking throughout, the materials in the
// outputs, and bad [materials] / [[layer.units]] input refused with exit 2, nothing written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "io/snapshot_reader.hpp"
#include "same_outputs.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using namespace orogen;
using orogen::testing::run_orogen;
using orogen::testing::slurp;
using orogen::testing::expect_same_runs;

namespace {

class MaterialsCli : public orogen::testing::TempDirTest {
 protected:
  void SetUp() override {
    ::setenv("OMP_WAIT_POLICY", "passive", 0);  // see test_cli.cpp
    TempDirTest::SetUp();
  }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
};

// A singly-vergent wedge of a bonded, weakening rock over a weak layer: about 400 of its 700
// bonds break over the run, from the first output to the last (3 s on one core).
const std::string kLayered = R"(
[run]
experiment = "singly_vergent"
[particles]
packing = "random_discs"
[layer]
length = 60.0
thickness = 6.0
[[layer.units]]
material = "weak"
thickness = 1.5
[[layer.units]]
material = "rock"
thickness = 4.5
[contact]
kn = 2000.0
[singly]
speed = 0.05
shortening = 1.0
outputs = 5
basal_weakening = 0.5
basal_weakening_distance = 0.5
[output]
progress = "never"
vtp = false
checkpoint_every = 2
[materials.rock]
friction = 0.5
friction_residual = 0.3
weakening_distance = 2.0
bond_tensile_strength = 5.0
bond_strength_scatter = 0.3
[materials.weak]
friction = 0.1
)";

const std::vector<std::string> kLayeredFiles = {"series.csv", "removals.csv", "bond_breaks.csv", "checkpoint.bin"};

std::size_t breakages(const fs::path& run) {
  std::ifstream in(run / "bond_breaks.csv");
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.ends_with(",tension") || line.ends_with(",shear");
  return n;
}

}  // namespace

TEST_F(MaterialsCli, BondsBreakTheSameForOneAndTwoThreadsAndAcrossAResume) {
  const fs::path config = write("layered.toml", kLayered);
  const fs::path one = dir_ / "one";
  // Killed after its third output (checkpoint after the second): bonds broke on both sides.
  ASSERT_NO_FATAL_FAILURE(expect_same_runs(" '" + config.string() + "'", dir_, kLayeredFiles));
  EXPECT_GT(breakages(one), 100u);

  // The outputs carry the materials: each disc's material and slip, the names in order.
  const SnapshotReader reader(one / "snapshots.h5");
  EXPECT_EQ(reader.metadata().strings.at("materials_names"), "rock\nweak\n");
  const Snapshot last = reader.read(reader.count() - 1);
  const auto& y0 = last.field("y0");
  ASSERT_EQ(last.material.size(), last.size());
  for (std::size_t i = 0; i < last.size(); ++i)
    EXPECT_EQ(last.material[i], y0[i] < 1.5 ? 1 : 0) << "disc " << last.id[i] << " at y0 = " << y0[i];
  double slip = 0;
  for (double s : last.field("slip")) slip = std::max(slip, s);
  EXPECT_GT(slip, 0.5);
}

// Rolling resistance (docs/model.md): the same layered wedge with every contact resisting rolling
// (contact.rolling_friction, the default of both materials; the settling before the materials
// resists too) gives the same bits for one and two threads and across a kill and resume, its
// rolling histories in the checkpoint; and it is not the wedge without it.
TEST_F(MaterialsCli, RollingResistanceIsTheSameForOneAndTwoThreadsAndAcrossAResume) {
  const fs::path config = write("layered.toml", kLayered);
  const fs::path plain = dir_ / "plain", one = dir_ / "one";
  ASSERT_EQ(run_orogen("run '" + config.string() + "' --out '" + plain.string() + "' --threads 1", dir_,
                       "OROGEN_MIN_PARALLEL_ITEMS=16 ")
                .status,
            0);
  ASSERT_NO_FATAL_FAILURE(
      expect_same_runs(" '" + config.string() + "' --set contact.rolling_friction=0.2", dir_, kLayeredFiles));
  EXPECT_NE(slurp(plain / "series.csv"), slurp(one / "series.csv"));
}

// The Brazilian test keeps its peak force in the checkpoint: one and two threads and a kill
// after its peak give the same bits, summary included.
TEST_F(MaterialsCli, ABrazilianTestIsTheSameForOneAndTwoThreadsAndAcrossAResume) {
  const std::string args =
      " --set run.experiment=biaxial --set biaxial.test=brazilian --set materials.rock.friction=0.5"
      " --set materials.rock.bond_tensile_strength=5 --set biaxial.material=rock --set particles.packing=random_discs"
      " --set biaxial.width=12 --set biaxial.height=12 --set biaxial.strain_end=0.02 --set biaxial.sigma3=0.5"
      " --set biaxial.outputs=20 --set output.checkpoint_every=1 --set output.progress=never";
  std::vector<std::string> files = kLayeredFiles;
  files.push_back("summary.csv");
  ASSERT_NO_FATAL_FAILURE(expect_same_runs(args, dir_, files, 25));
  EXPECT_GT(breakages(dir_ / "one"), 10u);
}

TEST_F(MaterialsCli, BadMaterialsAndUnitsExitWith2AndWriteNothing) {
  const std::string base = "[run]\nexperiment = \"singly_vergent\"\n[layer]\nthickness = 6.0\n";
  const std::string rock = "[materials.rock]\nfriction = 0.5\n";
  struct Case {
    std::string text;
    std::vector<std::string> expect;
  };
  const std::vector<Case> cases = {
      {base + "[[layer.units]]\nmaterial = \"granite\"\nthickness = 2.0\n" + rock,
       {"layer.units.material", "\"granite\"", "rock"}},
      {base + "[[layer.units]]\nmaterial = \"rock\"\nthickness = 7.0\n" + rock,
       {"layer.units", "layer.thickness = 6.0", "at most"}},
      {base + rock + "bond_tensile_strength = -1.0\n", {"materials.rock.bond_tensile_strength", "-1.0", ">= 0"}},
      {base + rock + "bond_shear_strength = nan\n", {"materials.rock.bond_shear_strength", "finite"}},
      {base + rock + "friction_residual = 0.6\n", {"materials.rock.friction_residual", "0.6", "at most the peak"}},
      {base + "[materials.rock]\nfriction_residual = 0.2\n", {"materials.rock.friction", "required"}},
      {base + rock + "cohesion = 2.0\n", {"materials.rock.cohesion", "unknown key", "bond_tensile_strength"}},
      {base + rock + "bond_tensile_strength = 2.0\nbond_shear_strength = 0.0\n",
       {"materials.rock.bond_shear_strength", "> 0 for a material that bonds"}},
      {base + "[time]\ndt = 0.005\n" + rock + "bond_tensile_strength = 2.0\nbond_stiffness = 100.0\n",
       {"time.dt", "0.005", "stability limit", "bond_stiffness"}},
      {base + "[singly]\nbasal_weakening = 0.3\n", {"singly.basal_weakening", "0.3", "[materials.NAME]"}},
      {base + "[singly]\nbasal_weakening = 1.0\n" + rock, {"singly.basal_weakening", "< 1"}},
      {"[wedge]\nbasal_weakening = 0.2\n", {"wedge.basal_weakening", "0.2", "[materials.NAME]"}},
      {base + rock + "rolling_friction = -0.1\n", {"materials.rock.rolling_friction", "-0.1", ">= 0"}},
      {base + "[contact]\nrolling_stiffness = 3.0\n", {"contact.rolling_stiffness", "3.0", "<= 2"}},
  };
  int k = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const fs::path config = write("bad" + std::to_string(k) + ".toml", c.text);
    const fs::path out = dir_ / ("out" + std::to_string(k++));
    const auto r = run_orogen("run '" + config.string() + "' --out '" + out.string() + "'", dir_);
    EXPECT_EQ(r.status, 2) << r.err;
    for (const auto& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << "missing '" << e << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // --set reaches a material's keys and checks them the same way.
  const fs::path config = write("good.toml", base + rock);
  const auto r = run_orogen("run '" + config.string() + "' --out '" + (dir_ / "set").string() +
                                "' --set materials.rock.weakening_distance=0",
                            dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("materials.rock.weakening_distance"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "set"));
}
