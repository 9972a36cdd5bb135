#pragma once
// Helpers for structure-of-arrays types that list their arrays with for_each_array.
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

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

// Re-orders every array of the SoA: element k becomes the old element order[k].
template <class SoA>
void permute_arrays(SoA& soa, std::span<const std::uint32_t> order) {
  soa.for_each_array([&](std::string_view, auto& v) {
    if (v.empty()) return;  // an optional array the SoA does not use (Discs::optional_array)
    std::remove_reference_t<decltype(v)> out(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
    v.swap(out);
  });
}

}  // namespace orogen
