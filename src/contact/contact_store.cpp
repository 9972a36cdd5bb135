#include "contact/contact_store.hpp"

namespace orogen {

WallContactStats wall_contact_stats(const ContactStore& store, std::size_t wall) {
  WallContactStats s;
  const auto& wc = store.walls;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    if (wc.wall[k] != wall || !wc.touching[k]) continue;
    ++s.touching;
    s.at_limit += wc.at_limit[k];
  }
  return s;
}

}  // namespace orogen
