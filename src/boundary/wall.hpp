#pragma once
// Rigid line-segment walls (MODEL §6). A wall pushes discs with the normal law of disc
// contacts; along the wall it is smooth, rough (tangential spring with its own Coulomb limit
// and history), or a traction belt that drags touching discs toward its surface velocity
// (the thesis's basal traction condition, eq. 4.1, capped by the Coulomb limit).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "util/select.hpp"

namespace orogen {

enum class WallFriction : std::uint8_t { Smooth = 0, Rough = 1, Traction = 2 };

struct Wall {
  std::string name;
  double ax = 0, ay = 0, bx = 0, by = 0;  // end points; the wall is the segment between them
  double vx = 0, vy = 0;                  // velocity of the wall itself (a moving backstop)
  double surface_speed = 0;               // speed of the wall's surface along (b - a), like a belt
  WallFriction friction = WallFriction::Smooth;
  double mu = 0.0;                        // Coulomb coefficient against discs
  double traction_gamma = 0.0;            // drag coefficient of a Traction wall (force per speed)
  bool enabled = true;                    // a removed wall stays in the list, switched off
  // A weakening wall (a world of materials): its coefficient at a disc falls linearly from mu to
  // mu_residual over weakening_distance of the disc's accumulated slip (Discs::slip), as a
  // material's friction does (contact/materials.hpp), and the disc's slip on it adds to that slip.
  bool weakens = false;
  double mu_residual = 0.0;
  double weakening_distance = 1.0;  // [d]

  double length() const;
};

// A base that weakens with slip ([wedge] and [singly] basal_weakening keys): the fraction of a
// wall's mu it loses, over `distance` of a disc's slip [d]. fraction 0: the wall keeps its mu.
struct BaseWeakening {
  double fraction = 0;
  double distance = 1;
};

inline void set_weakening(Wall& w, const BaseWeakening& b) {
  w.weakens = b.fraction > 0;
  w.mu_residual = w.mu * (1.0 - b.fraction);
  w.weakening_distance = b.distance;
}

// The height of a base at x (a deflecting base, src/isostasy); empty: a flat base at y = 0.
using BaseHeight = std::function<double(double x)>;

// A wall's segment as the distance tests use it: start point, the vector a -> b and its
// squared length.
struct Segment {
  double ax, ay, ex, ey, len2;
};

inline Segment segment(const Wall& w) {
  const double ex = w.bx - w.ax, ey = w.by - w.ay;
  return {w.ax, w.ay, ex, ey, ex * ex + ey * ey};
}

// Closest point (cx, cy) of the segment to p; returns the squared distance. Without
// branches: the wall force loop runs it in vector lanes.
inline double closest_point(const Segment& g, double px, double py, double& cx, double& cy) {
  const double along = ((px - g.ax) * g.ex + (py - g.ay) * g.ey) / g.len2;
  const double s = std::clamp(select(g.len2 > 0, along, 0.0), 0.0, 1.0);
  cx = g.ax + s * g.ex;
  cy = g.ay + s * g.ey;
  const double dx = px - cx, dy = py - cy;
  return dx * dx + dy * dy;
}

inline double closest_point_on_segment(const Wall& w, double px, double py, double& cx, double& cy) {
  return closest_point(segment(w), px, py, cx, cy);
}

}  // namespace orogen
