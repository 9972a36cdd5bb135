#include "contact/pair_forces.hpp"

#include "util/parallel.hpp"

#include <omp.h>

#include <algorithm>

namespace orogen {
namespace {

inline bool pair_force(const NeighborList& L, const Discs& d, const ContactLaw& law, double dt,
                       std::size_t p, double& xi, PairForce& f) {
  const auto i = L.first[p], j = L.second[p];
  return contact_force(d.x[j] - d.x[i], d.y[j] - d.y[i], d.radius[i], d.radius[j], d.vx[j] - d.vx[i],
                       d.vy[j] - d.vy[i], d.omega[i], d.omega[j], law.kn, law.ks, law.mu, L.gamma_n[p],
                       L.gamma_s[p], dt, xi, f);
}

void scatter_serial(NeighborList& L, Discs& d, const ContactLaw& law, double dt) {
  const std::size_t np = L.size();
  for (std::size_t p = 0; p < np; ++p) {
    PairForce f;
    if (!pair_force(L, d, law, dt, p, L.xi[p], f)) continue;
    const auto i = L.first[p], j = L.second[p];
    d.fx[i] -= f.fx; d.fy[i] -= f.fy; d.torque[i] += -d.radius[i] * f.ft;
    d.fx[j] += f.fx; d.fy[j] += f.fy; d.torque[j] += -d.radius[j] * f.ft;
  }
}

void pairs_then_gather(NeighborList& L, Discs& d, const ContactLaw& law, double dt, PairScratch& s) {
  const auto np = static_cast<std::ptrdiff_t>(L.size());
  s.fx.resize(L.size()); s.fy.resize(L.size()); s.ft.resize(L.size()); s.touching.resize(L.size());
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < np; ++p) {
      PairForce f;
      s.touching[p] = pair_force(L, d, law, dt, static_cast<std::size_t>(p), L.xi[p], f);
      s.fx[p] = f.fx; s.fy[p] = f.fy; s.ft[p] = f.ft;
    }
    const auto n = static_cast<std::ptrdiff_t>(d.size());
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      double fx = 0, fy = 0, tq = 0;
      const double r = d.radius[i];
      for (auto e = L.disc_start[i]; e < L.disc_start[i + 1]; ++e) {
        const auto entry = L.disc_entries[e];
        const auto p = entry >> 1;
        if (!s.touching[p]) continue;
        if (entry & 1u) { fx += s.fx[p]; fy += s.fy[p]; }
        else { fx -= s.fx[p]; fy -= s.fy[p]; }
        tq += -r * s.ft[p];
      }
      d.fx[i] = fx; d.fy[i] = fy; d.torque[i] = tq;
    }
  }
}

}  // namespace

void compute_pair_forces(NeighborList& L, Discs& d, const ContactLaw& law, double dt, PairScratch& s) {
  if (omp_get_max_threads() == 1 || static_cast<std::ptrdiff_t>(L.size()) < kMinParallelItems) {
    std::fill(d.fx.begin(), d.fx.end(), 0.0);
    std::fill(d.fy.begin(), d.fy.end(), 0.0);
    std::fill(d.torque.begin(), d.torque.end(), 0.0);
    scatter_serial(L, d, law, dt);
  } else {
    pairs_then_gather(L, d, law, dt, s);
  }
}

}  // namespace orogen
