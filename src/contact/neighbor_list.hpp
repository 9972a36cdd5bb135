#pragma once
// Contact detection (MODEL §5): a uniform cell grid sorts discs into cells, a half Verlet
// list of pairs closer than the sum of their radii plus a skin is built from neighbouring
// cells, and the list is rebuilt only when some disc has moved more than half the skin.
// Each pair carries its tangential spring history, which survives rebuilds (matched by the
// discs' stable ids) and is dropped when the discs separate.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/history_carry.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct NeighborList {
  double skin = 0.1;
  // Pairs (first, second) by disc index; the first always has the lower stable id, so the
  // sign of the history xi (measured along n rotated +90 degrees, n from first to second)
  // means the same thing after every rebuild.
  std::vector<std::uint32_t> first, second;
  std::vector<double> xi;
  std::vector<double> gamma_n;  // normal dashpot coefficient of the pair
  std::vector<std::int64_t> id_first, id_second;  // stable ids, to carry history across rebuilds
  // The pairs come in stripes of cells across the domain's long side; chunk k is pairs
  // [chunk_start[k], chunk_start[k+1]), whole stripes. A pair joins discs of one stripe or of
  // two neighbouring ones, so chunks two apart never share a disc: the force loop runs the even
  // chunks in parallel, then the odd ones, each disc summing its pairs in the same order
  // whatever the number of threads.
  std::vector<std::uint32_t> chunk_start;
  // Whether most of chunk k's pairs touched at the last build: the force loop then runs every
  // pair of the chunk through its kernel rather than testing each (contact/pair_forces.cpp).
  // Only a hint, as chunk_disc: both ways give the same bits, so it is not checkpointed.
  std::vector<std::uint8_t> chunk_dense;
  // The first disc of each chunk's stripes, chunks + 1 entries, from the last build that put
  // the discs in cell order (empty when unknown). Only a hint for cutting the discs between
  // threads where the chunks are cut (ThreadSplit): results never depend on it, so it is not
  // checkpointed.
  std::vector<std::uint32_t> chunk_disc;
  // Wall contacts (walls are few; discs within the skin of each wall).
  WallContacts walls;
  std::vector<std::int64_t> wall_disc_id;
  // Positions at the last build, for the half-skin rebuild test.
  std::vector<double> x_ref, y_ref;
  std::vector<double> wall_ax_ref, wall_ay_ref, wall_bx_ref, wall_by_ref;
  std::uint64_t builds = 0;
  bool valid = false;

  std::size_t size() const { return first.size(); }

  // Calls f(name, vector&) for every array of the list (for checkpoints).
  template <class F>
  void for_each_array(F&& f) {
    f("first", first); f("second", second); f("xi", xi); f("gamma_n", gamma_n);
    f("id_first", id_first); f("id_second", id_second); f("chunk_start", chunk_start);
    f("walls.wall", walls.wall); f("walls.disc", walls.disc); f("walls.xi", walls.xi);
    f("walls.gamma_n", walls.gamma_n); f("walls.mass", walls.mass); f("walls.touching", walls.touching);
    f("walls.at_limit", walls.at_limit); f("wall_disc_id", wall_disc_id);
    f("x_ref", x_ref); f("y_ref", y_ref);
    f("wall_ax_ref", wall_ax_ref); f("wall_ay_ref", wall_ay_ref);
    f("wall_bx_ref", wall_bx_ref); f("wall_by_ref", wall_by_ref);
  }
};

struct BuildStats {
  double max_overlap_ratio = 0;  // largest overlap divided by the smaller radius
  std::uint32_t worst_a = 0, worst_b = 0;
  bool finite = true;
};

// Re-orders discs in cell order (if sort is set), rebuilds pairs and wall contacts, carries
// history across and records reference positions.
BuildStats build_neighbor_list(NeighborList& list, Discs& discs, Clusters& clusters,
                               const std::vector<Wall>& walls, const ContactLaw& law, double dt, bool sort);

// Largest displacement of a wall end since the last build (infinite if the walls changed).
// The list is rebuilt when this plus the largest disc displacement exceeds half the skin.
double wall_displacement(const NeighborList& list, const std::vector<Wall>& walls);

}  // namespace orogen
