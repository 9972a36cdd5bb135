#pragma once
// One surface update on a profile (docs/surface.md): the laws of a SurfaceSpec in turn
// (hillslope, river, the user's), then the recycled fill of the forelands. Pure functions of the
// heights; surface_processes.hpp moves the particles after them.
#include <array>
#include <vector>

#include "surface/erosion_carry.hpp"
#include "surface/surface_spec.hpp"

namespace orogen {

struct ProfileStep {
  std::array<std::vector<double>, kSurfaceLaws> lowered;  // each law's lowering of each column [d]
  double recycled = 0;  // area filled into the forelands [d^2]
  double bypassed = 0;  // area to recycle that found no room below the base level [d^2]
  double supplied = 0;  // area of the outside supply filled into the forelands [d^2]
  double supply_bypassed = 0;  // area of the supply that found no room there [d^2]
};

// Advances h (columns dx wide, column 0 centred at x_lo + dx / 2) by dt: the hillslope law with
// closed ends (it moves area, conserving it), the river draining to the base level at both
// ends, the script; then spec.recycling of each side's net loss (the sides of the highest
// column: pro to the left, retro to the right) filled into that side's lowest columns, up to
// the base level at most; then the outside supply, spec.sediment_supply x dt, filled alike into
// the forelands spec.supply_to names (half each into both).
ProfileStep advance_profile(std::vector<double>& h, double dx, double x_lo, const SurfaceSpec& spec, double dt);

// Fills `area` into the columns [first, last) of h, lowest first, as water fills a basin: to one
// level, never above `level`. Returns the area that did not fit.
double fill_to_level(std::vector<double>& h, std::size_t first, std::size_t last, double dx, double area,
                     double level);

}  // namespace orogen
