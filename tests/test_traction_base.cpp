// The traction base. Eq. 4.1's drag (wedge.traction_law = "drag", wall_contact_law.hpp) steps
// against the body's effective mass at the contact point (boundary/traction_mass.hpp), so a
// body carried by the plate comes to the no-slip state and stays there, with no force
// chattering at the Coulomb limit, for any drag coefficient and friction; but a body held
// back on the plate gets at most m v_t / dt from it. The Coulomb belt (traction_law =
// "spring", the default: a rough wall moving with the plate) transmits mu F_n to it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

constexpr double kPlateSpeed = 0.025;

World plate_world(double gamma, double mu) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.3;
  Wall plate = testing::wall(-100, 0, 100, 0, WallFriction::Traction, mu);
  plate.traction_gamma = gamma;
  plate.surface_speed = kPlateSpeed;
  inside(w).walls = {plate};
  inside(w).neighbors.skin = 0.3;
  return w;
}

struct Velocity {
  double vx, omega;
};

// Steps the world and returns the last two steps' velocity of disc 0 (free) or of body 0.
std::array<Velocity, 2> last_two(World& w, int steps, bool body) {
  std::array<Velocity, 2> m{};
  for (int s = 0; s < steps; ++s) {
    w.advance();
    m[0] = m[1];
    m[1] = body ? Velocity{w.clusters().vx[0], w.clusters().omega[0]} : Velocity{w.discs().vx[0], w.discs().omega[0]};
  }
  return m;
}

// A free disc on the moving plate rolls: the drag's impulse J gives it v = J / m and spin
// omega r = J r^2 / I = 2 J / m, and the contact point moves with the plate when
// v + omega r = V: v = V / 3, omega r = 2 V / 3. Before, the drag stepped against the disc's
// mass alone (a third of the contact point's effective one) and flipped sign every step at
// the Coulomb limit: v alternated between 0.0082 and 0.0086.
TEST(TractionBase, AFreeDiscRollsWithThePlateAtAThirdOfItsSpeed) {
  for (double gamma : {10.0, 1e4, 1e8}) {
    World w = plate_world(gamma, 0.2);
    w.add_disc(0, 0.5, 0.5);
    inside(w).dt = 0.5 * w.stable_dt();
    const auto m = last_two(w, 20000, false);
    for (const auto& s : m) {
      EXPECT_NEAR(s.vx, kPlateSpeed / 3, 1e-6 * kPlateSpeed) << "gamma " << gamma;
      EXPECT_NEAR(s.omega * 0.5, 2 * kPlateSpeed / 3, 1e-6 * kPlateSpeed) << "gamma " << gamma;
    }
    EXPECT_EQ(w.wall_contact_stats(0).touching, 1u);
    EXPECT_EQ(w.wall_contact_stats(0).at_limit, 0u) << "the drag sits on the Coulomb limit, gamma " << gamma;
  }
}

// A three-disc body resting on two of its discs is carried at the plate's speed without
// turning, whatever the friction: both contacts' drags together stay below deadbeat. Before,
// each contact stepped against the whole body's mass, the two overshot together, and the body
// chattered (vx 0.0248-0.0253, spin +-4e-4); with mu_bp = 20 the wedge broke up in 34 steps.
TEST(TractionBase, ABodyOnTwoOfItsDiscsMovesWithThePlate) {
  for (double mu : {0.2, 20.0}) {
    World w = plate_world(1e4, mu);
    const std::size_t a = w.add_disc(-0.4, 0.4, 0.4), b = w.add_disc(0.4, 0.4, 0.4), c = w.add_disc(0, 1.0, 0.4);
    const std::array<std::size_t, 3> members{a, b, c};
    w.add_cluster(members);
    inside(w).dt = 0.5 * w.stable_dt();
    const auto m = last_two(w, 20000, true);
    for (const auto& s : m) {
      EXPECT_NEAR(s.vx, kPlateSpeed, 1e-9) << "mu " << mu;
      EXPECT_NEAR(s.omega, 0.0, 1e-9) << "mu " << mu;
    }
    EXPECT_EQ(w.wall_contact_stats(0).touching, 2u);
    EXPECT_EQ(w.wall_contact_stats(0).at_limit, 0u) << "mu " << mu;
  }
}

// A three-disc body pressed onto the moving plate by a load of about 130 times its weight and
// held by a smooth stop ahead of it, as a disc at the base of a thick wedge is held by the
// wedge: at rest, the stop's push balances what the plate transmits, and the plate carries
// the weight and the load, so the transmitted friction is the stop's normal force over the
// plate's (both from the overlaps of the linear law; at rest no damping acts).
double transmitted_friction(WallFriction law, double mu, double dt_fraction) {
  World w = plate_world(1e4, mu);
  inside(w).walls[0].friction = law;
  const double r = 0.4;
  inside(w).walls.push_back(testing::wall(0.8, -1, 0.8, 3));  // the stop, touching disc b's right side
  const std::size_t a = w.add_disc(-0.4, r, r), b = w.add_disc(0.4, r, r), c = w.add_disc(0, 1.0, r);
  const std::array<std::size_t, 3> members{a, b, c};
  w.add_cluster(members);
  inside(w).dt = dt_fraction * w.stable_dt();
  const double load = 200.0;
  w.hooks().add(Stage::AfterForces, "test.load", [c, load](World& world) { inside(world).scratch.forces[c].fy -= load; });
  for (int s = 0; s < 40000; ++s) w.advance();
  const auto& d = w.discs();
  EXPECT_NEAR(w.clusters().vx[0], 0.0, 1e-6);
  EXPECT_NEAR(w.clusters().vy[0], 0.0, 1e-6);
  const double stop = w.law().kn * (r - (0.8 - d.x[b]));
  const double plate = w.law().kn * (r - d.y[a]) + w.law().kn * (r - d.y[b]);
  return stop / plate;
}

// The Coulomb belt transmits exactly mu_bp F_n to a body it slides under, at any time step:
// the wedge's base is a Coulomb base. Eq. 4.1's drag transmits what one step's slip can carry,
// a fraction of mu_bp that halves with dt: the base under the thesis's wedges was weaker than
// its mu_bp, and more so the thicker the wedge (docs/wedge-evidence.md).
TEST(TractionBase, TheCoulombBeltTransmitsMuFnToABodyHeldOnItAtAnyTimeStep) {
  for (double dt_fraction : {0.5, 0.25}) {
    EXPECT_NEAR(transmitted_friction(WallFriction::Rough, 0.2, dt_fraction), 0.2, 1e-6) << dt_fraction;
    EXPECT_NEAR(transmitted_friction(WallFriction::Rough, 0.5, dt_fraction), 0.5, 1e-6) << dt_fraction;
  }
  const double drag = transmitted_friction(WallFriction::Traction, 0.2, 0.5);
  const double drag_half_dt = transmitted_friction(WallFriction::Traction, 0.2, 0.25);
  EXPECT_LT(drag, 0.5 * 0.2);
  EXPECT_NEAR(drag_half_dt / drag, 2.0, 0.1) << "the drag a slip carries grows as 1 / dt";
}

}  // namespace
}  // namespace orogen
