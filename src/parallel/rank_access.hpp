#pragma once
// What a rank's step (rank_step.cpp) reaches inside its copy of the World: the state it
// exchanges and the parts of World::advance it runs around its own phases. The World's friend
// for this module alone, as tests/world_internals.hpp is for the tests.
#include "world/contact_rebuild.hpp"
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
  Bonds& bonds;
  BondScratch& bond_scratch;

  explicit RankAccess(World& w)
      : world(w), discs(w.discs_), clusters(w.clusters_), walls(w.walls_), law(w.law_), body(w.body_),
        neighbors(w.neighbors_), contacts(w.contacts_), forces(w.scratch_.forces), moved(w.moved_), dt(w.dt_),
        bonds(w.bonds_), bond_scratch(w.bond_scratch_) {}

  // A list build in two parts around the pair search, which the ranks cut between them.
  void begin_list_build(PendingBuild& build, PairRange indexed) { world.begin_list_build(build, indexed); }
  void join_list_build(PendingBuild& build, const std::vector<ChunkPairs>& chunks) {
    world.join_list_build(build, chunks);
  }
  void finish_list_build(PendingBuild& build, PairRange carried) { world.finish_list_build(build, carried); }
  // The list, for a rank to write the pairs of its chunks that others searched, or the whole
  // list gathered (rank_step.cpp).
  NeighborList& list() { return world.neighbors_; }
  // What the contact stages read besides the discs, as World::step_stages prepares it: in a
  // world of materials each disc's friction from its slip (current for the discs this rank reads:
  // they came with the ghosts) and that slip for weakening walls; the rolling histories.
  void prepare_contact_coefficients(DiscCoefficients& disc, WallSlip& wall_slip) {
    world.prepare_contact_coefficients(disc, wall_slip);
  }
  // The acting bonds first, in their discs' order, after a list build or new bonds, as
  // World::step_stages does; whether that re-ordered them (the plan's bond routes then change).
  bool prepare_bonds() {
    if (bonds.id_a.empty()) return false;
    const bool again = bond_scratch.activity_build != neighbors.builds;
    prepare_bond_scratch(bonds, discs, neighbors.builds, bond_scratch);
    return again;
  }
  void finish_step() { world.finish_step(); }
};

}  // namespace orogen
