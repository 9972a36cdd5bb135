#pragma once
// Wedge measurements from particle positions and the upper surface (MODEL §8, thesis 4.3,
// 5.4.5): deformation and marker fronts, the highest peak, the wedge height and the pro- and
// retro-wedge taper angles. Pure functions, so they can be checked on synthetic input.
#include <cstddef>
#include <span>
#include <vector>

#include "analysis/surface.hpp"

namespace orogen {

// How the deformation fronts are found (wedge.fronts, docs/model.md "Measurements"):
// Discs: the thesis's, the extreme x of any disc whose centre is above h0 + d_max, so one
// disc rolling ahead on the foreland sets it; Surface: the same discs, but only those in a
// stretch of surface columns holding such discs (narrow gaps bridged) at least
// min_raised_width wide, so that a loose disc or cluster does not count and a thrust sheet does.
enum class FrontRule { Discs, Surface };

struct WedgeGeometry {
  double h = 0;        // highest elevation (top of the highest disc) minus h0
  double x_peak = 0;   // x of the highest disc (T)
  double dp = 0, dr = 0;  // pro/retro deformation fronts: extreme x of discs above h0 + d_max
  double mp = 0, mr = 0;  // pro/retro marker fronts: extreme x of discs above marker height
  double alpha = 0, beta = 0;          // mean tapers: slope from each front to the peak [rad]
  double alpha_fit = 0, beta_fit = 0;  // least-squares slope of the surface between them [rad]
  bool has_front = false;              // any disc above h0 + d_max
};

struct WedgeGeometryInput {
  std::span<const double> x, y, radius;  // all discs in the model
  double h0 = 1;            // undeformed layer thickness
  double d_max = 1;         // largest disc diameter
  double marker_height = 1.5;  // marker fronts at this multiple of h0
  double x_s = 0;           // S-point (fronts default to it when nothing is deformed)
  FrontRule front_rule = FrontRule::Discs;
  double min_raised_width = 0;  // FrontRule::Surface: narrower raised stretches do not count
  double max_bridged_gap = 0;   // FrontRule::Surface: columns without raised discs this wide join a stretch
};

WedgeGeometry measure_wedge(const WedgeGeometryInput& in, const Surface& surface);

// Least-squares slope of surface heights between x_lo and x_hi (column centres), as an angle.
double fitted_slope(const Surface& surface, double x_lo, double x_hi);

}  // namespace orogen
