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

ThreadSplit split_share(const ThreadSplit& cut, std::size_t r, int threads, const NeighborList& L) {
  const std::ptrdiff_t c0 = cut.chunk[r], c1 = cut.chunk[r + 1];
  const std::int64_t p0 = c0 < c1 ? L.chunk_start[static_cast<std::size_t>(c0)] : 0;
  const std::int64_t p1 = c0 < c1 ? L.chunk_start[static_cast<std::size_t>(c1)] : 0;
  const auto part = [threads](std::ptrdiff_t lo, std::ptrdiff_t hi, int t) { return lo + (hi - lo) * t / threads; };
  ThreadSplit s{{c0}, {cut.disc[r]}, {cut.body[r]}};
  for (int t = 1; t <= threads; ++t) {
    std::ptrdiff_t k = c1;
    if (t < threads) {
      const std::int64_t target = p0 + (p1 - p0) * t / threads;
      k = std::lower_bound(L.chunk_start.begin() + c0, L.chunk_start.begin() + c1, target) - L.chunk_start.begin();
      k = std::max(k, s.chunk.back());
    }
    s.chunk.push_back(k);
    s.disc.push_back(part(cut.disc[r], cut.disc[r + 1], t));
    s.body.push_back(part(cut.body[r], cut.body[r + 1], t));
  }
  return s;
}

}  // namespace orogen
