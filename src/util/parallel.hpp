#pragma once
// Below this many discs (or items) a loop runs on one thread: waking a thread team then costs
// more than it saves, and on a busy machine a spinning team can be many times slower than one
// thread. Results do not depend on it (every parallel loop is order-free or sums in a fixed
// order).
#include <cstddef>

namespace orogen {
constexpr std::ptrdiff_t kMinParallelItems = 16384;
}  // namespace orogen
