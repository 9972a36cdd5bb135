#include "contact/thread_split.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdint>

#include "util/parallel.hpp"

namespace orogen {

int step_threads(std::size_t discs) {
  return static_cast<std::ptrdiff_t>(discs) >= min_parallel_items() ? omp_get_max_threads() : 1;
}

ThreadSplit split_threads(const NeighborList& L, const Discs& d, const Clusters& c, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(d.size());
  const auto nc = static_cast<std::ptrdiff_t>(c.size());
  const auto chunks = std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1);
  const std::int64_t pairs = chunks > 0 ? L.chunk_start.back() : 0;
  const bool hint = chunks > 0 && L.chunk_disc.size() == static_cast<std::size_t>(chunks) + 1;
  // A body's place in the disc order is its lowest member index (the sort keeps bodies in
  // that order; between sorts the cut is still valid, only less tidy).
  auto first_disc = [&](std::ptrdiff_t k) {
    std::ptrdiff_t lo = n;
    for (const auto i : c.members[static_cast<std::size_t>(k)])
      if (i >= 0) lo = std::min<std::ptrdiff_t>(lo, i);
    return lo;
  };
  ThreadSplit s{{0}, {0}, {0}};
  for (int t = 1; t < threads; ++t) {
    const std::int64_t target = pairs * t / threads;
    const std::ptrdiff_t k =
        std::lower_bound(L.chunk_start.begin(), L.chunk_start.begin() + chunks, target) - L.chunk_start.begin();
    const std::ptrdiff_t i = hint ? std::min<std::ptrdiff_t>(L.chunk_disc[static_cast<std::size_t>(k)], n) : n * t / threads;
    std::ptrdiff_t b = 0, hi = nc;  // the first body whose discs start at i or later
    while (b < hi) {
      const std::ptrdiff_t mid = (b + hi) / 2;
      if (first_disc(mid) < i) b = mid + 1; else hi = mid;
    }
    // Boundaries never go back, so every thread's share is a range of its own.
    s.chunk.push_back(std::max(k, s.chunk.back()));
    s.disc.push_back(std::max(i, s.disc.back()));
    s.body.push_back(std::max(b, s.body.back()));
  }
  s.chunk.push_back(chunks);
  s.disc.push_back(n);
  s.body.push_back(nc);
  return s;
}

}  // namespace orogen
