#include "contact/chunk_hints.hpp"

namespace orogen {
namespace {

// A chunk whose pairs touch this often at a build is dense (NeighborList::chunk_dense). The
// benchmark pile (skin 0.1 d, 74% of the pairs touching) runs faster with every pair through
// the kernel, 1.06x at 5k discs and 1.5x at 80k; a wedge (skin 0.3 d, half of them) 1.14x
// slower (measured with both kernels at several shares, docs/performance.md).
constexpr double kDenseShare = 0.65;

}  // namespace

void set_chunk_hints(NeighborList& L, const PairSearchResult& search, const CellBins& bins, bool sorted) {
  const std::size_t chunks = search.touching.size();
  L.chunk_dense.clear();
  for (std::size_t k = 0; k < chunks; ++k) {
    const auto pairs = static_cast<double>(L.chunk_start[k + 1] - L.chunk_start[k]);
    L.chunk_dense.push_back(static_cast<double>(search.touching[k]) >= kDenseShare * pairs);
  }
  if (sorted) {  // discs are in cell order: chunk k's stripes hold discs from its first cell on
    const auto nv = static_cast<std::size_t>(bins.grid.nv());
    const auto stripes = static_cast<std::size_t>(search.stripes_per_chunk);
    L.chunk_disc.resize(chunks + 1);
    for (std::size_t k = 0; k < chunks; ++k) L.chunk_disc[k] = bins.cell_start[k * stripes * nv];
    L.chunk_disc.back() = static_cast<std::uint32_t>(bins.order.size());
  } else if (L.chunk_disc.size() != chunks + 1) {
    L.chunk_disc.clear();  // the grid changed since the last sort: no hint until the next
  }
}

}  // namespace orogen
