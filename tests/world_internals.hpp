#pragma once
// White-box tests of the engine set up and inspect states that no experiment makes (a force
// by hand, a wall turned rough, a contact's history): they reach the World's state through
// this friend. Code outside the tests changes a World only through its API (world/world.hpp).
#include "world/world.hpp"

namespace orogen {

struct WorldInternals {
  Discs& discs;
  Clusters& clusters;
  std::vector<Wall>& walls;
  ContactLaw& law;
  BodyForce& body;
  NeighborList& neighbors;
  ContactStore& contacts;
  MaterialTable& materials;
  Bonds& bonds;
  PairScratch& scratch;
  double& moved;
  double& dt;
  double& time;
  std::uint64_t& step;
  int& sort_every;
  std::int64_t& next_disc_id;
  std::vector<RemovalRecord>& removals;

  explicit WorldInternals(World& w)
      : discs(w.discs_), clusters(w.clusters_), walls(w.walls_), law(w.law_), body(w.body_), neighbors(w.neighbors_),
        contacts(w.contacts_), materials(w.materials_), bonds(w.bonds_), scratch(w.scratch_), moved(w.moved_),
        dt(w.dt_), time(w.time_), step(w.step_), sort_every(w.sort_every_), next_disc_id(w.next_disc_id_),
        removals(w.removals_) {}
};

inline WorldInternals inside(World& w) { return WorldInternals(w); }

}  // namespace orogen
