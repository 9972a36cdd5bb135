#include "integrate/integrator.hpp"

#include <cstddef>
#include "util/parallel.hpp"

namespace orogen {

void gather_cluster_forces(Clusters& c, const Discs& d) {
  const auto n = static_cast<std::ptrdiff_t>(c.size());
#pragma omp parallel for schedule(static) if (n > kMinParallelItems)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double fx = 0, fy = 0, tq = 0;
    for (const auto i : c.members[k]) {  // ascending disc-id order: a fixed summation order
      if (i < 0) break;
      const double rx = d.x[i] - c.x[k], ry = d.y[i] - c.y[k];
      fx += d.fx[i];
      fy += d.fy[i];
      tq += d.torque[i] + rx * d.fy[i] - ry * d.fx[i];
    }
    c.fx[k] = fx; c.fy[k] = fy; c.torque[k] = tq;
  }
}

void integrate(Discs& d, Clusters& c, const BodyForce& g, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(d.size());
  const double damp = 1.0 - g.drag * dt;
#pragma omp parallel for schedule(static) if (n > kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (d.cluster[i] >= 0) continue;
    if (d.motion[i] == static_cast<std::uint8_t>(Motion::Dynamic)) {
      d.vx[i] = damp * d.vx[i] + (d.fx[i] * d.inv_mass[i] + g.gx) * dt;
      d.vy[i] = damp * d.vy[i] + (d.fy[i] * d.inv_mass[i] + g.gy) * dt;
      d.omega[i] = damp * d.omega[i] + d.torque[i] * d.inv_inertia[i] * dt;
    }
    d.x[i] += d.vx[i] * dt;
    d.y[i] += d.vy[i] * dt;
    d.theta[i] += d.omega[i] * dt;
  }
  if (c.size() == 0) return;
  gather_cluster_forces(c, d);
  const auto nc = static_cast<std::ptrdiff_t>(c.size());
#pragma omp parallel for schedule(static) if (nc > kMinParallelItems)
  for (std::ptrdiff_t k = 0; k < nc; ++k) {
    if (c.motion[k] == static_cast<std::uint8_t>(Motion::Dynamic)) {
      c.vx[k] = damp * c.vx[k] + (c.fx[k] * c.inv_mass[k] + g.gx) * dt;
      c.vy[k] = damp * c.vy[k] + (c.fy[k] * c.inv_mass[k] + g.gy) * dt;
      c.omega[k] = damp * c.omega[k] + c.torque[k] * c.inv_inertia[k] * dt;
    }
    c.x[k] += c.vx[k] * dt;
    c.y[k] += c.vy[k] * dt;
    c.theta[k] += c.omega[k] * dt;
  }
  update_cluster_discs(c, d);
}

}  // namespace orogen
