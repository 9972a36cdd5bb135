#include "world/hold.hpp"

namespace orogen {

std::size_t hold_at_rest(World& w, std::span<const std::uint8_t> flags) {
  std::size_t held = 0;
  w.edit_motion([&](MotionEdit& e) {
    for (std::size_t i = 0; i < w.discs().size(); ++i)
      if (flags[i]) e.body_of(i, Motion::Kinematic);
  });
  for (std::size_t i = 0; i < w.discs().size(); ++i) held += !w.discs().is_dynamic(i);
  return held;
}

}  // namespace orogen
