// The surface laws in a wedge run end to end (docs/surface.md): every law on, with deposition
// and recycling, gives the same bits for one and two threads and across a kill and resume; every
// removal is logged with its law; the area ledger balances to round-off; bad [surface] input is
// refused with exit 2 and nothing written; a law that would remove the layer stops with exit 3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_labelled.hpp"
#include "io/snapshot_reader.hpp"
#include "refused_input.hpp"
#include "same_outputs.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using namespace orogen;
using orogen::testing::run_orogen;
using orogen::testing::slurp;
using orogen::testing::expect_same_outputs;

namespace {

class SurfaceCli : public orogen::testing::TempDirTest {
 protected:
  void SetUp() override {
    ::setenv("OMP_WAIT_POLICY", "passive", 0);  // see test_cli.cpp
    TempDirTest::SetUp();
  }
};

// A small wedge (h0 = 5) with the nonlinear hillslope, a river under windward rain on the pro
// side, deposition and recycling, and the thesis's threshold: about 30 fluvial and a few
// hillslope removals, deposits from the first output on (3 s on one core).
const std::string kSmallWedge =
    " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
    " --set wedge.window=3 --set wedge.s_end=1.0 --set wedge.outputs=6 --set wedge.erosion_height=1.1"
    " --set output.progress=never --set output.vtp=false --set output.checkpoint_every=2";
const std::string kEveryLawKeys =
    " --set surface.every=100 --set surface.diffusivity=0.2 --set surface.critical_slope=1.0"
    " --set surface.erodibility=1.0 --set surface.windward=pro --set surface.windward_factor=3"
    " --set surface.deposition=true --set surface.recycling=0.5 --set surface.base_level=0.9"
    " --set wedge.erosion_height=0";  // the laws alone erode
const std::string kEveryLaw = kSmallWedge + kEveryLawKeys;

// series.csv's rows as {column: value}.
std::vector<std::map<std::string, double>> series_rows(const fs::path& run) {
  std::ifstream in(run / "series.csv");
  std::vector<std::string> names;
  std::vector<std::map<std::string, double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream cells(line);
    std::vector<std::string> cell;
    for (std::string c; std::getline(cells, c, ',');) cell.push_back(c);
    if (names.empty()) {
      names = cell;
      continue;
    }
    std::map<std::string, double> row;
    for (std::size_t k = 0; k < names.size(); ++k) row[names[k]] = std::stod(cell[k]);
    rows.push_back(row);
  }
  return rows;
}

// The ledger at every output: the model holds what entered, less what was eroded and left, plus
// what was laid (to round-off); the laws' shares add up to no more than the erosion.
void expect_ledger_balanced(const std::vector<std::map<std::string, double>>& rows) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    const double expected =
        row.at("area_entered") - row.at("area_eroded") + row.at("area_deposited") - row.at("area_left");
    EXPECT_NEAR(row.at("area_model"), expected, 1e-12 * row.at("area_entered")) << "output " << k;
    EXPECT_GE(row.at("area_eroded") + 1e-9,
              row.at("area_eroded_hillslope") + row.at("area_eroded_fluvial") + row.at("area_eroded_script"));
  }
}

std::size_t count_of(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

}  // namespace

