#pragma once
// Seeded random numbers with the same results on every platform: std::mt19937_64's output is
// fixed by the standard, but the standard distributions are not, so uniforms are made here.
#include <cstdint>
#include <random>

namespace orogen {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace orogen
