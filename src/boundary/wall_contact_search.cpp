#include "boundary/wall_contact_search.hpp"

#include <cstddef>
#include <cstdint>

#include "util/parallel.hpp"

namespace orogen {

void search_wall_contacts(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, double skin) {
  wc.clear();
  const std::size_t n = d.size();
  std::vector<std::uint8_t> near(n);
  // The distance test in parallel, the list in order.
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (!walls[w].enabled) continue;
    const Segment wall = segment(walls[w]);
    const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count > min_parallel_items())
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      double cx, cy;
      const double dist2 = closest_point(wall, d.x[i], d.y[i], cx, cy);
      const double reach = d.radius[i] + skin;
      near[i] = d.is_dynamic(i) && dist2 < reach * reach;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!near[i]) continue;
      wc.wall.push_back(static_cast<std::uint32_t>(w));
      wc.disc.push_back(static_cast<std::uint32_t>(i));
      wc.disc_id.push_back(d.id[i]);
    }
  }
  wc.touching.assign(wc.size(), 0);
  wc.at_limit.assign(wc.size(), 0);
}

}  // namespace orogen
