#pragma once
// Below this many items a loop runs on one thread: the cost of waking a thread team is then
// larger than the work. Results do not depend on it (every parallel loop is order-free or
// sums in a fixed order).
#include <cstddef>

namespace orogen {
constexpr std::ptrdiff_t kMinParallelItems = 4096;
}  // namespace orogen
