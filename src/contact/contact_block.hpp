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

inline void contact_forces_block(ContactBlock& b, int count, double kn, double ks, double mu, double dt) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const double dist2 = b.dx[k] * b.dx[k] + b.dy[k] * b.dy[k];
    const double rsum = b.ri[k] + b.rj[k];
    const bool touching = dist2 < rsum * rsum;
    const double dist = std::sqrt(dist2);
    const double inv = 1.0 / dist;
    const double nx = b.dx[k] * inv, ny = b.dy[k] * inv;
    const double tx = -ny, ty = nx;
    const double delta = rsum - dist;
    const double rot = b.wi[k] * b.ri[k] + b.wj[k] * b.rj[k];
    const double vn = b.dvx[k] * nx + b.dvy[k] * ny;
    const double vt = b.dvx[k] * tx + b.dvy[k] * ty - rot;
    double fn = kn * delta - b.gn[k] * vn;
    fn = fn < 0 ? 0.0 : fn;
    double xi = b.xi[k] + vt * dt;
    double ft = -ks * xi - b.gs[k] * vt;
    const double limit = mu * fn;
    const bool slip = std::fabs(ft) > limit;
    const double ft_limit = std::copysign(limit, ft);
    const double xi_limit = -ft_limit / ks;  // computed unconditionally: no branch to vectorise
    ft = slip ? ft_limit : ft;
    xi = slip ? xi_limit : xi;
    b.fx[k] = touching ? fn * nx + ft * tx : 0.0;
    b.fy[k] = touching ? fn * ny + ft * ty : 0.0;
    b.ft[k] = touching ? ft : 0.0;
    b.xi[k] = touching ? xi : 0.0;
    b.touching[k] = touching;
  }
}

}  // namespace orogen
