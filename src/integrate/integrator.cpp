#include "integrate/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include "util/parallel.hpp"

namespace orogen {

void gather_cluster_forces(Clusters& c, const Discs& d, const DiscForce* f) {
  const auto n = static_cast<std::ptrdiff_t>(c.size());
#pragma omp parallel for schedule(static) if (n > kMinParallelItems)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double fx = 0, fy = 0, tq = 0;
    for (const auto i : c.members[k]) {  // ascending disc-id order: a fixed summation order
      if (i < 0) break;
      const double rx = d.x[i] - c.x[k], ry = d.y[i] - c.y[k];
      fx += f[i].fx;
      fy += f[i].fy;
      tq += f[i].torque + rx * f[i].fy - ry * f[i].fx;
    }
    c.fx[k] = fx; c.fy[k] = fy; c.torque[k] = tq;
  }
}

double integrate(Discs& d, Clusters& c, const DiscForce* force, const BodyForce& g, double dt, const double* x_ref,
                 const double* y_ref) {
  const auto n = static_cast<std::ptrdiff_t>(d.size());
  const double damp = 1.0 - g.drag * dt;
  // Written without branches so that it vectorises. Cluster discs are updated here too, for
  // nothing: update_cluster_discs overwrites them from their bodies below.
  double* __restrict vx = d.vx.data();
  double* __restrict vy = d.vy.data();
  double* __restrict omega = d.omega.data();
  double* __restrict x = d.x.data();
  double* __restrict y = d.y.data();
  double* __restrict theta = d.theta.data();
  const double* __restrict inv_m = d.inv_mass.data();
  const double* __restrict inv_i = d.inv_inertia.data();
  const std::uint8_t* __restrict motion = d.motion.data();
  const std::int32_t* __restrict cluster = d.cluster.data();
  double max2 = 0;
#pragma omp parallel for simd schedule(static) reduction(max : max2) if (n > kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const bool dynamic = motion[i] == static_cast<std::uint8_t>(Motion::Dynamic);
    const double vx_new = damp * vx[i] + (force[i].fx * inv_m[i] + g.gx) * dt;
    const double vy_new = damp * vy[i] + (force[i].fy * inv_m[i] + g.gy) * dt;
    const double w_new = damp * omega[i] + force[i].torque * inv_i[i] * dt;
    vx[i] = dynamic ? vx_new : vx[i];
    vy[i] = dynamic ? vy_new : vy[i];
    omega[i] = dynamic ? w_new : omega[i];
    x[i] += vx[i] * dt;
    y[i] += vy[i] * dt;
    theta[i] += omega[i] * dt;
    const double dx = x[i] - x_ref[i], dy = y[i] - y_ref[i];
    const double m2 = cluster[i] < 0 ? dx * dx + dy * dy : 0.0;  // member discs: measured below
    // Written so that NaN counts as infinitely far: it forces a rebuild, where it is caught.
    max2 = m2 <= max2 ? max2 : (m2 == m2 ? m2 : std::numeric_limits<double>::infinity());
  }
  const double moved = std::sqrt(max2);
  if (c.size() == 0) return moved;
  gather_cluster_forces(c, d, force);
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
  const double members = update_cluster_discs(c, d, x_ref, y_ref);
  return members == members ? std::max(moved, members) : std::numeric_limits<double>::infinity();
}

}  // namespace orogen
