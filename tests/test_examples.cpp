// Every preset in examples/ is a valid configuration of a known experiment.
#include <gtest/gtest.h>

#include <filesystem>

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

}  // namespace
}  // namespace orogen
