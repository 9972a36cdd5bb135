// Every preset in examples/ is a valid configuration of a known experiment.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "config/config.hpp"
#include "experiments/experiment.hpp"

namespace orogen {
namespace {

TEST(Examples, EveryPresetLoadsAndNamesAKnownExperiment) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(OROGEN_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    SCOPED_TRACE(entry.path().string());
    const Config c = Config::load(entry.path(), {});
    EXPECT_NE(make_experiment(c), nullptr);
    ++count;
  }
  EXPECT_GE(count, 4);
}

// Every series.csv column states its unit in its description, as "[unit]" at the end ([-] for
// counts, fractions and other numbers without one): docs/output-files.md, Units.
TEST(Examples, EverySeriesColumnStatesItsUnit) {
  std::set<std::string> experiments;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(OROGEN_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    const Config c = Config::load(entry.path(), {});
    if (!experiments.insert(c.get_string("run.experiment")).second) continue;
    for (const auto& col : make_experiment(c)->columns()) {
      SCOPED_TRACE(c.get_string("run.experiment") + " " + col.name);
      EXPECT_TRUE(col.description.ends_with("]") && col.description.find(" [") != std::string::npos) << col.description;
    }
  }
  EXPECT_EQ(experiments.size(), 5u);
}

}  // namespace
}  // namespace orogen
