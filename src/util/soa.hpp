#pragma once
// Helpers for structure-of-arrays types that list their arrays with for_each_array.
#include <cstdint>
#include <span>
#include <string_view>

namespace orogen {

// Keeps the elements whose keep flag is set, in order, in every array of the SoA.
template <class SoA>
void compact_arrays(SoA& soa, std::span<const std::uint8_t> keep) {
  soa.for_each_array([&](std::string_view, auto& v) {
    std::size_t w = 0;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (keep[k]) v[w++] = v[k];
    v.resize(w);
  });
}

}  // namespace orogen
