#pragma once
// The registered normal-force laws: the one place where a new law is added (docs/architecture.md,
// "Adding a contact law"). ContactLaw::normal_force is an index into this list, the key
// contact.normal_force takes the names, and every loop that applies the law (pairs, walls, the
// analyses) is compiled once per law and picks its instance once per call, outside its loops.
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "contact/normal_hertz.hpp"
#include "contact/normal_linear.hpp"

namespace orogen {

// ---- Registration: add the new law's type here (its header above). ----
using NormalLaws = std::tuple<LinearNormal, LinearPullNormal, HertzNormal>;
// ------------------------------------------------------------------------

constexpr std::size_t kNormalLawCount = std::tuple_size_v<NormalLaws>;

namespace detail {
template <class F, std::size_t... I>
void with_normal_law(std::size_t index, F& f, std::index_sequence<I...>) {
  static_cast<void>(((index == I ? (f(std::tuple_element_t<I, NormalLaws>{}), true) : false) || ...));
}
}  // namespace detail

// Calls f(Law{}) with the law of the given index (an object of the law's type, only for its type).
template <class F>
void with_normal_law(std::size_t index, F&& f) {
  detail::with_normal_law(index, f, std::make_index_sequence<kNormalLawCount>{});
}

// The laws' names in list order, and the index of a name (kNormalLawCount when none has it).
inline std::vector<std::string> normal_law_names() {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < kNormalLawCount; ++k) with_normal_law(k, [&](auto law) { names.emplace_back(law.name); });
  return names;
}
inline std::size_t normal_law_index(std::string_view name) {
  std::size_t found = kNormalLawCount;
  for (std::size_t k = 0; k < kNormalLawCount; ++k)
    with_normal_law(k, [&](auto law) { if (name == law.name) found = k; });
  return found;
}

}  // namespace orogen
