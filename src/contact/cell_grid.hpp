#pragma once
// Binning for the pair search: a uniform grid of cells at least one reach wide, numbered
// stripe by stripe across the longer side of the domain, (u, v) with u along the long axis
// (the stripe) and v across it, index u * nv + v. Discs sorted by cell then lie in memory in
// the order the pairs are built, and stripes make the chunks of the force loop (see
// NeighborList::chunk_start).
#include <cstdint>
#include <vector>

#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct CellGrid {
  double x_lo = 0, y_lo = 0, cell = 1;
  std::int64_t nx = 1, ny = 1;
  bool x_long = true;  // u runs along x
  std::int64_t nu() const { return x_long ? nx : ny; }
  std::int64_t nv() const { return x_long ? ny : nx; }
  std::int64_t cell_of(double x, double y) const;
};

// Discs binned into the grid's cells: disc indices in cell order, and where each cell starts.
struct CellBins {
  CellGrid grid;
  std::vector<std::uint32_t> order, cell_start;
};

// A grid over the discs with cells of at least `cell` (grown if a few stray discs far away
// would make too many cells).
CellGrid make_grid(const Discs& discs, double cell);

// Sorts the discs into the grid's cells (counting sort).
CellBins bin_discs(const Discs& discs, const CellGrid& grid);

// Re-orders the disc arrays (and clusters with them) in cell order; the bins then list the
// discs in index order.
void sort_discs_by_cell(CellBins& bins, Discs& discs, Clusters& clusters);

}  // namespace orogen
