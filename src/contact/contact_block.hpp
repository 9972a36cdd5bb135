#pragma once
// The contact law of contact_law.hpp for a block of pairs at once, written without branches
// so that the compiler can vectorise it. Same operations in the same order as contact_force,
// so the results are bitwise identical (tests/test_contact_block.cpp checks it).
#include <cmath>
#include <cstdint>

namespace orogen {

constexpr int kContactBlock = 64;

struct ContactBlock {
  // Inputs, gathered per pair: geometry and kinematics of the second disc relative to the first.
  alignas(64) double dx[kContactBlock], dy[kContactBlock], ri[kContactBlock], rj[kContactBlock];
  alignas(64) double dvx[kContactBlock], dvy[kContactBlock], wi[kContactBlock], wj[kContactBlock];
  alignas(64) double gn[kContactBlock], gs[kContactBlock];
  // In and out: tangential history.
  alignas(64) double xi[kContactBlock];
  // Outputs.
  alignas(64) double fx[kContactBlock], fy[kContactBlock], ft[kContactBlock];
  alignas(64) std::int64_t touching[kContactBlock];  // as wide as a double: one vector type
};

// The contact law for one pair, without branches (the lanes of a vector loop): force on the
// second disc, tangential force and new history; all zero for a pair that does not touch.
struct ContactLane {
  double fx, fy, ft, xi;
  bool touching;
};

inline ContactLane contact_lane(double dx, double dy, double ri, double rj, double dvx, double dvy, double wi,
                                double wj, double gn, double gs, double xi_old, double kn, double ks, double mu,
                                double dt) {
  const double dist2 = dx * dx + dy * dy;
  const double rsum = ri + rj;
  const bool touching = dist2 < rsum * rsum;
  const double dist = std::sqrt(dist2);
  const double inv = 1.0 / dist;
  const double nx = dx * inv, ny = dy * inv;
  const double tx = -ny, ty = nx;
  const double delta = rsum - dist;
  const double rot = wi * ri + wj * rj;
  const double vn = dvx * nx + dvy * ny;
  const double vt = dvx * tx + dvy * ty - rot;
  double fn = kn * delta - gn * vn;
  fn = fn < 0 ? 0.0 : fn;
  double xi = xi_old + vt * dt;
  double ft = -ks * xi - gs * vt;
  const double limit = mu * fn;
  const bool slip = std::fabs(ft) > limit;
  const double ft_limit = std::copysign(limit, ft);
  const double xi_limit = -ft_limit / ks;  // computed unconditionally: no branch to vectorise
  ft = slip ? ft_limit : ft;
  xi = slip ? xi_limit : xi;
  return {touching ? fn * nx + ft * tx : 0.0, touching ? fn * ny + ft * ty : 0.0, touching ? ft : 0.0,
          touching ? xi : 0.0, touching};
}

inline void contact_forces_block(ContactBlock& b, int count, double kn, double ks, double mu, double dt) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const ContactLane c = contact_lane(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k], b.wj[k],
                                       b.gn[k], b.gs[k], b.xi[k], kn, ks, mu, dt);
    b.fx[k] = c.fx; b.fy[k] = c.fy; b.ft[k] = c.ft; b.xi[k] = c.xi;
    b.touching[k] = c.touching;
  }
}

}  // namespace orogen
