#pragma once
// Rigid line-segment walls (MODEL §6). A wall pushes discs with the normal law of disc
// contacts; along the wall it is smooth, rough (tangential spring with its own Coulomb limit
// and history), or a traction belt that drags touching discs toward its surface velocity
// (the thesis's basal traction condition, eq. 4.1, capped by the Coulomb limit).
#include <cstdint>
#include <string>
#include <vector>

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

  double length() const;
};

// Closest point of segment (a, b) to p; returns the squared distance.
double closest_point_on_segment(const Wall& w, double px, double py, double& cx, double& cy);

}  // namespace orogen
