#include "contact/chunk_hints.hpp"

namespace orogen {

void set_chunk_hints(NeighborList& L, const PairSearchResult& search, const CellBins& bins) {
  const std::size_t chunks = search.touching.size();
  L.chunk_touching.assign(search.touching.begin(), search.touching.end());
  // Chunk k's stripes hold the discs from its first cell on: the first disc index of each chunk
  // in cell order. Sorted, the discs are in that order; unsorted, still near it (the order of
  // the last sort, by stripes along the same axis), so the count is the best cut there too.
  const auto nv = static_cast<std::size_t>(bins.grid.nv());
  const auto stripes = static_cast<std::size_t>(search.stripes_per_chunk);
  L.chunk_disc.resize(chunks + 1);
  for (std::size_t k = 0; k < chunks; ++k) L.chunk_disc[k] = bins.cell_start[k * stripes * nv];
  L.chunk_disc.back() = static_cast<std::uint32_t>(bins.order.size());
}

}  // namespace orogen
