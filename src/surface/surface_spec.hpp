#pragma once
// What a run's surface processes are (the [surface] keys, docs/surface.md): the laws that move
// the surface between particle updates, how often they run, and what happens to what they move.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace orogen {

// The side the rain comes from under an orographic pattern: more precipitation there.
enum class Windward { None, Pro, Retro };

// The forelands an outside sediment supply fills: both (half each), or one.
enum class SupplySide { Both, Pro, Retro };

// A user's law (from Python): advances the heights h of columns dx wide, the first centred at
// x_lo + dx / 2, by dt, in place.
using SurfaceScript = std::function<void(std::vector<double>& h, double dx, double x_lo, double dt)>;

struct SurfaceSpec {
  std::int32_t every = 500;    // time steps between surface updates
  double column_width = 0;     // [d]; 0: the experiment's surface columns (2.3 mean radii)
  double diffusivity = 0;      // hillslope kappa [d^2 / sqrt(d/g)]; 0: no hillslope law
  double critical_slope = 0;   // Roering's Sc [-]; 0: the linear law
  double erodibility = 0;      // stream-power K; 0: no river
  double area_exponent = 0.5;  // m
  double slope_exponent = 1;   // n
  double precipitation = 1;    // rain on the leeward side (everywhere when uniform) [d / sqrt(d/g)]
  Windward windward = Windward::None;
  double windward_factor = 1;  // rain on the windward side over the leeward
  double base_level = 0;       // where rivers drain and basins fill to [d]
  bool deposition = false;     // particles laid where the surface rises
  double recycling = 0;        // fraction of the profile's net loss filled into the forelands
  double sediment_supply = 0;  // area brought from outside the model into the forelands [d^2 / sqrt(d/g)]
  SupplySide supply_to = SupplySide::Both;
  std::uint8_t sediment_material = 0;  // the deposits' material, an index of [materials]
  SurfaceScript script;           // a user's law, after the others

  // Whether anything moves the surface: a law, or sediment from outside.
  bool has_laws() const {
    return diffusivity > 0 || erodibility > 0 || static_cast<bool>(script) || sediment_supply > 0;
  }
};

}  // namespace orogen
