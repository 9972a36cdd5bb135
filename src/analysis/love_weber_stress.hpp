#pragma once
// Stress from contact forces (Love-Weber): per disc, sigma_ij = (1/A) sum_c f_i^c l_j^c over
// the disc's contacts c, f^c the force the disc feels and l^c the branch vector from its centre
// to the contact point, A = pi r^2 the disc's own area (not a Voronoi cell: the disc's stress,
// not the bulk's, which needs the porosity). Tension is positive: a loaded packing has
// sigma_yy < 0. In 2D a stress is a force per length [m g / d].
#include <cstddef>
#include <vector>

#include "analysis/contact_forces.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct DiscStress {
  std::vector<double> xx, xy, yx, yy;  // per disc index (xy = sum f_x l_y / A)
  std::vector<double> area;            // pi r^2
};

DiscStress love_weber_stress(const Discs& discs, const ContactList& contacts);

// Stress on a regular grid of square cells: the sum of sigma A over the discs whose centre lies
// in a cell, divided by the cell's area (the packing's bulk stress, voids included: a cell
// inside a packing of solid fraction phi gets about phi times its discs' mean stress).
// Cells are [x0 + i h, x0 + (i+1) h) x [y0 + j h, ...), x0 and y0 multiples of h, covering
// every disc centre; values row-major, row j = y, column i = x.
struct StressGrid {
  double cell = 0, x0 = 0, y0 = 0;
  std::size_t nx = 0, ny = 0;
  std::vector<double> xx, xy, yx, yy;
};

StressGrid coarse_grain_stress(const Discs& discs, const DiscStress& stress, double cell);

}  // namespace orogen
