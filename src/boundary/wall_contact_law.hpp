#pragma once
// The law of one disc-wall contact (MODEL §3 with the wall's friction kind), as a pure
// function of the disc, the wall and the contact's history: the force stage
// (boundary/wall_forces.cpp) and the contact output (analysis/contact_forces.cpp) both call
// it, so the stored forces are bitwise those the next step applies.
#include <cmath>

#include "boundary/wall.hpp"
#include "contact/contact_law.hpp"
#include "contact/law_kernels.hpp"

namespace orogen {

struct WallContactForce {
  bool touching = false, at_limit = false;
  double cx = 0, cy = 0;  // closest point of the wall to the disc centre
  double nx = 0, ny = 0;  // unit normal from the wall to the disc centre
  double delta = 0;       // overlap
  double fn = 0, ft = 0;  // normal and tangential (along t = n rotated +90 degrees) force on the disc
  double xi = 0;          // history after the step (0 when apart or smooth)
};

// Disc at (x, y) with velocity (vx, vy), spin omega and radius r; gamma_n, mass and xi_old
// are the contact's own (WallContacts, contact/contact_store.hpp). Normal is a registered normal law
// (contact/normal_laws.hpp); the tangential law is the wall's friction kind, each built from
// the kernels of contact/law_kernels.hpp that the pair kernel uses too.
template <class Normal>
inline WallContactForce wall_contact_force(const Wall& w, double x, double y, double vx, double vy, double omega,
                                           double r, double gamma_n, double mass, double xi_old,
                                           const ContactLaw& law, double dt) {
  WallContactForce c;
  const double dist2 = closest_point_on_segment(w, x, y, c.cx, c.cy);
  if (dist2 >= r * r || dist2 == 0.0) return c;
  const double dist = std::sqrt(dist2);
  const double nx = (x - c.cx) / dist, ny = (y - c.cy) / dist;  // wall -> disc
  const double tx = -ny, ty = nx;
  const double delta = r - dist;
  // Velocity of the disc's contact point (at -r n) relative to the wall's surface.
  const double len = w.length();
  const double ex = len > 0 ? (w.bx - w.ax) / len : 0, ey = len > 0 ? (w.by - w.ay) / len : 0;
  const double wvx = w.vx + w.surface_speed * ex, wvy = w.vy + w.surface_speed * ey;
  const double rvx = vx - omega * r * tx - wvx;
  const double rvy = vy - omega * r * ty - wvy;
  const double vn = rvx * nx + rvy * ny;  // > 0 when separating
  const double vt = rvx * tx + rvy * ty;
  const double fn = Normal::force(law.kn, delta, gamma_n, vn, r);  // a wall: the disc's radius
  const double limit = w.mu * Normal::load(fn);
  Tangential t{0.0, 0.0, false};  // smooth: no tangential force, no history
  switch (w.friction) {
    case WallFriction::Smooth:
      break;
    case WallFriction::Rough:
      t = tangential_spring(xi_old, vt, dt, law.ks, law.tangential_damping_ratio * gamma_n, limit);
      break;
    case WallFriction::Traction:
      // Eq. 4.1 with the drag taken implicitly over the step, gamma / (1 + gamma dt / m):
      // stable for any gamma, and at most the force that brings a free disc to the
      // plate's speed in one step. Traction keeps no spring; the history is left as it was.
      t = viscous_traction(w.traction_gamma / (1.0 + w.traction_gamma * dt / mass), vt, limit, xi_old);
      break;
  }
  c.touching = true;
  c.at_limit = t.slip;
  c.nx = nx; c.ny = ny; c.delta = delta; c.fn = fn; c.ft = t.ft; c.xi = t.xi;
  return c;
}

}  // namespace orogen
