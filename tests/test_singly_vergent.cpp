// The singly-vergent critical wedge (thesis 3.2.3) on a small, soft layer: a stronger base
// builds a steeper wedge, the taper settles after the transient, the backstop moves as set,
// and a shortening that would reach the far wall is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/singly_vergent_experiment.hpp"
#include "experiments/spec_from_config.hpp"
#include "packing/packing.hpp"

namespace orogen {
namespace {

double value(const std::vector<SummaryValue>& values, const std::string& name) {
  for (const auto& v : values)
    if (v.name == name) return v.value;
  ADD_FAILURE() << "no summary value " << name;
  return std::nan("");
}

// Soft contacts (k_n = 2000) allow a faster backstop and a longer step: the test runs in
// seconds while keeping h0 = 8 d, enough for a wedge several columns long.
std::vector<SummaryValue> run_singly(double mu_b) {
  const Config c = Config::load(std::nullopt, {"run.experiment=singly_vergent", "particles.packing=random_clusters",
                                               "contact.mu=0.3", "singly.mu_b=" + std::to_string(mu_b),
                                               "layer.length=120", "layer.thickness=8", "singly.shortening=3",
                                               "singly.outputs=20", "contact.kn=2000", "singly.speed=0.05"});
  auto exp = make_experiment(c);
  World w;
  apply_engine_config(c, w);
  exp->setup(w);
  const double backstop0 = w.wall(kBoxRight).ax;
  // Outputs as the runner takes them, for the steady-state statistics.
  const double interval = exp->output_interval().value();
  double next = 0;
  while (exp->advance(w))
    if (w.time() >= next) { exp->after_output(w); next += interval; }
  EXPECT_NEAR(backstop0 - w.wall(kBoxRight).ax, 3 * 8.0, 0.01);
  return exp->summary(w);
}

TEST(SinglyVergent, StrongerBaseBuildsASteeperWedgeWhoseTaperSettles) {
  const auto weak = run_singly(0.1), strong = run_singly(0.3);
  // Measured (seed 1): steady taper -1.5 (a flat, sliding sheet) and 7.6 degrees, spread 3.4.
  EXPECT_GT(value(strong, "taper_steady_deg"), value(weak, "taper_steady_deg") + 3.0);
  EXPECT_GT(value(strong, "taper_steady_deg"), 3.0);
  EXPECT_LT(value(strong, "taper_steady_deg"), 25.0);
  EXPECT_LT(value(strong, "taper_steady_sd_deg"), 5.0);
  // The strong base stacks the material higher at the backstop. (Not the width: over a weak
  // base this small layer slides and thickens as a whole, and where its "front" lies flips
  // from one realisation to the next.)
  EXPECT_GT(value(strong, "height_final"), value(weak, "height_final"));
}

TEST(SinglyVergent, AnInitialSlopeCutsAWedgeOfThatSurface) {
  // Buiter et al. (2016) experiment 1's start: the settled layer cut to a 20-degree wedge h0
  // high at the backstop.
  const Config c = Config::load(std::nullopt, {"run.experiment=singly_vergent", "particles.packing=random_discs",
                                               "layer.length=60", "layer.thickness=8", "contact.kn=2000",
                                               "singly.initial_slope=20", "singly.shortening=1"});
  auto exp = make_experiment(c);
  World w;
  apply_engine_config(c, w);
  exp->setup(w);
  const double x_back = w.wall(kBoxRight).ax, slope = std::tan(20.0 * std::numbers::pi / 180);
  double top_near_back = 0, lowest_x = x_back;
  for (std::size_t i = 0; i < w.discs().size(); ++i) {
    EXPECT_LE(w.discs().y[i], 8.0 - slope * (x_back - w.discs().x[i]) + 1e-9) << "disc " << i;
    if (x_back - w.discs().x[i] < 3) top_near_back = std::max(top_near_back, w.discs().y[i]);
    lowest_x = std::min(lowest_x, w.discs().x[i]);
  }
  EXPECT_GT(top_near_back, 8.0 - slope * 3 - 1.0);  // the wedge reaches up to its surface
  EXPECT_NEAR(x_back - lowest_x, 8.0 / slope, 2.0);  // and runs out where the surface meets the base
  // Depths below the new surface (to the centre: the top discs lie a radius down).
  EXPECT_LT(*std::min_element(w.discs().depth0.begin(), w.discs().depth0.end()), 0.5);
}

TEST(SinglyVergent, RefusesAShorteningThatReachesTheFarWall) {
  const Config c = Config::load(std::nullopt, {"run.experiment=singly_vergent", "layer.length=100",
                                               "layer.thickness=10", "singly.shortening=9"});
  try {
    make_experiment(c);
    FAIL() << "expected a configuration error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("singly.shortening"), std::string::npos) << e.what();
  }
}

TEST(SinglyVergent, ABackstopAboveTheQuasiStaticBoundWarnsUnlessRefused) {
  // 0.5 d per time unit at dt = 5e-4 (a setting LAMMPS users run): 2.5e-4 d per step, above
  // m g / k_n = 3.85e-5 d, a bound of eq. 4.3 for the constant-velocity base, not the backstop.
  auto config = [](const std::string& bound) {
    return Config::load(std::nullopt, {"run.experiment=singly_vergent", "singly.speed=0.5", "time.dt=5e-4",
                                       "singly.speed_bound=" + bound});
  };
  ASSERT_EQ(config_warnings(config("warn")).size(), 1u);
  EXPECT_NE(config_warnings(config("warn"))[0].find("thesis eq. 4.3"), std::string::npos);
  EXPECT_TRUE(config_warnings(config("off")).empty());
  EXPECT_NO_THROW(make_experiment(config("warn")));
  EXPECT_NO_THROW(make_experiment(config("off")));
  try {
    make_experiment(config("refuse"));
    FAIL() << "expected a configuration error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("singly.speed = 0.5"), std::string::npos) << e.what();
  }
  // Within the bound nothing is said.
  EXPECT_TRUE(config_warnings(Config::load(std::nullopt, {"run.experiment=singly_vergent"})).empty());
}

}  // namespace
}  // namespace orogen
