// Named materials against their analytic cases (docs/materials.md): a bonded pair pulled apart
// breaks at its tensile strength and sheared at its shear strength, a bonded beam of discs
// bends as the discrete beam does, a slip-weakening contact follows its curve, a contact that
// resists rolling follows its elastic-plastic curve, and the units of a layer take their
// materials by height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/materials.hpp"
#include "world/world.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

using namespace orogen;

namespace {

constexpr double kKn = 1e4, kKs = 5e3;

// A weightless world of one material, the given discs (radius 0.5) at rest.
World bonded_world(const std::vector<std::pair<double, double>>& centres, const Material& m) {
  World w;
  inside(w).body.gx = inside(w).body.gy = 0;
  inside(w).law.kn = kKn;
  inside(w).law.ks = kKs;
  inside(w).dt = 1e-3;
  inside(w).materials.list = {m};
  for (const auto& [x, y] : centres) w.add_disc(x, y, 0.5);
  w.enable_materials();
  return w;
}

Material bonding(double tensile, double shear) {
  Material m;
  m.name = "rock";
  m.friction = m.friction_residual = 0.3;
  m.bond.tensile_strength = tensile;
  m.bond.shear_strength = shear;
  return m;
}

// Disc 0 held at rest, disc 1 moved at (vx, vy) without spin: kinematic in effect, but dynamic
// (a bond of two kinematic discs acts on nothing and is left out), put on its path after every
// step.
void drive_second_disc(World& w, double vx, double vy) {
  w.edit_motion([&](MotionEdit& e) { e.disc(0, Motion::Kinematic); });
  inside(w).discs.vx[1] = vx;
  inside(w).discs.vy[1] = vy;
  const double x0 = w.discs().x[1], y0 = w.discs().y[1];
  w.hooks().add(Stage::AfterIntegration, "drive", [=](World& world) {
    const double t = static_cast<double>(world.step() + 1) * world.dt();
    inside(world).discs.x[1] = x0 + vx * t;
    inside(world).discs.y[1] = y0 + vy * t;
    inside(world).discs.vx[1] = vx;
    inside(world).discs.vy[1] = vy;
    inside(world).discs.omega[1] = 0;
  });
}

}  // namespace

TEST(Bonds, APairPulledApartBreaksInTensionAtItsStrength) {
  const double strength = 5, v = 1e-3;
  World w = bonded_world({{0, 0}, {1, 0}}, bonding(strength, 100));
  ASSERT_EQ(w.make_bonds(0, 2, 1), 1u);
  drive_second_disc(w, v, 0);
  const double area = 1.0;  // 2 R, R = lambda r = 0.5
  const double per_step = kKn * area * v * w.dt();
  double last_fn = 0;
  int steps = 0;
  while (!w.bonds().id_a.empty() && steps < 100000) {
    w.advance();
    ++steps;
    if (!w.bonds().id_a.empty()) {
      last_fn = w.bonds().fn[0];
      // Elastic until it breaks: k_n A times the opening.
      EXPECT_NEAR(last_fn, kKn * area * (w.discs().x[1] - w.discs().x[0] - 1.0), 1e-9 * strength) << steps;
    }
  }
  ASSERT_EQ(w.bonds().breaks.size(), 1u);
  EXPECT_EQ(w.bonds().breaks[0].mode, BondBreakMode::Tension);
  EXPECT_EQ(w.bonds().breaks[0].id_a, 0);
  EXPECT_EQ(w.bonds().breaks[0].id_b, 1);
  // It held at last_fn and broke on the step that would have carried it past the strength.
  EXPECT_LT(last_fn / area, strength);
  EXPECT_GE((last_fn + per_step * (1 + 1e-9)) / area, strength);
  // The broken bond is gone for good: the pair, apart, feels nothing.
  w.advance();
  EXPECT_TRUE(w.bonds().id_a.empty());
}

TEST(Bonds, APairShearedBreaksInShearAtItsStrength) {
  const double strength = 3, v = 1e-3;
  World w = bonded_world({{0, 0}, {1, 0}}, bonding(100, strength));
  ASSERT_EQ(w.make_bonds(0, 2, 1), 1u);
  drive_second_disc(w, 0, v);
  const double area = 1.0, per_step = kKs * area * v * w.dt();
  double last_fs = 0;
  int steps = 0;
  while (!w.bonds().id_a.empty() && steps < 100000) {
    w.advance();
    ++steps;
    if (!w.bonds().id_a.empty()) last_fs = w.bonds().fs[0];
  }
  ASSERT_EQ(w.bonds().breaks.size(), 1u);
  EXPECT_EQ(w.bonds().breaks[0].mode, BondBreakMode::Shear);
  EXPECT_LT(last_fs, 0);  // resists b moving along +t
  EXPECT_LT(std::fabs(last_fs) / area, strength);
  // The normal direction turns a little as b moves up: allow 1% beyond one step's increment.
  EXPECT_GE((std::fabs(last_fs) + 1.01 * per_step) / area, strength);
}

