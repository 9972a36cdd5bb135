#pragma once
// The simulated system and its time step. One step is a fixed list of stages:
//   1. rebuild the neighbour list if some disc moved more than half the skin
//   2. disc-disc contact forces        (contact/pair_forces)
//   3. wall contact forces             (boundary/wall_forces)
//   4. body forces and integration     (integrate/integrator)
//   5. move walls, advance the clock
// Experiments add their own stages (boundary conditions, erosion, inflow, measurements)
// around World::advance() without reaching into it.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_forces.hpp"
#include "integrate/integrator.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Thrown when the simulation blows up; the message names the likely cause.
struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class RemovalReason : std::uint8_t { LeftDomain = 0, Eroded = 1, Other = 2 };

struct RemovalRecord {
  std::uint64_t step = 0;
  double time = 0;
  std::int64_t id = 0, cluster_id = -1;
  double x = 0, y = 0;
  RemovalReason reason = RemovalReason::Other;
};

// Largest stable time step for normal stiffness kn and the smallest effective pair mass:
// 0.1 * 2 pi sqrt(m_eff / kn) (MODEL §3, thesis 2.7).
double stable_time_step(double kn, double min_pair_mass);

struct World {
  Discs discs;
  Clusters clusters;
  std::vector<Wall> walls;
  ContactLaw law;
  BodyForce body;
  NeighborList neighbors;
  PairScratch scratch;
  double moved = 0;  // largest disc displacement since the last list build (from integration)
  double dt = 1e-3;
  double time = 0;
  std::uint64_t step = 0;
  int sort_every = 10;  // re-order discs in cell order every this many list builds
  std::int64_t next_disc_id = 0, next_cluster_id = 0;
  std::vector<RemovalRecord> removals;

  // One time step (stages listed above).
  void advance();

  // Stages 2-4 of a step (pair forces, wall forces, integration) in one thread team, each
  // thread on its share of `split` (one thread per share), or with none (advance) on the
  // threads step_threads gives, cut by split_threads; sets `moved`. The neighbour list must be
  // valid. Tests give lopsided splits: results never depend on the split.
  void step_stages(const ThreadSplit* split = nullptr);

  // Removes the flagged discs (flags are by disc index; a flagged cluster disc removes its
  // whole cluster), logging each removal; history of the surviving contacts is kept.
  std::size_t remove(std::span<const std::uint8_t> flags, RemovalReason reason);

  // Removes every free disc whose centre, and every cluster whose member discs' mean centre
  // height, is above the given height (the mean, not the centre of mass, which weighs big discs
  // more and can lie on the other side). Used for trimming a packing and for erosion.
  std::size_t remove_above(double height, RemovalReason reason);

  // Adds a free disc and returns its index; the neighbour list is rebuilt on the next step.
  std::size_t add_disc(double x, double y, double r);

  // Makes the given discs one rigid cluster.
  std::size_t add_cluster(std::span<const std::size_t> disc_indices);

  // Marks that the neighbour list must be rebuilt (after motion flags changed, say).
  void invalidate_neighbors() { neighbors.valid = false; }

  // Smallest effective mass of a contact pair, for the stability limit.
  double min_pair_mass() const;
  // Largest stable time step for the current stiffness and masses (MODEL §3, §2.7).
  double stable_dt() const;
  // Kinetic energy (translational and rotational) of dynamic free discs and clusters.
  double kinetic_energy() const;
};

}  // namespace orogen
