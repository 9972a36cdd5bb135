// The World's API keeps what depends on a change consistent without the caller's help, and
// its stage hooks run inside each step, in order, once (issue 17 point 3).
#include <gtest/gtest.h>

#include <stdexcept>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

#include "world/world.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// Two discs pressed together along y, the upper one sliding along x over the lower, held one.
World sliding_pair() {
  World w;
  inside(w).body.gx = inside(w).body.gy = 0;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).dt = 1e-4;
  w.add_disc(0, 0, 0.5);
  w.add_disc(0, 0.99, 0.5);
  w.edit_motion([](MotionEdit& e) { e.disc(0, Motion::Kinematic); });
  inside(w).discs.vx[1] = 0.1;
  return w;
}

TEST(StageHooks, RunInOrderOncePerStepAtTheirStage) {
  World w;
  w.add_disc(0, 5, 0.5);  // falls freely under gravity
  std::vector<std::pair<char, std::uint64_t>> seen;  // (hook, step)
  double y_before = 0;
  w.hooks().add(Stage::AfterIntegration, "c", [&](World& world) {
    seen.emplace_back('c', world.step());
    EXPECT_LT(world.discs().y[0], y_before);  // the disc has moved, the clock not yet
  });
  w.hooks().add(Stage::AfterForces, "a", [&](World& world) {
    seen.emplace_back('a', world.step());
    EXPECT_EQ(world.discs().y[0], y_before);  // forces summed, nothing moved yet
  });
  w.hooks().add(Stage::AfterForces, "b", [&](World& world) { seen.emplace_back('b', world.step()); });
  // The same name again replaces the hook rather than running it twice.
  w.hooks().add(Stage::AfterForces, "b", [&](World& world) { seen.emplace_back('B', world.step()); });
  EXPECT_EQ(w.hooks().names(Stage::AfterForces), (std::vector<std::string>{"a", "b"}));
  for (int s = 0; s < 3; ++s) {
    y_before = w.discs().y[0];
    w.advance();
  }
  const std::vector<std::pair<char, std::uint64_t>> expected = {{'a', 0}, {'B', 0}, {'c', 0}, {'a', 1}, {'B', 1},
                                                                {'c', 1}, {'a', 2}, {'B', 2}, {'c', 2}};
  EXPECT_EQ(seen, expected);
  w.hooks().remove("a");
  EXPECT_EQ(w.hooks().names(Stage::AfterForces), (std::vector<std::string>{"b"}));
}

TEST(StageHooks, AnErrorInAHookLeavesTheStep) {
  World w;
  w.add_disc(0, 5, 0.5);
  w.hooks().add(Stage::AfterForces, "fails", [](World&) { throw std::runtime_error("hook failed"); });
  EXPECT_THROW(w.advance(), std::runtime_error);
}

// A copy stepped with the original's hooks would change the state of the original's
// experiment (what the hooks capture): a copy starts without them; a move keeps them.
TEST(StageHooks, ACopyOfAWorldHasNoHooksAMoveKeepsThem) {
  World w;
  w.add_disc(0, 5, 0.5);
  int calls = 0;
  w.hooks().add(Stage::AfterForces, "count", [&](World&) { ++calls; });
  World copy = w;
  EXPECT_TRUE(copy.hooks().empty(Stage::AfterForces));
  copy.advance();
  EXPECT_EQ(calls, 0);
  World assigned;
  assigned = w;
  EXPECT_TRUE(assigned.hooks().empty(Stage::AfterForces));
  w.advance();
  EXPECT_EQ(calls, 1);
  World moved = std::move(w);
  moved.advance();
  EXPECT_EQ(calls, 2);
}

TEST(WorldApi, ChangedFrictionIsSeenByTheNextForcePass) {
  World w = sliding_pair();
  double fx = -1;
  w.hooks().add(Stage::AfterForces, "record", [&](World& world) { fx = world.scratch().forces[1].fx; });
  w.set_friction(0.0);
  w.advance();
  EXPECT_EQ(fx, 0.0);  // frictionless: no force along the sliding direction
  w.set_friction(0.5);
  EXPECT_EQ(w.friction(), 0.5);
  w.advance();
  EXPECT_LT(fx, 0.0);  // friction now resists the sliding
}

TEST(WorldApi, ChangedContactLawRebuildsTheDashpots) {
  World w = sliding_pair();
  w.advance();
  ASSERT_TRUE(w.neighbors().valid);
  const double gamma = w.contacts().pairs.gamma_n.at(0);
  ContactLaw stiffer = w.law();
  stiffer.kn *= 4;
  w.set_contact_law(stiffer);
  EXPECT_FALSE(w.neighbors().valid);
  w.advance();
  EXPECT_GT(w.contacts().pairs.gamma_n.at(0), 1.5 * gamma);  // 2 zeta sqrt(k_n m_eff): about twice at 4 k_n
}

