#pragma once
// The disc-disc contact law (MODEL §3) for one pair, and for a block of pairs at once: the one
// pair kernel, built from the branch-free pieces of contact/law_kernels.hpp and a registered
// normal law (contact/normal_laws.hpp), so that the compiler can vectorise it. The pair loop,
// the contact output and the tests all call it (tests/test_one_contact_law.cpp checks that
// every user gets the same bits).
#include <cmath>
#include <cstdint>

#include "contact/law_kernels.hpp"

namespace orogen {

constexpr int kContactBlock = 64;

struct ContactBlock {
  // Inputs, gathered per pair: geometry and kinematics of the second disc relative to the first.
  alignas(64) double dx[kContactBlock], dy[kContactBlock], ri[kContactBlock], rj[kContactBlock];
  alignas(64) double dvx[kContactBlock], dvy[kContactBlock], wi[kContactBlock], wj[kContactBlock];
  alignas(64) double gn[kContactBlock], gs[kContactBlock];
  alignas(64) double mu[kContactBlock];  // the pair's Coulomb coefficient (contact/materials.hpp)
  // In and out: tangential history.
  alignas(64) double xi[kContactBlock];
  // Outputs.
  alignas(64) double fx[kContactBlock], fy[kContactBlock], ft[kContactBlock];
  alignas(64) double slip[kContactBlock];  // sliding in this step (weakening; 0 off the limit)
  // Rolling resistance only: the pair's coefficient in, the rolling history in and out, the
  // rolling moment on the second disc out (its opposite acts on the first).
  alignas(64) double mur[kContactBlock], roll[kContactBlock], moment[kContactBlock];
  alignas(64) std::int64_t touching[kContactBlock];  // as wide as a double: one vector type
};

// The law for one pair, without branches (the lanes of a vector loop): force on the second
// disc, tangential force and new history, all zero for a pair that does not touch; and, for
// the contact output (unused values cost nothing in the loops), the normal force, the unit
// normal from the first disc to the second, the overlap and whether the Coulomb limit held;
// and, for weakening materials, how far the contact slid on the limit in this step (the trial
// history beyond the one the limit set; 0 when it held).
struct ContactLane {
  double fx, fy, ft, xi;
  bool touching;
  double fn, nx, ny, delta;
  bool at_limit;
  double slip;
};

// Second disc at (dx, dy) from the first, relative velocity (dvx, dvy), spins wi, wj; gn, gs
// the pair's normal and tangential dashpots, xi_old its history.
template <class Normal>
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
  // Relative velocity of j's contact point with respect to i's.
  const double rot = wi * ri + wj * rj;
  const double vn = dvx * nx + dvy * ny;        // > 0 when separating
  const double vt = dvx * tx + dvy * ty - rot;  // sliding along t
  const double fn = Normal::force(kn, delta, gn, vn, ri * rj / rsum);
  const Tangential t = tangential_spring(xi_old, vt, dt, ks, gs, mu * Normal::load(fn));
  return {touching ? fn * nx + t.ft * tx : 0.0,
          touching ? fn * ny + t.ft * ty : 0.0,
          touching ? t.ft : 0.0,
          touching ? t.xi : 0.0,
          touching,
          fn,
          nx,
          ny,
          delta,
          touching && t.slip,
          touching && t.slip ? std::fabs(xi_old + vt * dt - t.xi) : 0.0};
}

// Rolling resistance of one pair (Iwashita and Oda 1998; the elastic-plastic spring of Ai et al.
// 2011 without its dashpot): a spring of stiffness kr_per_r2 r_eff^2 on the discs' relative
// rotation (the history, advanced by (w_j - w_i) dt), its moment capped at mu_r r_eff times the
// load that caps the tangential force; the same piece as the tangential spring. The moment acts
// on the second disc, its opposite on the first; zero, with zero history, for a pair apart.
struct RollingLane {
  double moment, roll;
};
inline RollingLane rolling_lane(bool touching, double ri, double rj, double wi, double wj, double roll_old,
                                double load, double kr_per_r2, double mur, double dt) {
  const double r_eff = ri * rj / (ri + rj);
  const Tangential r = tangential_spring(roll_old, wj - wi, dt, kr_per_r2 * r_eff * r_eff, 0.0, mur * r_eff * load);
  return {touching ? r.ft : 0.0, touching ? r.xi : 0.0};
}

// Every pair with the friction mu (the thesis's one material).
template <class Normal>
inline void contact_forces_block(ContactBlock& b, int count, double kn, double ks, double mu, double dt) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const ContactLane c = contact_lane<Normal>(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k],
                                               b.wj[k], b.gn[k], b.gs[k], b.xi[k], kn, ks, mu, dt);
    b.fx[k] = c.fx; b.fy[k] = c.fy; b.ft[k] = c.ft; b.xi[k] = c.xi;
    b.touching[k] = c.touching;
  }
}

// Each pair with its own friction b.mu[k], and its slip on the limit out (named materials).
template <class Normal>
inline void contact_forces_block_materials(ContactBlock& b, int count, double kn, double ks, double dt) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const ContactLane c = contact_lane<Normal>(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k],
                                               b.wj[k], b.gn[k], b.gs[k], b.xi[k], kn, ks, b.mu[k], dt);
    b.fx[k] = c.fx; b.fy[k] = c.fy; b.ft[k] = c.ft; b.xi[k] = c.xi; b.slip[k] = c.slip;
    b.touching[k] = c.touching;
  }
}

// Each pair with its own friction b.mu[k] and rolling resistance b.mur[k]: the slip on the limit
// and the rolling moment out.
template <class Normal>
inline void contact_forces_block_rolling(ContactBlock& b, int count, double kn, double ks, double kr_per_r2,
                                         double dt) {
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const ContactLane c = contact_lane<Normal>(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k],
                                               b.wj[k], b.gn[k], b.gs[k], b.xi[k], kn, ks, b.mu[k], dt);
    const RollingLane r = rolling_lane(c.touching, b.ri[k], b.rj[k], b.wi[k], b.wj[k], b.roll[k],
                                       Normal::load(c.fn), kr_per_r2, b.mur[k], dt);
    b.fx[k] = c.fx; b.fy[k] = c.fy; b.ft[k] = c.ft; b.xi[k] = c.xi; b.slip[k] = c.slip;
    b.roll[k] = r.roll; b.moment[k] = r.moment;
    b.touching[k] = c.touching;
  }
}

}  // namespace orogen
