#pragma once
// What a rank's step (rank_step.cpp) reaches inside its copy of the World: the state it
// exchanges and the parts of World::advance it runs around its own phases. The World's friend
// for this module alone, as tests/world_internals.hpp is for the tests.
#include "world/world.hpp"

namespace orogen {

struct RankAccess {
  World& world;
  Discs& discs;
  Clusters& clusters;
  const std::vector<Wall>& walls;
  const ContactLaw& law;
  const BodyForce& body;
  const NeighborList& neighbors;
  ContactStore& contacts;
  std::vector<DiscForce>& forces;
  double& moved;
  const double dt;

  explicit RankAccess(World& w)
      : world(w), discs(w.discs_), clusters(w.clusters_), walls(w.walls_), law(w.law_), body(w.body_),
        neighbors(w.neighbors_), contacts(w.contacts_), forces(w.scratch_.forces), moved(w.moved_), dt(w.dt_) {}

  void rebuild_if_stale() { world.rebuild_if_stale(); }
  // The store's rolling histories kept or dropped for this step, as World::step_stages does (a
  // world over ranks has no materials: the law's coefficient for every pair).
  void prepare_rolling() {
    DiscCoefficients uniform;
    world.prepare_rolling(uniform);
  }
  void finish_step() { world.finish_step(); }
};

}  // namespace orogen