TEST(WorldApi, MotionEditsUpdateClustersAndTheList) {
  World w;
  inside(w).body.gx = inside(w).body.gy = 0;
  const std::size_t a = w.add_disc(0, 0, 0.5), b = w.add_disc(1, 0, 0.5), free_disc = w.add_disc(5, 0, 0.5);
  const std::vector<std::size_t> members = {a, b};
  w.add_cluster(members);
  w.advance();
  ASSERT_TRUE(w.neighbors().valid);

  // Nothing changes: nothing is rebuilt.
  w.edit_motion([&](MotionEdit& e) { EXPECT_FALSE(e.disc(free_disc, Motion::Dynamic)); });
  EXPECT_TRUE(w.neighbors().valid);

  // The cluster turns kinematic: its member discs follow at once, with the body's velocity,
  // and the list (wall contacts are listed for dynamic discs) is rebuilt.
  w.edit_motion([&](MotionEdit& e) { EXPECT_TRUE(e.cluster(0, Motion::Kinematic, 0.5, -0.25)); });
  EXPECT_FALSE(w.neighbors().valid);
  for (auto i : {a, b}) {
    EXPECT_FALSE(w.discs().is_dynamic(i));
    EXPECT_EQ(w.discs().vx[i], 0.5);
    EXPECT_EQ(w.discs().vy[i], -0.25);
  }
  // A member disc goes with its cluster: MotionEdit::disc refuses it, body_of takes the cluster.
  w.edit_motion([&](MotionEdit& e) {
    EXPECT_THROW(e.disc(a, Motion::Dynamic), std::logic_error);
    EXPECT_TRUE(e.body_of(b, Motion::Dynamic));
  });
  EXPECT_TRUE(w.discs().is_dynamic(a));
  EXPECT_EQ(w.clusters().motion[0], static_cast<std::uint8_t>(Motion::Dynamic));
}

TEST(WorldApi, WallsByNameAndTheirInvariants) {
  World w;
  Wall floor = testing::wall(-10, 0, 10, 0, WallFriction::Rough, 0.3);
  floor.name = "floor";
  Wall side = testing::wall(10, 0, 10, 10);
  side.name = "side";
  w.set_walls({floor, side});
  w.add_disc(0, 0.49, 0.5);
  w.advance();
  ASSERT_TRUE(w.neighbors().valid);

  EXPECT_EQ(w.wall_index("side"), 1u);
  EXPECT_EQ(w.wall("floor").mu, 0.3);
  try {
    (void)w.wall("roof");
    ADD_FAILURE() << "no error for a missing wall";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'roof'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("floor, side"), std::string::npos) << e.what();
  }

  // Velocity and friction are read at every step: the list stands.
  w.set_wall_velocity("side", -0.1, 0);
  w.set_wall_friction("floor", WallFriction::Smooth, 0.0);
  EXPECT_TRUE(w.neighbors().valid);
  EXPECT_EQ(w.wall("side").vx, -0.1);
  EXPECT_EQ(w.wall("floor").friction, WallFriction::Smooth);

  // The disc rests on the floor; switching the floor off drops its contact at the next step.
  EXPECT_EQ(w.wall_contact_stats(0).touching, 1u);
  w.enable_wall("floor", false);
  EXPECT_FALSE(w.neighbors().valid);
  w.advance();
  EXPECT_EQ(w.wall_contact_stats(0).touching, 0u);

  // New walls replace the old ones and the list with them.
  w.set_walls({side});
  EXPECT_FALSE(w.neighbors().valid);
  EXPECT_EQ(w.wall_index("side"), 0u);
}

// The state is read through views that cannot change it, even of a world one may change.
static_assert(std::is_same_v<decltype(std::declval<World&>().discs()), const Discs&>);
static_assert(std::is_same_v<decltype(std::declval<World&>().walls()), const std::vector<Wall>&>);
static_assert(std::is_same_v<decltype(std::declval<World&>().law()), const ContactLaw&>);
static_assert(std::is_same_v<decltype(std::declval<World&>().neighbors()), const NeighborList&>);
static_assert(!std::is_aggregate_v<World>);

// The changes that keep something consistent do so: a moved disc, a new skin or time step
// rebuilds the list, a list build forgets the displacement, the per-disc records change nothing
// else.
TEST(WorldApi, DiscEditsAndSettingsKeepTheListConsistent) {
  World w = sliding_pair();
  w.advance();
  ASSERT_TRUE(w.neighbors().valid);
  w.set_disc_velocity(1, 0.2, 0, 0);
  w.set_initial_depth(1, 3.0);
  w.set_start_position(1, 1.0, 2.0);
  w.set_sort_every(0);
  EXPECT_TRUE(w.neighbors().valid);
  EXPECT_EQ(w.discs().vx[1], 0.2);
  EXPECT_EQ(w.discs().depth0[1], 3.0);
  EXPECT_EQ(w.discs().y0[1], 2.0);
  w.set_time_step(5e-5);
  EXPECT_FALSE(w.neighbors().valid);
  EXPECT_EQ(w.dt(), 5e-5);
  w.advance();

  w.move_disc(1, 0.0, 1.5);
  EXPECT_FALSE(w.neighbors().valid);
  w.advance();
  EXPECT_TRUE(w.neighbors().valid);
  w.set_neighbor_skin(0.2);
  EXPECT_FALSE(w.neighbors().valid);
  w.rebuild_contacts(false);
  EXPECT_EQ(w.moved(), 0.0);
  EXPECT_FALSE(w.contacts_stale());

  w.restart_clock();
  EXPECT_EQ(w.step(), 0u);
  EXPECT_EQ(w.time(), 0.0);
}

}  // namespace
}  // namespace orogen
