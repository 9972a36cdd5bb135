// The results of a wedge run (summary.csv): the power law of the height, the late tapers, the
// shape at the end, and the history's round trip through a checkpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "experiments/wedge_summary.hpp"
#include "temp_dir_fixture.hpp"

namespace orogen {
namespace {

std::map<std::string, double> by_name(const std::vector<SummaryValue>& values) {
  std::map<std::string, double> m;
  for (const SummaryValue& v : values) m[v.name] = v.value;
  return m;
}

WedgeHistory power_law_history() {
  WedgeHistory h;
  for (int k = 0; k <= 40; ++k) {
    const double s = 0.5 * k;
    // Before S = 5 the height follows another law, which the fit must leave out.
    const double height = s < 5 ? 0.1 * s : 0.3 * std::pow(s, 0.55);
    h.record({s, height, -2.0 * s, -s, s, 0.5 * s, 0.1, s < 5 ? 30.0 : 8.0, s < 5 ? 40.0 : 12.0});
  }
  return h;
}

TEST(WedgeSummary, FitsThePowerLawAndTheLateTapersFromTheGivenS) {
  const auto m = by_name(power_law_history().summary(5.0));
  EXPECT_NEAR(m.at("H_b"), 0.55, 1e-12);
  EXPECT_NEAR(m.at("H_a"), 0.3, 1e-12);
  EXPECT_NEAR(m.at("H_r2"), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.at("alpha_late_deg"), 8.0);
  EXPECT_DOUBLE_EQ(m.at("beta_late_deg"), 12.0);
  EXPECT_DOUBLE_EQ(m.at("S_final"), 20.0);
  EXPECT_DOUBLE_EQ(m.at("Dp_final"), -40.0);
  EXPECT_DOUBLE_EQ(m.at("Mr_final"), 10.0);
}

TEST(WedgeSummary, EmptyHistoryGivesNaNsNotACrash) {
  const auto m = by_name(WedgeHistory{}.summary(1.0));
  EXPECT_TRUE(std::isnan(m.at("H_b")));
  EXPECT_TRUE(std::isnan(m.at("H_final")));
  EXPECT_TRUE(std::isnan(m.at("alpha_late_deg")));
}

class WedgeSummaryFiles : public testing::TempDirTest {};

TEST_F(WedgeSummaryFiles, HistoryTravelsInTheCheckpointAndAnOldOneLoadsEmpty) {
  ArchiveWriter with;
  power_law_history().save(with, "wedge");
  with.finish(dir_ / "with.bin");
  ArchiveWriter without;
  without.put_scalar("wedge.t_start", 1.0);
  without.finish(dir_ / "without.bin");

  WedgeHistory loaded;
  loaded.load(ArchiveReader(dir_ / "with.bin"), "wedge");
  const auto a = by_name(power_law_history().summary(5.0)), b = by_name(loaded.summary(5.0));
  for (const auto& [name, value] : a) EXPECT_EQ(b.at(name), value) << name;

  loaded.load(ArchiveReader(dir_ / "without.bin"), "wedge");
  EXPECT_TRUE(std::isnan(by_name(loaded.summary(0.0)).at("S_final")));
}

}  // namespace
}  // namespace orogen
