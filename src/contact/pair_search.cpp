#include "contact/pair_search.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "util/parallel.hpp"

namespace orogen {

PairChunks pair_chunks(const CellGrid& g) {
  // Chunks of whole stripes, at most kMaxPairChunks of them: a number fixed by the geometry
  // alone, so that the order of the force sums never depends on the thread count.
  PairChunks chunks;
  chunks.stripes_per_chunk = (g.nu() + kMaxPairChunks - 1) / kMaxPairChunks;
  chunks.count = (g.nu() + chunks.stripes_per_chunk - 1) / chunks.stripes_per_chunk;
  return chunks;
}

std::vector<ChunkPairs> search_pair_chunks(const CellBins& bins, const Discs& d, double skin, std::int64_t begin,
                                           std::int64_t end) {
  const CellGrid& g = bins.grid;
  const auto& order = bins.order;
  const auto& cell_start = bins.cell_start;
  const std::int64_t stripes_per_chunk = pair_chunks(g).stripes_per_chunk;
  // Each cell against itself and its four forward neighbours in traversal order: (u, v+1) in
  // its own stripe and (u+1, v-1), (u+1, v), (u+1, v+1) in the next. Chunks are searched in
  // parallel into lists of their own.
  //
  // A chunk's pairs that touch now, then the rest, each part in search order: the force loop
  // runs the first part through the kernel untested and tests the second, and either test
  // then mostly goes one way (a test that goes either way at random costs a mispredicted
  // branch for one pair in four; docs/performance.md).
  std::vector<ChunkPairs> found(static_cast<std::size_t>(std::max<std::int64_t>(end - begin, 0)));
  const std::int64_t neighbours[4][2] = {{0, 1}, {1, -1}, {1, 0}, {1, 1}};  // (du, dv)
#pragma omp parallel for schedule(dynamic, 1) if (static_cast<std::ptrdiff_t>(d.size()) > min_parallel_items())
  for (std::int64_t k = begin; k < end; ++k) {
    ChunkPairs& out = found[static_cast<std::size_t>(k - begin)];
    auto consider = [&](std::uint32_t a, std::uint32_t b) {
      if (d.cluster_id[a] >= 0 && d.cluster_id[a] == d.cluster_id[b]) return;
      if (!d.is_dynamic(a) && !d.is_dynamic(b)) return;
      const double dx = d.x[b] - d.x[a], dy = d.y[b] - d.y[a];
      const double reach = d.radius[a] + d.radius[b] + skin;
      const double dist2 = dx * dx + dy * dy;
      if (dist2 >= reach * reach) return;
      const double overlap = d.radius[a] + d.radius[b] - std::sqrt(dist2);
      const double ratio = overlap / std::min(d.radius[a], d.radius[b]);
      if (ratio > out.stats.max_overlap_ratio) {
        out.stats.max_overlap_ratio = ratio; out.stats.worst_a = a; out.stats.worst_b = b;
      }
      if (d.id[a] > d.id[b]) std::swap(a, b);
      // The kernel's own test (contact/contact_block.hpp), so "touching" means the same here.
      const double rsum = d.radius[a] + d.radius[b];
      const bool touching = dist2 < rsum * rsum;
      (touching ? out.first : out.apart_first).push_back(a);
      (touching ? out.second : out.apart_second).push_back(b);
    };
    const std::int64_t u_end = std::min(g.nu(), (k + 1) * stripes_per_chunk);
    for (std::int64_t u = k * stripes_per_chunk; u < u_end; ++u) {
      for (std::int64_t v = 0; v < g.nv(); ++v) {
        const auto cell = static_cast<std::size_t>(u * g.nv() + v);
        for (auto s = cell_start[cell]; s < cell_start[cell + 1]; ++s) {
          const auto a = order[s];
          for (auto t = s + 1; t < cell_start[cell + 1]; ++t) consider(a, order[t]);
          for (const auto& nb : neighbours) {
            const std::int64_t ou = u + nb[0], ov = v + nb[1];
            if (ov < 0 || ov >= g.nv() || ou >= g.nu()) continue;
            const auto other = static_cast<std::size_t>(ou * g.nv() + ov);
            for (auto t = cell_start[other]; t < cell_start[other + 1]; ++t) consider(a, order[t]);
          }
        }
      }
    }
  }
  return found;
}

std::vector<std::int64_t> chunk_ranges_by_discs(const CellBins& bins, int shares) {
  const CellGrid& g = bins.grid;
  const PairChunks chunks = pair_chunks(g);
  const auto discs_before = [&](std::int64_t k) {  // discs in the stripes of chunks [0, k)
    const std::int64_t stripe = std::min(g.nu(), k * chunks.stripes_per_chunk);
    return static_cast<std::uint64_t>(bins.cell_start[static_cast<std::size_t>(stripe * g.nv())]);
  };
  const std::uint64_t total = discs_before(chunks.count);
  std::vector<std::int64_t> bounds(static_cast<std::size_t>(shares) + 1, chunks.count);
  bounds[0] = 0;
  std::int64_t k = 0;
  for (int r = 1; r < shares; ++r) {  // the first chunk with at least r / shares of the discs before it
    while (k < chunks.count && discs_before(k) * static_cast<std::uint64_t>(shares) < r * total) ++k;
    bounds[static_cast<std::size_t>(r)] = k;
  }
  return bounds;
}

PairSearchResult join_pair_chunks(NeighborList& L, const std::vector<ChunkPairs>& found,
                                  std::int64_t stripes_per_chunk) {
  PairSearchResult result;
  result.stripes_per_chunk = stripes_per_chunk;
  L.first.clear(); L.second.clear();
  L.chunk_start.clear();
  for (const auto& f : found) {
    L.chunk_start.push_back(static_cast<std::uint32_t>(L.first.size()));
    L.first.insert(L.first.end(), f.first.begin(), f.first.end());
    L.second.insert(L.second.end(), f.second.begin(), f.second.end());
    L.first.insert(L.first.end(), f.apart_first.begin(), f.apart_first.end());
    L.second.insert(L.second.end(), f.apart_second.begin(), f.apart_second.end());
    result.touching.push_back(f.first.size());
    if (f.stats.max_overlap_ratio > result.stats.max_overlap_ratio) {
      result.stats.max_overlap_ratio = f.stats.max_overlap_ratio;
      result.stats.worst_a = f.stats.worst_a;
      result.stats.worst_b = f.stats.worst_b;
    }
  }
  L.chunk_start.push_back(static_cast<std::uint32_t>(L.first.size()));
  return result;
}

PairSearchResult search_pairs(NeighborList& L, const CellBins& bins, const Discs& d) {
  const PairChunks chunks = pair_chunks(bins.grid);
  return join_pair_chunks(L, search_pair_chunks(bins, d, L.skin, 0, chunks.count), chunks.stripes_per_chunk);
}

}  // namespace orogen
