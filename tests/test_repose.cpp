// Angle of repose experiments (thesis 3.2.1-3.2.2) on small blocks: the slope rises with
// contact friction, clusters stand steeper than discs, the hexagonal packing slumps to a
// concave profile; and the profile fit itself on exact shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/profile_fit.hpp"
#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/repose_experiment.hpp"

namespace orogen {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// A finished repose run's summary, by name.
struct ReposeResult {
  std::vector<SummaryValue> values;
  std::size_t discs = 0, held_moved = 0;
  double get(const std::string& name) const {
    for (const auto& v : values)
      if (v.name == name) return v.value;
    ADD_FAILURE() << "no summary value " << name;
    return std::nan("");
  }
};

ReposeResult run_repose(const std::string& packing, double mu, const std::string& variant = "slump",
                        int size = 24) {
  const Config c = Config::load(std::nullopt, {"run.experiment=repose", "particles.packing=" + packing,
                                               "contact.mu=" + std::to_string(mu), "repose.variant=" + variant,
                                               "repose.size=" + std::to_string(size)});
  auto exp = make_experiment(c);
  World w;
  apply_engine_config(c, w);
  exp->setup(w);
  // Held discs, by id, with their positions: they must not move.
  std::vector<std::pair<std::int64_t, double>> held;
  for (std::size_t i = 0; i < w.discs().size(); ++i)
    if (!w.discs().is_dynamic(i)) held.emplace_back(w.discs().id[i], w.discs().x[i] + 1e3 * w.discs().y[i]);
  EXPECT_FALSE(held.empty());
  while (exp->advance(w)) {
  }
  ReposeResult r{exp->summary(w), w.discs().size(), 0};
  for (auto [id, key] : held)
    for (std::size_t i = 0; i < w.discs().size(); ++i)
      if (w.discs().id[i] == id && w.discs().x[i] + 1e3 * w.discs().y[i] != key) ++r.held_moved;
  return r;
}

TEST(ProfileFit, StraightLineAndParabola) {
  std::vector<double> x, line, concave, convex;
  for (int k = 0; k <= 20; ++k) {
    x.push_back(k);
    line.push_back(10 - 0.5 * k);
    concave.push_back(0.05 * (k - 20) * (k - 20));  // steep at the top (x = 0), flat at the foot
    convex.push_back(20 - 0.05 * k * k);            // flat at the top, steep at the foot
  }
  const ProfileFit f = fit_points(x, line);
  EXPECT_NEAR(f.slope, -0.5, 1e-12);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  EXPECT_NEAR(f.concavity, 0.0, 1e-9);
  // Tangent slopes at the ends of the concave parabola: -2 at x = 0 and 0 at x = 20.
  EXPECT_NEAR(fit_points(x, concave).concavity, std::atan(2.0), 1e-9);
  EXPECT_NEAR(fit_points(x, convex).concavity, -std::atan(2.0), 1e-9);
  EXPECT_FALSE(fit_points({0, 1}, {0, 1}).valid());
}

TEST(Repose, RandomDiscsSlopeRisesWithFrictionAndClustersStandSteeper) {
  const ReposeResult low = run_repose("random_discs", 0.01), high = run_repose("random_discs", 0.3);
  const ReposeResult clusters = run_repose("random_clusters", 0.3);
  for (const auto* r : {&low, &high, &clusters}) {
    EXPECT_EQ(r->get("at_rest"), 1.0);
    EXPECT_EQ(r->held_moved, 0u);
    EXPECT_GT(r->get("removed_fraction"), 0.2);  // material did flow out
    EXPECT_GT(r->get("angle_r2"), 0.85);         // a planar slope
  }
  // Measured (seed 1, size 24): 15.5, 22.6 and 33.8 degrees.
  EXPECT_GT(high.get("angle_deg"), low.get("angle_deg") + 3.0);
  EXPECT_GT(clusters.get("angle_deg"), high.get("angle_deg") + 5.0);
  EXPECT_GT(low.get("angle_deg"), 3.0);
  EXPECT_LT(clusters.get("angle_deg"), 45.0);
}

TEST(Repose, HexagonalSlumpIsConcaveAndRandomIsNearlyPlanar) {
  // Measured (seed 1): hexagonal +32 degrees at size 30 (+20 at size 24), random discs -15.
  // A random slope's concavity is noise about a plane: over seeds 1-14 it was -1.4 +- 10.0
  // degrees (-8.4 +- 9.6 with the list order before 2026-11-25), never beyond 23 in magnitude.
  const ReposeResult hex = run_repose("hexagonal", 0.03, "slump", 30), random = run_repose("random_discs", 0.3);
  EXPECT_GT(hex.get("concavity_deg"), 15.0);
  EXPECT_LT(std::fabs(random.get("concavity_deg")), 25.0);
  EXPECT_GT(hex.get("concavity_deg") - random.get("concavity_deg"), 15.0);
  // The hexagonal slope follows its close-packed planes: steeper than any random packing here.
  EXPECT_GT(hex.get("angle_deg"), 40.0);
}

TEST(Repose, LedgeKeepsItsLipAndDeformsInternally) {
  const ReposeResult ledge = run_repose("random_clusters", 0.1, "ledge");
  EXPECT_EQ(ledge.get("at_rest"), 1.0);
  EXPECT_EQ(ledge.held_moved, 0u);
  EXPECT_GT(ledge.get("removed_fraction"), 0.1);
  EXPECT_LT(ledge.get("removed_fraction"), 0.8);  // the lip retains the lower part
  EXPECT_GT(ledge.get("angle_deg"), 5.0);
}

TEST(Repose, RefusesAMaximumTimeBeforeTheFirstRestCheck) {
  const Config c = Config::load(std::nullopt, {"run.experiment=repose", "repose.min_time=50", "repose.max_time=40"});
  try {
    make_experiment(c);
    FAIL() << "expected a configuration error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("repose.max_time"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("repose.min_time = 50"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace orogen
