#pragma once
// Eroded flux against the incoming flux v h0 (thesis eq. 6.1) and the flux steady state.
#include <cstdint>
#include <span>
#include <vector>

namespace orogen {

struct FluxBalance {
  std::vector<double> flux_out;    // eroded area per time over (t_{k-1}, t_k]; NaN at k = 0
  std::vector<double> mean_out;    // eroded area over the last `window` intervals / their time; NaN before
  std::vector<double> ratio;       // mean_out / flux_in
  std::int64_t steady_output = -1; // first output whose ratio reaches the fraction; -1: none yet
};

// eroded_area[k]: area eroded between output k-1 and k (k = 0: before output 0, ignored).
// The steady-state rule: the first output k >= window at which the eroded flux averaged over
// the last `window` output intervals reaches `fraction` of flux_in.
FluxBalance flux_balance(std::span<const double> time, std::span<const double> eroded_area, double flux_in,
                         int window, double fraction);

}  // namespace orogen
