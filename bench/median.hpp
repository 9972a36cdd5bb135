#pragma once
// The median of a benchmark's repeated timings (the middle value, or the mean of the two middle
// ones), as the benchmarks report it.
#include <algorithm>
#include <vector>

namespace orogen::bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace orogen::bench
