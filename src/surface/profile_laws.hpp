#pragma once
// Surface processes on a profile of column heights (issue 40; docs/surface.md): the continuum
// laws that move the model's surface between particle updates. Each law takes the heights h of
// equal columns dx wide (the surface of analysis/surface.hpp) and advances them by dt; none knows
// particles, which the caller removes or adds where the new surface asks for it.
//
//   hillslope diffusion, linear:     dh/dt = kappa d2h/dx2
//   hillslope diffusion, nonlinear:  dh/dt = -dq/dx, q = -kappa S / (1 - (|S| / Sc)^2) (Roering et al. 1999)
//   fluvial stream power:            dh/dt = -K Q^m S^n, Q the discharge routed down the profile
//
// Lengths in d, time in sqrt(d/g); kappa in d^2 / sqrt(d/g), K in d^(1 - 2m) ... per the units of
// Q (precipitation x length: d^2 per unit time and width).
#include <cstddef>
#include <vector>

namespace orogen {

// What lies beyond the profile's two ends: nothing (no flux crosses them: the hillslope laws
// conserve the profile's area), or a base level the ends drain to (a column of height base_level
// one dx beyond each end).
struct ProfileEnds {
  bool open = false;
  double base_level = 0;
};

// Linear diffusion over dt, backward Euler (stable for any dt; error O(dt) + O(dx^2)).
void diffuse_linear(std::vector<double>& h, double dx, double kappa, double dt, const ProfileEnds& ends);

// Roering et al.'s nonlinear diffusion over dt, explicit in sub-steps short enough for the
// steepest face of each (its effective diffusivity kappa (1 + s^2) / (1 - s^2)^2, s = |S| / Sc). Faces
// steeper than kMaxSlopeRatio Sc carry the flux of that slope: the law's flux diverges at Sc,
// where a real hillslope fails by landsliding; the cap keeps the step finite.
constexpr double kMaxSlopeRatio = 0.95;
void diffuse_nonlinear(std::vector<double>& h, double dx, double kappa, double critical_slope, double dt,
                       const ProfileEnds& ends);

// Stream power. Each column drains to its lower neighbour (the steeper descent; an end column may
// drain out to the base level); the discharge of a column is its own precipitation times dx plus
// the discharge of the columns that drain into it. Water fills each pit to the rim it spills
// over (and stands at the base level beyond an open end): a column under water is not cut (its
// floor keeps its height; deposition fills it), passes its water on towards the spill, and the
// rivers that run into it cut down to the water's surface, not to its floor. Without this a
// rough granular surface, whose pits are everywhere, would be cut through to the model's base.
struct StreamPower {
  double K = 0;  // erodibility
  double m = 0.5;
  double n = 1;
};

// Advances h by dt: each column, from the outlets upwards, solved implicitly against its
// receiver's new height (Braun and Willett 2013: unconditionally stable for n = 1; Newton's method
// for other n). precipitation: one value per column (>= 0). Returns each column's discharge.
std::vector<double> erode_fluvial(std::vector<double>& h, double dx, const StreamPower& law,
                                  const std::vector<double>& precipitation, double dt, const ProfileEnds& ends);

// A precipitation pattern over the columns: uniform `rate`, or orographic, `rate` on the leeward
// side of the highest column and rate x windward_factor on the windward side (the side towards
// -x when windward_is_left).
std::vector<double> precipitation_pattern(const std::vector<double>& h, double rate, double windward_factor,
                                          bool windward_is_left);

}  // namespace orogen
