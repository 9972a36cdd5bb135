#pragma once
// Contact detection (MODEL §5): a uniform cell grid sorts discs into cells, a half Verlet
// list of candidate pairs closer than the sum of their radii plus a skin is built from
// neighbouring cells, and the list is rebuilt only when some disc has moved more than half
// the skin. The list holds candidates only: the state of each contact (tangential history,
// dashpot, flags) is the contact store's (contact/contact_store.hpp), which a build carries
// over by the discs' stable ids. A build runs the single-job functions of pair_search,
// cell_grid, chunk_hints, contact_damping, store_carry and boundary/wall_contact_search in
// order (world/contact_rebuild.cpp).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace orogen {

struct NeighborList {
  double skin = 0.1;
  // Pairs (first, second) by disc index; the first always has the lower stable id, so the
  // sign of the history xi (measured along n rotated +90 degrees, n from first to second)
  // means the same thing after every rebuild.
  std::vector<std::uint32_t> first, second;
  // The pairs come in stripes of cells across the domain's long side; chunk k is pairs
  // [chunk_start[k], chunk_start[k+1]), whole stripes. A pair joins discs of one stripe or of
  // two neighbouring ones, so chunks two apart never share a disc: the force loop runs the even
  // chunks in parallel, then the odd ones, each disc summing its pairs in the same order
  // whatever the number of threads.
  std::vector<std::uint32_t> chunk_start;
  // A build lists each chunk's pairs that touch first, then those apart. chunk_touching[k] is
  // how many of chunk k's pairs touched at the last build: the force loop runs those through
  // its kernel untested and tests the rest (contact/pair_forces.cpp). Only a hint, as
  // chunk_disc: both ways give the same bits, so it is not checkpointed.
  std::vector<std::uint32_t> chunk_touching;
  // The first disc of each chunk's stripes, chunks + 1 entries, from the last build that put
  // the discs in cell order (empty when unknown). Only a hint for cutting the discs between
  // threads where the chunks are cut (ThreadSplit): results never depend on it, so it is not
  // checkpointed.
  std::vector<std::uint32_t> chunk_disc;
  // Positions at the last build, for the half-skin rebuild test (world/reference_positions).
  std::vector<double> x_ref, y_ref;
  std::vector<double> wall_ax_ref, wall_ay_ref, wall_bx_ref, wall_by_ref;
  std::uint64_t builds = 0;
  bool valid = false;

  std::size_t size() const { return first.size(); }
};

// A range [begin, end) of a list's pairs (end past the last: to the end); all of them by
// default. Over ranks, one rank's chunks (docs/domain-decomposition.md).
struct PairRange {
  std::size_t begin = 0, end = std::numeric_limits<std::size_t>::max();
  std::size_t end_in(std::size_t pairs) const { return end < pairs ? end : pairs; }
};

}  // namespace orogen