// A branch (orogen run --from) of a run without surface laws may switch them on: they start at
// the branch's state (the ledger from its discs, nothing carried), remove and lay discs from
// there, the same for one and two threads and across a resume.
TEST_F(SurfaceCli, LawsSwitchedOnInABranchStartThere) {
  const fs::path source = dir_ / "source";
  const auto r = run_orogen("run --out '" + source.string() + "' --threads 1" + kSmallWedge, dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(slurp(source / "series.csv").find("area_entered"), std::string::npos);
  const std::string branch = " --from '" + source.string() + ":3'" + kSmallWedge + kEveryLawKeys;
  ASSERT_NO_FATAL_FAILURE(orogen::testing::expect_same_runs(branch, dir_));
  const fs::path one = dir_ / "one";

  const auto rows = series_rows(one);
  ASSERT_EQ(rows.size(), 4u);  // outputs 3 to 6 of the source's spacing
  EXPECT_EQ(rows.front().at("area_entered"), rows.front().at("area_model"));  // nothing gone yet
  expect_ledger_balanced(rows);
  EXPECT_GT(rows.back().at("area_eroded_fluvial"), 0.0);
  const std::string removals = slurp(one / "removals.csv");
  EXPECT_GT(count_of(removals, ",eroded_fluvial\n"), 0u) << removals;
}

TEST_F(SurfaceCli, EveryLawIsTheSameForOneAndTwoThreadsAndAcrossAResume) {
  // Killed after its third output (checkpoint after the second): the carry, the ledger and the
  // deposits' times cross the resume.
  ASSERT_NO_FATAL_FAILURE(orogen::testing::expect_same_runs(kEveryLaw, dir_));
  const fs::path one = dir_ / "one";

  // Each removal with its law; deposits tagged with their time.
  const std::string removals = slurp(one / "removals.csv");
  // The rivers cut no deeper than the water they drain into (the sea at the base level): in
  // this small wedge, a few particles.
  EXPECT_GT(count_of(removals, ",eroded_fluvial\n"), 3u) << removals;
  EXPECT_GT(count_of(removals, ",eroded_hillslope\n"), 0u) << removals;
  const SnapshotReader reader(one / "snapshots.h5");
  const Snapshot last = reader.read(reader.count() - 1);
  std::size_t laid = 0;
  for (double t : last.field("deposition_time")) laid += std::isfinite(t) && t > 0;
  EXPECT_GT(laid, 0u);  // most deposits are eroded again in this small, fast-eroding run

  // orogen analyze: each deposit's time along the particle dimension, the sediment per column.
  const auto r = run_orogen("analyze '" + one.string() + "'", dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const h5::File analysis = h5::File::open(one / "analysis.h5", h5::File::Mode::ReadOnly);
  const auto ids = h5::read_block<std::int64_t>(analysis.id(), "particle", {0}, {h5::shape(analysis.id(), "particle")[0]});
  const auto times = h5::read_block<double>(analysis.id(), "deposition_time", {0}, {ids.size()});
  std::map<std::int64_t, double> laid_at;
  for (std::size_t k = 0; k < ids.size(); ++k) laid_at[ids[k]] = times[k];
  const auto& field = last.field("deposition_time");
  for (std::size_t i = 0; i < last.size(); ++i) {
    if (std::isnan(field[i])) EXPECT_TRUE(std::isnan(laid_at.at(last.id[i])));
    else EXPECT_EQ(laid_at.at(last.id[i]), field[i]);
  }
  const auto thickness = h5::shape(analysis.id(), "deposit_thickness");
  EXPECT_EQ(thickness[0], static_cast<hsize_t>(reader.count()));

  // The ledger: the model holds what entered, less what was eroded and left, plus what was laid.
  const auto rows = series_rows(one);
  ASSERT_EQ(rows.size(), 7u);
  expect_ledger_balanced(rows);
  EXPECT_GT(rows.back().at("area_deposited"), 5.0);  // a dozen discs or more
  EXPECT_GT(rows.back().at("area_recycled"), 0.0);
}

// Sedimentation without erosion: no law and no threshold, only sediment brought from outside
// and filled into both forelands up to the base level. Deposits are laid, nothing is eroded, the
// supply's books hold what the rate delivered, and the run is the same for one and two threads
// and across a kill and resume (2 s on one core).
TEST_F(SurfaceCli, AnOutsideSupplyFillsTheForelandsWithoutErosion) {
  const double rate = 0.3;
  const std::string supply = kSmallWedge + " --set wedge.erosion_height=0 --set surface.every=100"
                             " --set surface.deposition=true --set surface.sediment_supply=0.3"
                             " --set surface.base_level=1.3";
  ASSERT_NO_FATAL_FAILURE(orogen::testing::expect_same_runs(supply, dir_));
  const fs::path one = dir_ / "one";
  EXPECT_EQ(count_of(slurp(one / "removals.csv"), ",eroded"), 0u);
  const auto rows = series_rows(one);
  ASSERT_EQ(rows.size(), 7u);
  expect_ledger_balanced(rows);
  const auto& last = rows.back();
  EXPECT_EQ(last.at("area_eroded"), 0.0);
  EXPECT_EQ(last.at("area_recycled"), 0.0);
  EXPECT_GT(last.at("area_deposited"), 20.0);  // a few dozen discs
  EXPECT_GT(last.at("area_supplied"), last.at("area_deposited"));  // the rest still owed to the columns
  // Filled or bypassed, the supply is the rate times the time (to the last update, 100 steps
  // before the output at most).
  EXPECT_NEAR(last.at("area_supplied") + last.at("area_supply_bypassed"), rate * last.at("time"),
              1e-3 * rate * last.at("time"));
}

// A branch of a run with laws but no supply may bring one in: its books start at zero there.
TEST_F(SurfaceCli, ASupplyBroughtInByABranchStartsItsBooksThere) {
  const fs::path source = dir_ / "source", branch = dir_ / "branch";
  auto r = run_orogen("run --out '" + source.string() + "' --threads 1" + kEveryLaw, dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_orogen("run --from '" + source.string() + ":3' --out '" + branch.string() + "' --threads 1" + kEveryLaw +
                     " --set surface.sediment_supply=0.3",
                 dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = series_rows(branch);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows.front().at("area_supplied"), 0.0);
  EXPECT_GT(rows.back().at("area_supplied") + rows.back().at("area_supply_bypassed"), 0.0);
  expect_ledger_balanced(rows);
}

TEST_F(SurfaceCli, BadSurfaceInputExitsWith2AndWritesNothing) {
  orogen::testing::expect_refused({
      {"--set surface.diffusivity=-1", {"surface.diffusivity", "-1", ">= 0"}},
      {"--set surface.erodibility=0.1 --set surface.windward_factor=3", {"surface.windward_factor", "surface.windward"}},
      {"--set surface.recycling=0.5 --set surface.diffusivity=1", {"surface.recycling", "surface.deposition"}},
      {"--set surface.base_level=60", {"surface.base_level", "60", "< 50"}},
      {"--set surface.sediment_supply=0.5", {"surface.sediment_supply", "surface.deposition"}},
      {"--set surface.sediment_supply=-1", {"surface.sediment_supply", "-1", ">= 0"}},
      {"--set surface.sediment_supply=1 --set surface.deposition=true --set surface.supply_to=east",
       {"surface.supply_to", "east", "\"pro\""}},
      {"--set surface.windward=east", {"surface.windward", "east", "\"pro\""}},
      {"--set surface.sediment_material=sand --set surface.deposition=true",
       {"surface.sediment_material", "\"sand\"", "[materials]"}},
  }, dir_);
}

// A river a thousand times too strong, draining to the base: the first update would cut the
// layer away, and the run stops saying so (exit 3) rather than eroding it.
TEST_F(SurfaceCli, ALawThatWouldRemoveTheLayerStopsWithADiagnosis) {
  const fs::path out = dir_ / "gone";
  const auto r = run_orogen("run --out '" + out.string() + "' --threads 1" + kEveryLaw +
                                " --set surface.erodibility=1000 --set surface.base_level=0 --set surface.recycling=0",
                            dir_);
  EXPECT_EQ(r.status, 3) << r.err;
  const std::string log = slurp(out / "run.log");
  EXPECT_NE(log.find("would remove the whole layer"), std::string::npos) << log;
  EXPECT_NE(log.find("surface.erodibility"), std::string::npos) << log;
}

// The singly-vergent wedge with hillslopes, a river and deposition between its far wall and the
// backstop: the same bits for one and two threads and across a kill and resume, erosion logged
// with its law, the ledger balanced (1 s on one core).
TEST_F(SurfaceCli, TheSinglyVergentWedgeErodesAndDepositsAlike) {
  const std::string singly =
      " --set run.experiment=singly_vergent --set particles.packing=random_discs --set layer.length=40"
      " --set layer.thickness=6 --set contact.kn=2000 --set singly.speed=0.05 --set singly.shortening=1.5"
      " --set singly.outputs=6 --set output.progress=never --set output.vtp=false --set output.checkpoint_every=2"
      " --set surface.every=100 --set surface.diffusivity=0.3 --set surface.erodibility=0.05"
      " --set surface.deposition=true --set surface.base_level=1.0";
  // One and two threads, and killed after its third output (checkpoint after the second) then
  // resumed: the same results.
  ASSERT_NO_FATAL_FAILURE(orogen::testing::expect_same_runs(singly, dir_));
  const fs::path one = dir_ / "one";
  const std::string removals = slurp(one / "removals.csv");
  EXPECT_GT(count_of(removals, ",eroded_fluvial\n") + count_of(removals, ",eroded_hillslope\n"), 20u) << removals;
  const auto rows = series_rows(one);
  ASSERT_EQ(rows.size(), 7u);
  expect_ledger_balanced(rows);
  EXPECT_GT(rows.back().at("area_eroded"), 10.0);
}