TEST(Bonds, ABondedBeamBendsAsTheDiscreteBeamSays) {
  // A cantilever of n bonds (n + 1 discs in a row), the root disc held (kinematic: no spin),
  // a load P down on the tip disc, damped to rest. Each bond is a beam segment of length 1 with
  // bending stiffness k_n I (I = (2R)^3 / 12) and shear stiffness k_s A: the bond j (from the
  // root) carries the moment P (n - j - 1/2) at its contact point, so the tip sinks by
  //   P n (4 n^2 - 1) / (12 k_n I) + n P / (k_s A)
  // (the midpoint sum of the Euler-Bernoulli integral, exact for the chain, plus the shear).
  const int n = 10;
  const double P = 0.01;
  std::vector<std::pair<double, double>> centres;
  for (int k = 0; k <= n; ++k) centres.emplace_back(k, 0);
  World w = bonded_world(centres, bonding(1e9, 1e9));
  ASSERT_EQ(w.make_bonds(0, n + 1, 1), static_cast<std::size_t>(n));
  w.edit_motion([&](MotionEdit& e) { e.disc(0, Motion::Kinematic); });
  inside(w).body.drag = 0.5;  // to rest
  const std::size_t tip = n;
  w.hooks().add(Stage::AfterForces, "load", [&](World& world) { inside(world).scratch.forces[tip].fy -= P; });
  for (int s = 0; s < 200000; ++s) w.advance();
  const double area = 1.0, inertia = 1.0 / 12;
  const double expected = P * n * (4.0 * n * n - 1) / (12 * kKn * inertia) + n * P / (kKs * area);
  const double deflection = -w.discs().y[tip];
  EXPECT_NEAR(deflection, expected, 1e-5 * expected) << "beam theory " << expected;
  EXPECT_LT(std::fabs(w.discs().vy[tip]), 1e-9);  // at rest
  EXPECT_TRUE(w.bonds().breaks.empty());
}

TEST(Bonds, MadeBetweenListBuildsActAtTheNextStep) {
  // Bonds made where no disc is added (the biaxial test bonds its consolidated sample), after
  // others have acted: no list build follows, and still they act from the next step.
  World w = bonded_world({{0, 0}, {1, 0}, {5, 0}, {6, 0}}, bonding(100, 100));
  ASSERT_EQ(w.make_bonds(0, 2, 1), 1u);
  w.advance();
  ASSERT_EQ(w.make_bonds(2, 4, 1), 1u);
  inside(w).discs.vx[3] = 1e-3;  // opening
  ASSERT_FALSE(w.contacts_stale());
  w.advance();
  ASSERT_EQ(w.bonds().size(), 2u);
  const std::size_t k = w.bonds().id_a[0] == 2 ? 0 : 1;
  EXPECT_GT(w.bonds().fn[k], 0.0);  // the new bond pulls
}

TEST(Bonds, OfTwoKinematicDiscsAreLeftAsTheyAre) {
  // The incoming slab's bonds: their force would act on nothing, so they are not computed.
  World w = bonded_world({{0, 0}, {1, 0}}, bonding(1, 1));
  ASSERT_EQ(w.make_bonds(0, 2, 1), 1u);
  w.edit_motion([&](MotionEdit& e) { e.disc(0, Motion::Kinematic); e.disc(1, Motion::Kinematic, 1e-3, 0); });
  for (int s = 0; s < 5000; ++s) w.advance();
  ASSERT_EQ(w.bonds().size(), 1u);
  EXPECT_EQ(w.bonds().fn[0], 0.0);
  EXPECT_TRUE(w.bonds().breaks.empty());
}

TEST(Bonds, AreMadeByTheRuleAndSurviveReordering) {
  // Three discs touching in a row and one far off; a fourth of a non-bonding material touches.
  Material rock = bonding(1, 1), sand;
  sand.name = "sand";
  World w = bonded_world({{0, 0}, {1, 0}, {2.04, 0}, {10, 0}, {0, 1}}, rock);
  inside(w).materials.list.push_back(sand);
  inside(w).discs.material[4] = 1;
  // Gap 0.04 < bond_gap 0.05: bonded; the far disc and the sand disc are not.
  EXPECT_EQ(w.make_bonds(0, 5, 1), 2u);
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (std::size_t k = 0; k < w.bonds().size(); ++k) pairs.emplace_back(w.bonds().id_a[k], w.bonds().id_b[k]);
  EXPECT_EQ(pairs, (std::vector<std::pair<std::int64_t, std::int64_t>>{{0, 1}, {1, 2}}));
  // Re-ordered and compacted discs: the bonds follow the ids.
  std::vector<std::uint8_t> keep = {1, 1, 1, 0, 1};
  inside(w).discs.compact(keep);
  std::vector<std::uint32_t> order = {3, 2, 1, 0};
  inside(w).discs.permute(order);
  w.rebuild_contacts(false);
  for (std::size_t k = 0; k < w.bonds().size(); ++k) {
    EXPECT_EQ(w.discs().id[w.bonds().a[k]], w.bonds().id_a[k]);
    EXPECT_EQ(w.discs().id[w.bonds().b[k]], w.bonds().id_b[k]);
  }
}

