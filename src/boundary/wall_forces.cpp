#include "boundary/wall_forces.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "boundary/wall_contact_law.hpp"
#include "contact/normal_laws.hpp"
#include "util/select.hpp"

namespace orogen {
namespace {

constexpr std::size_t kWallBlock = 64;

// Contacts [begin, end) of one wall: force, history and flags of each, added onto its disc.
// A block at a time, the law in vector lanes (every contact through it, apart ones masked to
// zero), then the sums in contact order: the contacts of one wall name each disc once, and
// adding a zero changes no sum (the sums start at +0.0 and never become -0.0), so the sums
// are bitwise those of adding the touching contacts alone. A weakening wall (kWeakens) takes its
// coefficient at each disc from the disc's slip at the step's start and adds the slip on it to
// the disc's slip (a thread's own discs: no race).
template <class Normal, WallFriction kFriction, bool kWeakens>
void contact_range(WallContacts& wc, const Discs& d, const WallFrame& frame, const ContactLaw& law, double dt,
                   const WallSlip& slip, DiscForce* __restrict forces, std::size_t begin, std::size_t end) {
  alignas(64) double fx[kWallBlock], fy[kWallBlock], torque[kWallBlock], slipped[kWallBlock];
  const double *x = d.x.data(), *y = d.y.data(), *vx = d.vx.data(), *vy = d.vy.data(), *omega = d.omega.data(),
               *radius = d.radius.data();
  const double kn = law.kn, ks = law.ks, damping_ratio = law.tangential_damping_ratio;
  for (std::size_t b0 = begin; b0 < end; b0 += kWallBlock) {
    const auto count = static_cast<std::ptrdiff_t>(std::min(kWallBlock, end - b0));
    const std::uint32_t* __restrict disc = wc.disc.data() + b0;
    const double* __restrict gamma_n = wc.gamma_n.data() + b0;
    const double* __restrict traction_mass = wc.traction_mass.data() + b0;
    double* __restrict xi = wc.xi.data() + b0;
    std::uint8_t* __restrict touching = wc.touching.data() + b0;
    std::uint8_t* __restrict at_limit = wc.at_limit.data() + b0;
#pragma omp simd
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const auto i = disc[k];
      const double mu = kWeakens ? wall_mu(frame, slip.at_start[i]) : frame.mu;
      const WallContactForce c = wall_contact_lane<Normal, kFriction>(
          frame, x[i], y[i], vx[i], vy[i], omega[i], radius[i], gamma_n[k], traction_mass[k], xi[k], mu, kn, ks,
          damping_ratio, dt);
      touching[k] = c.touching;
      at_limit[k] = c.at_limit;
      xi[k] = c.xi;
      const double tx = -c.ny, ty = c.nx;
      fx[k] = select(c.touching, c.fn * c.nx + c.ft * tx, 0.0);
      fy[k] = select(c.touching, c.fn * c.ny + c.ft * ty, 0.0);
      torque[k] = select(c.touching, -radius[i] * c.ft, 0.0);
      if constexpr (kWeakens) slipped[k] = c.slip;
    }
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const auto i = disc[k];
      forces[i].fx += fx[k];
      forces[i].fy += fy[k];
      forces[i].torque += torque[k];
      if constexpr (kWeakens) slip.slip[i] += slipped[k];
    }
  }
}

}  // namespace

void wall_forces_share(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, const WallSlip& slip, DiscForce* forces, const ThreadSplit& split, std::size_t t) {
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
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const std::size_t begin = first_at(w, split.disc[t]), end = first_at(w, split.disc[t + 1]);
      if (begin == end) continue;
      const WallFrame frame = wall_frame(walls[w]);
      with_wall_friction(walls[w].friction, [&](auto kind) {
        if (walls[w].weakens && slip.slip != nullptr)
          contact_range<decltype(normal), decltype(kind)::value, true>(wc, d, frame, law, dt, slip, forces, begin, end);
        else
          contact_range<decltype(normal), decltype(kind)::value, false>(wc, d, frame, law, dt, slip, forces, begin,
                                                                        end);
      });
    }
  });
}

}  // namespace orogen
