#pragma once
// Two 32-bit numbers (a pair's disc indices, or its discs' stable ids) in one double, bit for
// bit: the transport between ranks carries doubles. The first goes in the high half and stays
// below 2^31, so the bits are never a NaN or an infinity, which a copy might alter; a copy
// keeps all others.
#include <bit>
#include <cstdint>

namespace orogen {

inline constexpr std::uint64_t kPackedPairLimit = std::uint64_t{1} << 31;

inline double pack_pair(std::uint32_t first, std::uint32_t second) {
  return std::bit_cast<double>(std::uint64_t{first} << 32 | second);
}
inline void unpack_pair(double packed, std::uint32_t& first, std::uint32_t& second) {
  const auto bits = std::bit_cast<std::uint64_t>(packed);
  first = static_cast<std::uint32_t>(bits >> 32);
  second = static_cast<std::uint32_t>(bits);
}

}  // namespace orogen
