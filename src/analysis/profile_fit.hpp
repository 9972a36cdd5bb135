#pragma once
// Least-squares fits of a surface profile (heights of surface columns against x), for the
// angle of repose (a straight line, its goodness of fit and the profile's curvature) and the
// taper of a singly-vergent wedge.
#include <vector>

#include "analysis/surface.hpp"

namespace orogen {

struct ProfileFit {
  int n = 0;                 // columns used
  double x_lo = 0, x_hi = 0; // extent of the columns used (centres)
  double slope = 0;          // dy/dx of the straight line
  double intercept = 0;
  double r2 = 0;             // coefficient of determination of the line
  double rms = 0;            // root-mean-square residual of the line [d]
  // Slope change along the profile from a quadratic fit: the angle of descent of the
  // quadratic's tangent at the upper end minus that at the lower end [rad]. Positive for a
  // concave profile (steep top, flattening foot), near zero for a planar one.
  double concavity = 0;
  bool valid() const { return n >= 3; }
};

// Fits the columns of `surface` whose centre lies in [x_lo, x_hi] and whose height lies in
// (y_lo, y_hi); empty columns are skipped.
ProfileFit fit_profile(const Surface& surface, double x_lo, double x_hi, double y_lo, double y_hi);

// Fits plain (x, y) points.
ProfileFit fit_points(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace orogen
