#include "contact/thread_split.hpp"

#include <omp.h>

#include <algorithm>

#include "util/parallel.hpp"

namespace orogen {

int step_threads(std::size_t discs) {
  return static_cast<std::ptrdiff_t>(discs) >= min_parallel_items() ? omp_get_max_threads() : 1;
}

ThreadSplit split_threads(const NeighborList& L, const Discs& d, const Clusters& c, int threads) {
  ThreadSplit s;
  const auto n = static_cast<std::ptrdiff_t>(d.size());
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  const auto pairs = chunks > 0 ? static_cast<std::ptrdiff_t>(L.chunk_start.back()) : 0;
  const bool hint = chunks > 0 && L.chunk_disc.size() == static_cast<std::size_t>(chunks) + 1;
  // A body's place in the disc order is its lowest member index (bodies are kept in that
  // order by the sort; between sorts the cut below is still valid, only less tidy).
  auto first_disc = [&](std::ptrdiff_t k) {
    std::ptrdiff_t lo = n;
    for (const auto i : c.members[static_cast<std::size_t>(k)])
      if (i >= 0) lo = std::min<std::ptrdiff_t>(lo, i);
    return lo;
  };
  const auto nc = static_cast<std::ptrdiff_t>(c.size());
  for (int t = 0; t <= threads; ++t) {
    std::ptrdiff_t k = chunks > 0 ? chunks : 0;
    if (t < threads && chunks > 0) {
      const auto target = static_cast<std::uint32_t>(pairs * t / threads);
      k = std::lower_bound(L.chunk_start.begin(), L.chunk_start.end() - 1, target) - L.chunk_start.begin();
    }
    if (t == 0) k = 0;
    std::ptrdiff_t i = hint ? std::min<std::ptrdiff_t>(L.chunk_disc[static_cast<std::size_t>(k)], n) : n * t / threads;
    if (t == 0) i = 0;
    if (t == threads) i = n;
    std::ptrdiff_t b = 0, hi = nc;  // first body whose discs start at i or later
    while (b < hi) {
      const std::ptrdiff_t mid = (b + hi) / 2;
      if (first_disc(mid) < i) b = mid + 1; else hi = mid;
    }
    if (t == threads) b = nc;
    // Boundaries never go back: each thread's share is a range of its own.
    if (t > 0) {
      k = std::max(k, s.chunk.back());
      i = std::max(i, s.disc.back());
      b = std::max(b, s.body.back());
    }
    s.chunk.push_back(k);
    s.disc.push_back(i);
    s.body.push_back(b);
  }
  return s;
}

}  // namespace orogen
