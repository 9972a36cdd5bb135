#pragma once
// A select between two doubles that GCC 12 vectorises. Written as `pick ? a : old` with `old`
// the element the result is stored back to, a select becomes a masked store, and the loop is
// then not vectorised at all ("no vectype" for the masked load/store of a double under AVX2);
// the same choice through the bits stays a select. Bit for bit the `?:` result.
#include <bit>
#include <cstdint>

namespace orogen {

inline double select(bool pick, double a, double b) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(pick);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

}  // namespace orogen