TEST(Bonds, StrengthScatterIsSeededByTheIdsAlone) {
  Material rock = bonding(10, 10);
  rock.bond.strength_scatter = 0.3;
  std::vector<std::pair<double, double>> row;
  for (int k = 0; k < 40; ++k) row.emplace_back(k, 0);
  World a = bonded_world(row, rock), b = bonded_world(row, rock), c = bonded_world(row, rock);
  a.make_bonds(0, 40, 7);
  b.make_bonds(20, 40, 7);  // in two goes, the other half first
  b.make_bonds(0, 20, 7);
  c.make_bonds(0, 40, 8);
  ASSERT_EQ(a.bonds().size(), 39u);
  ASSERT_EQ(b.bonds().size(), 39u);
  auto strength_of = [](const World& w, std::int64_t id) {
    for (std::size_t k = 0; k < w.bonds().size(); ++k)
      if (w.bonds().id_a[k] == id) return w.bonds().tensile[k];
    return -1.0;
  };
  double mean = 0, var = 0, differ = 0;
  for (std::int64_t id = 0; id < 39; ++id) {
    EXPECT_EQ(strength_of(a, id), strength_of(b, id));
    differ += strength_of(a, id) != strength_of(c, id);
    mean += strength_of(a, id) / 39;
  }
  for (std::int64_t id = 0; id < 39; ++id) var += std::pow(strength_of(a, id) - mean, 2) / 38;
  EXPECT_GT(differ, 30);                  // another seed, other strengths
  EXPECT_NEAR(mean, 10, 3 * 3 / std::sqrt(39.0));  // mean 10, sd 3: within three standard errors
  EXPECT_NEAR(std::sqrt(var), 3, 1.2);
}

TEST(Weakening, ASlidingContactFollowsItsCurve) {
  // Two discs of one weakening material pressed together (overlap 0.001: F_n = 10), the upper
  // one spun (kinematic): the contact slides at r omega with the geometry fixed. The friction
  // force is mu(s) F_n, s the slip the discs have accumulated, mu falling linearly from 0.6 to
  // 0.3 over 0.05 d of slip, then residual.
  Material m;
  m.name = "sand";
  m.friction = 0.6;
  m.friction_residual = 0.3;
  m.weakening_distance = 0.05;
  World w = bonded_world({{0, 0}, {0, 0.999}}, m);
  // The lower disc kinematic, the upper dynamic but put back in place, spinning, after every
  // step (a pair of two kinematic discs has no contact: its force would act on nothing).
  w.edit_motion([&](MotionEdit& e) { e.disc(0, Motion::Kinematic); });
  const double omega = 0.02;
  inside(w).discs.omega[1] = omega;
  w.hooks().add(Stage::AfterIntegration, "hold", [&](World& world) {
    inside(world).discs.x[1] = 0; inside(world).discs.y[1] = 0.999;
    inside(world).discs.vx[1] = inside(world).discs.vy[1] = 0;
    inside(world).discs.omega[1] = omega;
  });
  std::vector<DiscForce> forces;
  orogen::testing::record_step_forces(w, forces);
  const double fn = kKn * 0.001;
  int sliding = 0;
  for (int s = 0; s < 12000; ++s) {
    const double slip_before = w.discs().slip[1];
    w.advance();
    // Torque on the spun disc: -r F_t, with F_t at the limit once the spring is loaded.
    const double ft = -forces[1].torque / 0.5;
    const double mu = m.friction_at(slip_before);
    if (w.discs().slip[1] == slip_before) continue;  // still loading the spring
    ++sliding;
    EXPECT_NEAR(std::fabs(ft), mu * fn, 1e-9) << "step " << s << ", slip " << slip_before;
    // Once on the limit it slides r omega dt each step (plus, while the friction falls, the
    // spring's give as its limit drops: (0.3 / 0.05) r omega dt F_n / k_s, 1.2% of it here).
    if (slip_before > 0) {
      EXPECT_NEAR(w.discs().slip[1] - slip_before, 0.5 * omega * w.dt(), 0.015 * 0.5 * omega * w.dt());
    }
  }
  EXPECT_GT(sliding, 10000);
  EXPECT_GT(w.discs().slip[1], m.weakening_distance);  // past the end: residual
  EXPECT_EQ(w.discs().slip[0], w.discs().slip[1]);        // each disc of the contact took the slip
  EXPECT_DOUBLE_EQ(w.contact_friction(0, 1), 0.3);
}

