// The scripted experiment (geometry from a Python setup function): it ends on
// scripted.duration with its last output there, refuses a run without a duration, and the
// time step check refuses discs built below particles.d_min.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/time_step_config.hpp"

namespace orogen {
namespace {

Config scripted_config(std::vector<std::string> extra = {}) {
  extra.insert(extra.begin(), {"run.experiment=scripted", "scripted.duration=0.5", "scripted.outputs=4"});
  return Config::load(std::nullopt, extra);
}

std::string config_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Scripted, StartsEmptyAndEndsAtItsDuration) {
  const Config c = scripted_config();
  auto exp = make_experiment(c);
  World w;
  apply_engine_config(c, w);
  exp->setup(w);
  EXPECT_EQ(w.discs().size(), 0u);
  EXPECT_TRUE(w.walls().empty());
  w.add_disc(0.0, 5.0, 0.5);  // what a setup function does: one disc falling freely
  ASSERT_EQ(exp->output_interval().value(), 0.5 / 4);
  std::uint64_t steps = 0;
  while (exp->advance(w)) ++steps;
  EXPECT_GE(w.time(), 0.5 - 1e-9);
  EXPECT_LT(w.time(), 0.5 + w.dt());
  EXPECT_FALSE(exp->advance(w));  // done stays done, without a step
  EXPECT_EQ(w.step(), steps + 1);
  EXPECT_LT(w.discs().vy[0], 0.0);  // the engine's gravity acts
  const auto row = exp->measure(w);
  ASSERT_EQ(row.size(), exp->columns().size());
  EXPECT_EQ(row[2], 1.0);  // n_discs
}

TEST(Scripted, RefusesARunWithoutADuration) {
  const std::string msg = config_error_of([] {
    (void)make_experiment(Config::load(std::nullopt, {"run.experiment=scripted"}));
  });
  EXPECT_NE(msg.find("scripted.duration"), std::string::npos) << msg;
}

TEST(Scripted, RefusesDiscsTooSmallForTheTimeStep) {
  const Config c = scripted_config({"particles.d_min=0.8"});
  World w;
  apply_engine_config(c, w);
  EXPECT_NO_THROW(check_world_time_step(c, w));  // no discs: nothing to refuse
  w.add_disc(0.0, 0.0, 0.4);
  EXPECT_NO_THROW(check_world_time_step(c, w));
  w.add_disc(2.0, 0.0, 0.1);
  const std::string msg = config_error_of([&] { check_world_time_step(c, w); });
  EXPECT_NE(msg.find("particles.d_min"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.2"), std::string::npos) << msg;  // the diameter found
}

}  // namespace
}  // namespace orogen
