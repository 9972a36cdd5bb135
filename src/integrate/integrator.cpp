#include "integrate/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "util/select.hpp"

namespace orogen {

namespace {

// Sums the member disc forces of bodies [begin, end) onto them: force, and torque about the
// centre of mass; then zeroes the members' sums for the next step (while their lines are in
// cache: a pass of its own to clear them cost 3-4% of a wedge step).
void gather_cluster_forces(Clusters& c, const Discs& d, DiscForce* __restrict f, std::ptrdiff_t begin,
                           std::ptrdiff_t end) {
  const double* __restrict x = d.x.data();
  const double* __restrict y = d.y.data();
  double* __restrict fx_out = c.fx.data();
  double* __restrict fy_out = c.fy.data();
  double* __restrict torque_out = c.torque.data();
  for (std::ptrdiff_t k = begin; k < end; ++k) {
    double fx = 0, fy = 0, tq = 0;
    // Kinematic bodies (the incoming slab, pinned bodies) ignore their forces.
    if (c.motion[k] == static_cast<std::uint8_t>(Motion::Dynamic)) {
      for (const auto i : c.members[k]) {  // ascending disc-id order: a fixed summation order
        if (i < 0) break;
        const double rx = x[i] - c.x[k], ry = y[i] - c.y[k];
        fx += f[i].fx;
        fy += f[i].fy;
        tq += f[i].torque + rx * f[i].fy - ry * f[i].fx;
      }
    }
    for (const auto i : c.members[k]) {
      if (i < 0) break;
      f[i] = {0.0, 0.0, 0.0};
    }
    fx_out[k] = fx; fy_out[k] = fy; torque_out[k] = tq;
  }
}

// Free discs [b0, b1): semi-implicit Euler without branches (selects through the bits,
// util/select.hpp), so that it vectorises (the pointers are restrict parameters here:
// captured into an OpenMP region they lose it); squared displacements into m2. Cluster discs
// in the range keep their values (step_free_discs passes no range holding one: it would
// write them back, racing with the thread that places them). With kAllFreeDynamic
// (a block of dynamic free discs only, the usual case where there are free discs) the selects
// fold away: the same arithmetic, so the same bits, 1.1x faster on the benchmark pile. Each
// disc's force sums are zeroed once used, for the next step.
template <bool kAllFreeDynamic>
void step_free_block(std::ptrdiff_t b0, std::ptrdiff_t b1, double* __restrict vx, double* __restrict vy,
                     double* __restrict omega, double* __restrict x, double* __restrict y, double* __restrict theta,
                     DiscForce* __restrict force, const double* __restrict inv_m,
                     const double* __restrict inv_i, const std::uint8_t* __restrict motion,
                     const std::int32_t* __restrict cluster, const double* __restrict x_ref,
                     const double* __restrict y_ref, double damp, double gx, double gy, double dt,
                     double* __restrict m2) {
  for (std::ptrdiff_t i = b0; i < b1; ++i) {
    const bool free = kAllFreeDynamic || cluster[i] < 0;
    const bool dynamic = kAllFreeDynamic || (free & (motion[i] == static_cast<std::uint8_t>(Motion::Dynamic)));
    const double vx_new = damp * vx[i] + (force[i].fx * inv_m[i] + gx) * dt;
    const double vy_new = damp * vy[i] + (force[i].fy * inv_m[i] + gy) * dt;
    const double w_new = damp * omega[i] + force[i].torque * inv_i[i] * dt;
    force[i] = {0.0, 0.0, 0.0};  // only free discs come here (step_free_discs)
    vx[i] = select(dynamic, vx_new, vx[i]);
    vy[i] = select(dynamic, vy_new, vy[i]);
    omega[i] = select(dynamic, w_new, omega[i]);
    const double x_new = x[i] + vx[i] * dt, y_new = y[i] + vy[i] * dt;
    const double theta_new = theta[i] + omega[i] * dt;
    x[i] = select(free, x_new, x[i]);
    y[i] = select(free, y_new, y[i]);
    theta[i] = select(free, theta_new, theta[i]);
    const double dx = x[i] - x_ref[i], dy = y[i] - y_ref[i];
    m2[i - b0] = select(free, dx * dx + dy * dy, 0.0);  // member discs: measured by their bodies
  }
}

// Free discs [begin, end), a block at a time; the largest displacement of them.
Displacement step_free_discs(std::ptrdiff_t begin, std::ptrdiff_t end, double* vx, double* vy, double* omega,
                             double* x, double* y, double* theta, DiscForce* force, const double* inv_m,
                             const double* inv_i, const std::uint8_t* motion, const std::int32_t* cluster,
                             const double* x_ref, const double* y_ref, double damp, double gx, double gy, double dt) {
  double max2 = 0;
  std::int64_t not_finite = 0;
  // In blocks: the update loop vectorises only without a floating-point max reduction in it
  // (GCC will not reorder a max over doubles), so the displacements go to a small buffer and
  // their max is taken in a second, scalar loop.
  constexpr std::ptrdiff_t kBlock = 256;
  double m2[kBlock];
  for (std::ptrdiff_t b0 = begin; b0 < end; b0 += kBlock) {
    const std::ptrdiff_t b1 = std::min(end, b0 + kBlock);
    int all_free_dynamic = 1, any_member = 0;
    for (std::ptrdiff_t i = b0; i < b1; ++i) {
      all_free_dynamic &= (cluster[i] < 0) & (motion[i] == static_cast<std::uint8_t>(Motion::Dynamic));
      any_member |= cluster[i] >= 0;
    }
    if (!any_member) {
      const auto step_block = all_free_dynamic ? &step_free_block<true> : &step_free_block<false>;
      step_block(b0, b1, vx, vy, omega, x, y, theta, force, inv_m, inv_i, motion, cluster, x_ref, y_ref, damp, gx,
                 gy, dt, m2);
    } else {
      // Member discs are never written here, not even with their old values: their body may
      // be another thread's, placing them at this moment (a write-back of the old value would
      // undo that). So the block goes run by run of free discs; members count no displacement.
      for (std::ptrdiff_t i = b0; i < b1;) {
        if (cluster[i] >= 0) { m2[i - b0] = 0; ++i; continue; }
        const std::ptrdiff_t run = i;
        while (i < b1 && cluster[i] < 0) ++i;
        step_free_block<false>(run, i, vx, vy, omega, x, y, theta, force, inv_m, inv_i, motion, cluster, x_ref,
                               y_ref, damp, gx, gy, dt, m2 + (run - b0));
      }
    }
    for (std::ptrdiff_t k = 0; k < b1 - b0; ++k) {
      max2 = std::max(max2, m2[k]);
      not_finite += m2[k] != m2[k];
    }
  }
  return {max2, not_finite};
}

// Turns the rotation (c, s) by the angle h: cos h and sin h to fourth order (h = omega dt is
// below 1e-3 rad in any stable run, so the angle is exact to ~1e-16 rad), then back onto the
// unit circle. No trigonometry: sin and cos of each body's angle every step cost as much as
// the rest of the cluster update.
inline void rotate_pose(double& c, double& s, double h) {
  const double h2 = h * h;
  const double ch = 1 - 0.5 * h2 * (1 - h2 / 12), sh = h * (1 - h2 / 6);
  const double rc = c * ch - s * sh, rs = s * ch + c * sh;
  // 1 / |(rc, rs)| by one Newton step from 1: the length is 1 to within rounding (the rotation
  // keeps it to O(h^6)), so the step is exact to rounding, without a square root or a division.
  const double norm = 1.5 - 0.5 * (rc * rc + rs * rs);
  // Without a branch, so that the loop vectorises; bodies that do not turn (at rest,
  // kinematic) keep their rotation bit for bit.
  c = select(h == 0, c, rc * norm);
  s = select(h == 0, s, rs * norm);
}

// Semi-implicit Euler for the rigid bodies [begin, end), through restrict parameters as
// step_free_block. Out of line: inlined into integrate_share, GCC 12 no longer vectorises it.
__attribute__((noinline))
void step_bodies(std::ptrdiff_t begin, std::ptrdiff_t end, double* __restrict vx, double* __restrict vy,
                 double* __restrict omega, double* __restrict x, double* __restrict y, double* __restrict theta,
                 double* __restrict rot_c, double* __restrict rot_s, const double* __restrict fx, const double* __restrict fy,
                 const double* __restrict torque, const double* __restrict inv_m, const double* __restrict inv_i,
                 const std::uint8_t* __restrict motion, double damp, double gx, double gy, double dt) {
  for (std::ptrdiff_t k = begin; k < end; ++k) {
    const bool dynamic = motion[k] == static_cast<std::uint8_t>(Motion::Dynamic);
    const double vx_new = damp * vx[k] + (fx[k] * inv_m[k] + gx) * dt;
    const double vy_new = damp * vy[k] + (fy[k] * inv_m[k] + gy) * dt;
    const double w_new = damp * omega[k] + torque[k] * inv_i[k] * dt;
    vx[k] = select(dynamic, vx_new, vx[k]);
    vy[k] = select(dynamic, vy_new, vy[k]);
    omega[k] = select(dynamic, w_new, omega[k]);
    x[k] += vx[k] * dt;
    y[k] += vy[k] * dt;
    theta[k] += omega[k] * dt;
    rotate_pose(rot_c[k], rot_s[k], omega[k] * dt);
  }
}

}  // namespace

// Bodies per block: each thread takes its bodies a block at a time through the three
// stages (forces, step, placement), so that a block's arrays are still in cache for the next
// stage, while each stage stays a loop of its own (the body step vectorises).
constexpr std::ptrdiff_t kBodyBlock = 256;

Displacement integrate_share(Discs& d, Clusters& c, DiscForce* force, const BodyForce& g, double dt,
                             const double* x_ref, const double* y_ref, const ThreadSplit& split, std::size_t t) {
  const double damp = 1.0 - g.drag * dt;
  Displacement moved;
  // The free-disc pass and the body passes touch different discs (members are left to their
  // bodies), and each disc's and body's update is its own: no thread waits for another.
  // Discs outside clusters in this stretch, if any (with none, the usual cluster packing, the
  // bodies place every disc and that pass would be wasted).
  const auto* cluster = d.cluster.data();
  if (std::find(cluster + split.disc[t], cluster + split.disc[t + 1], kNoCluster) != cluster + split.disc[t + 1])
    moved = step_free_discs(split.disc[t], split.disc[t + 1], d.vx.data(), d.vy.data(), d.omega.data(), d.x.data(),
                            d.y.data(), d.theta.data(), force, d.inv_mass.data(), d.inv_inertia.data(),
                            d.motion.data(), d.cluster.data(), x_ref, y_ref, damp, g.gx, g.gy, dt);
  const std::ptrdiff_t body_end = split.body[t + 1];
  for (std::ptrdiff_t b0 = split.body[t]; b0 < body_end; b0 += kBodyBlock) {
    const std::ptrdiff_t b1 = std::min(body_end, b0 + kBodyBlock);
    gather_cluster_forces(c, d, force, b0, b1);
    step_bodies(b0, b1, c.vx.data(), c.vy.data(), c.omega.data(), c.x.data(), c.y.data(), c.theta.data(),
                c.rot_c.data(), c.rot_s.data(), c.fx.data(), c.fy.data(), c.torque.data(), c.inv_mass.data(),
                c.inv_inertia.data(), c.motion.data(), damp, g.gx, g.gy, dt);
    moved.max2 = std::max(moved.max2, place_cluster_discs(c, d, b0, b1, x_ref, y_ref));
  }
  return moved;
}

double Displacement::distance() const {
  // NaN counts as infinitely far: it forces a rebuild, where it is caught.
  return not_finite ? std::numeric_limits<double>::infinity() : std::sqrt(max2);
}

}  // namespace orogen