TEST(Weakening, AContactOfTwoMaterialsSlidesAtTheWeakerFriction) {
  Material strong, weak;
  strong.name = "strong";
  strong.friction = strong.friction_residual = 0.6;
  weak.name = "weak";
  weak.friction = weak.friction_residual = 0.1;
  World w = bonded_world({{0, 0}, {1, 0}, {2, 0}}, strong);
  inside(w).materials.list.push_back(weak);
  inside(w).discs.material[2] = 1;
  EXPECT_DOUBLE_EQ(w.contact_friction(0, 1), 0.6);
  EXPECT_DOUBLE_EQ(w.contact_friction(1, 2), 0.1);
}

TEST(Rolling, AContactTurnedWithoutSlidingFollowsItsElasticPlasticCurve) {
  // Two discs pressed together (overlap 0.001: F_n = 10), the lower spun at -omega (kinematic),
  // the upper at +omega (put back in place after every step): the contact point does not slide
  // (v_t = 0, no tangential force), the discs turn against each other at 2 omega. The rolling
  // moment on the upper disc is -k_r theta, k_r = k_s r_eff^2, theta the relative rotation, up to
  // mu_r r_eff F_n, then it stays there; spun back, it unloads along k_r to the opposite limit.
  // The lower disc takes the opposite moment. Once through contact.rolling_friction (the
  // thesis's one material), once through a material's rolling_friction; a list build halfway up
  // the spring carries its history.
  for (const bool materials : {false, true}) {
    SCOPED_TRACE(materials ? "a material's rolling_friction" : "contact.rolling_friction");
    Material m = bonding(0, 0);
    m.rolling_friction = materials ? 0.1 : 0.0;
    World w = bonded_world({{0, 0}, {0, 0.999}}, m);
    if (!materials) {
      inside(w).discs.has_materials = false;
      inside(w).discs.material.clear();
      inside(w).discs.slip.clear();
      inside(w).law.rolling_friction = 0.1;
    }
    double omega = 0.02;
    w.edit_motion([&](MotionEdit& e) { e.disc(0, Motion::Kinematic); });
    inside(w).discs.omega[0] = -omega;
    inside(w).discs.omega[1] = omega;
    w.hooks().add(Stage::AfterIntegration, "hold", [&](World& world) {
      inside(world).discs.x[1] = 0; inside(world).discs.y[1] = 0.999;
      inside(world).discs.vx[1] = inside(world).discs.vy[1] = 0;
      inside(world).discs.omega[0] = -omega;
      inside(world).discs.omega[1] = omega;
    });
    std::vector<DiscForce> forces;
    orogen::testing::record_step_forces(w, forces);
    const double kr = kKs * 0.25 * 0.25, limit = 0.1 * 0.25 * kKn * 0.001;
    double theta = 0;  // the relative rotation the spring holds
    for (int s = 0; s < 150; ++s) {
      if (s == 100) {  // spun back
        omega = -omega;
        inside(w).discs.omega[0] = -omega;
        inside(w).discs.omega[1] = omega;
      }
      if (s == 10) w.rebuild_contacts(false);
      w.advance();
      theta = std::clamp(theta + 2 * omega * w.dt(), -limit / kr, limit / kr);
      EXPECT_NEAR(forces[1].torque, -kr * theta, 1e-12) << "step " << s;
      EXPECT_EQ(forces[0].torque, -forces[1].torque) << "step " << s;
      EXPECT_EQ(forces[1].fx, 0.0);
    }
    EXPECT_NEAR(forces[1].torque, limit, 1e-12);  // at the opposite limit after unloading
  }
}

TEST(Units, DiscsTakeTheMaterialOfTheUnitAtTheirHeight) {
  const std::vector<LayerUnit> units = {{2, 1.5}, {0, 3.0}, {1, 2.0}};
  EXPECT_EQ(material_at_height(units, 0.2), 2u);
  EXPECT_EQ(material_at_height(units, 1.6), 0u);
  EXPECT_EQ(material_at_height(units, 4.4), 0u);
  EXPECT_EQ(material_at_height(units, 4.6), 1u);
  EXPECT_EQ(material_at_height(units, 50), 1u);  // above the section: its top unit
  EXPECT_EQ(material_at_height({}, 3), 0u);
}
