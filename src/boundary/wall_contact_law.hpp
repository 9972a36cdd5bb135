#pragma once
// The law of one disc-wall contact (MODEL §3 with the wall's friction kind), as a pure
// function of the disc, the wall and the contact's history: the force stage
// (boundary/wall_forces.cpp) and the contact output (analysis/contact_forces.cpp) both call
// it, so the stored forces are bitwise those the next step applies. Without branches, as the
// pair kernel: the force stage runs it in the lanes of a vector loop over one wall's contacts.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/law_kernels.hpp"
#include "util/select.hpp"

namespace orogen {

struct WallContactForce {
  bool touching = false, at_limit = false;
  double cx = 0, cy = 0;  // closest point of the wall to the disc centre
  double nx = 0, ny = 0;  // unit normal from the wall to the disc centre
  double delta = 0;       // overlap
  double fn = 0, ft = 0;  // normal and tangential (along t = n rotated +90 degrees) force on the disc
  double xi = 0;          // history after the step (0 when apart or smooth)
  double slip = 0;        // sliding in this step on the Coulomb limit (0 off it), for a weakening wall
};

// What the law needs of a wall, worked out once per wall and force pass rather than per
// contact (the segment's length is a hypot).
struct WallFrame {
  Segment segment;
  double wvx, wvy;  // velocity of the wall's surface: the wall's own plus its belt's
  double mu, traction_gamma;
  double mu_lost, inverse_weakening_distance;  // a weakening wall: mu - mu_residual, 1 / distance (else 0, 0)
};

// The wall's coefficient at a disc that has slipped `slip` (branch-free; mu itself when the wall
// does not weaken).
inline double wall_mu(const WallFrame& f, double slip) {
  return f.mu - f.mu_lost * std::min(1.0, slip * f.inverse_weakening_distance);
}

inline WallFrame wall_frame(const Wall& w) {
  const Segment g = segment(w);
  const double len = w.length();
  const double ux = len > 0 ? g.ex / len : 0, uy = len > 0 ? g.ey / len : 0;
  return {g,
          w.vx + w.surface_speed * ux,
          w.vy + w.surface_speed * uy,
          w.mu,
          w.traction_gamma,
          w.weakens ? w.mu - w.mu_residual : 0.0,
          w.weakens ? 1.0 / w.weakening_distance : 0.0};
}

// Disc at (x, y) with velocity (vx, vy), spin omega and radius r; gamma_n, traction_mass and xi_old
// are the contact's own (WallContacts, contact/contact_store.hpp); mu the wall's coefficient at
// this disc (f.mu, or wall_mu of the disc's slip for a weakening wall). Normal is a registered
// normal law (contact/normal_laws.hpp); kFriction the wall's friction kind, each built from
// the kernels of contact/law_kernels.hpp that the pair kernel uses too. A disc apart from the
// wall (or exactly on it, with no normal) gets zeros; its values are computed and masked.
template <class Normal, WallFriction kFriction>
inline WallContactForce wall_contact_lane(const WallFrame& f, double x, double y, double vx, double vy, double omega,
                                          double r, double gamma_n, double traction_mass, double xi_old, double mu,
                                          double kn, double ks, double damping_ratio, double dt) {
  double cx, cy;
  const double dist2 = closest_point(f.segment, x, y, cx, cy);
  const bool touching = !(dist2 >= r * r) & (dist2 != 0.0);
  const double dist = std::sqrt(dist2);
  const double nx = (x - cx) / dist, ny = (y - cy) / dist;  // wall -> disc
  const double tx = -ny, ty = nx;
  const double delta = r - dist;
  // Velocity of the disc's contact point (at -r n) relative to the wall's surface.
  const double rvx = vx - omega * r * tx - f.wvx;
  const double rvy = vy - omega * r * ty - f.wvy;
  const double vn = rvx * nx + rvy * ny;  // > 0 when separating
  const double vt = rvx * tx + rvy * ty;
  const double fn = Normal::force(kn, delta, gamma_n, vn, r);  // a wall: the disc's radius
  const double limit = mu * Normal::load(fn);
  Tangential t{0.0, 0.0, false};  // smooth: no tangential force, no history
  if constexpr (kFriction == WallFriction::Rough) {
    t = tangential_spring(xi_old, vt, dt, ks, damping_ratio * gamma_n, limit);
  } else if constexpr (kFriction == WallFriction::Traction) {
    // Eq. 4.1 with the drag taken implicitly over the step, gamma / (1 + gamma dt / m), m the
    // body's effective mass at the contact point (boundary/traction_mass.hpp): stable for any
    // gamma, and at most the force that brings the contact point to the plate's speed in one
    // step. Traction keeps no spring; the history is left as it was.
    t = viscous_traction(f.traction_gamma / (1.0 + f.traction_gamma * dt / traction_mass), vt, limit, xi_old);
  }
  WallContactForce c;
  c.touching = touching;
  c.at_limit = touching & t.slip;
  c.cx = cx; c.cy = cy;
  c.nx = select(touching, nx, 0.0); c.ny = select(touching, ny, 0.0);
  c.delta = select(touching, delta, 0.0);
  c.fn = select(touching, fn, 0.0); c.ft = select(touching, t.ft, 0.0);
  c.xi = select(touching, t.xi, 0.0);
  c.slip = select(c.at_limit, std::fabs(xi_old + vt * dt - t.xi), 0.0);
  return c;
}

// Calls f(std::integral_constant<WallFriction, kind>{}) with the wall's friction kind, so
// that a loop over one wall's contacts is compiled once per kind, without a branch inside.
template <class F>
void with_wall_friction(WallFriction kind, F&& f) {
  switch (kind) {
    case WallFriction::Smooth: f(std::integral_constant<WallFriction, WallFriction::Smooth>{}); break;
    case WallFriction::Rough: f(std::integral_constant<WallFriction, WallFriction::Rough>{}); break;
    case WallFriction::Traction: f(std::integral_constant<WallFriction, WallFriction::Traction>{}); break;
  }
}

// The same law for one contact, for callers outside the force loop (the contact output); slip
// is the disc's accumulated slip (0 without materials).
template <class Normal>
inline WallContactForce wall_contact_force(const Wall& w, double x, double y, double vx, double vy, double omega,
                                           double r, double gamma_n, double traction_mass, double xi_old,
                                           double slip, const ContactLaw& law, double dt) {
  WallContactForce c;
  const WallFrame frame = wall_frame(w);
  with_wall_friction(w.friction, [&](auto kind) {
    c = wall_contact_lane<Normal, decltype(kind)::value>(frame, x, y, vx, vy, omega, r, gamma_n, traction_mass,
                                                         xi_old, wall_mu(frame, slip), law.kn, law.ks,
                                                         law.tangential_damping_ratio, dt);
  });
  return c;
}

}  // namespace orogen
