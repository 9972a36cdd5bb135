#include "boundary/wall_forces.hpp"

#include <utility>

#include "boundary/wall_contact_law.hpp"
#include "contact/normal_laws.hpp"

namespace orogen {
namespace {

// Wall contacts [begin, end): force, history and flags of each, added onto its disc.
template <class Normal>
void contact_range(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                   double dt, DiscForce* forces, std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) {
    const auto i = wc.disc[k];
    const double r = d.radius[i];
    const WallContactForce c = wall_contact_force<Normal>(walls[wc.wall[k]], d.x[i], d.y[i], d.vx[i], d.vy[i],
                                                          d.omega[i], r, wc.gamma_n[k], wc.mass[k], wc.xi[k], law, dt);
    wc.touching[k] = c.touching ? 1 : 0;
    wc.at_limit[k] = c.at_limit ? 1 : 0;
    wc.xi[k] = c.xi;
    if (!c.touching) continue;
    const double tx = -c.ny, ty = c.nx;
    forces[i].fx += c.fn * c.nx + c.ft * tx;
    forces[i].fy += c.fn * c.ny + c.ft * ty;
    forces[i].torque += -r * c.ft;
  }
}

}  // namespace

void wall_forces_share(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, DiscForce* forces, const ThreadSplit& split, std::size_t t) {
  // The first contact at or after (wall w, disc i): contacts are in wall, then disc order.
  auto first_at = [&](std::size_t w, std::ptrdiff_t i) {
    std::size_t lo = 0, hi = wc.size();
    const std::pair<std::size_t, std::ptrdiff_t> key{w, i};
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (std::pair<std::size_t, std::ptrdiff_t>{wc.wall[mid], wc.disc[mid]} < key) lo = mid + 1; else hi = mid;
    }
    return lo;
  };
  // The contacts of thread t's own discs, wall by wall: every disc still adds its wall forces
  // in wall order, whatever the number of threads.
  with_normal_law(law.normal_force, [&](auto normal) {
    for (std::size_t w = 0; w < walls.size(); ++w)
      contact_range<decltype(normal)>(wc, d, walls, law, dt, forces, first_at(w, split.disc[t]),
                                      first_at(w, split.disc[t + 1]));
  });
}

}  // namespace orogen
