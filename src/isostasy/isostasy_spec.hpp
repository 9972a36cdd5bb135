#pragma once
// What a run's isostasy is (the [isostasy] keys, docs/isostasy.md), in model units: lengths in d,
// densities over the grains' (a disc of radius r weighs pi r^2 with g = 1).
#include <cstdint>

namespace orogen {

enum class IsostasyModel { None, Airy, Flexure };

struct IsostasySpec {
  IsostasyModel model = IsostasyModel::None;
  double mantle_density = 1.22;  // [-], the restoring force per length and deflection (g = 1)
  double rigidity = 0;           // D [d^4 rho g], 0 under Airy
  std::int32_t every = 500;      // steps between solves; the base moves to each over the next `every`
  double segment_length = 5;     // [d]
  // Airy: each node balances the load averaged over the nodes within half this width [d] of it
  // (2 h0: five nodes at the default segments, docs/isostasy.md): a layer of
  // grains is not compensated grain by grain, and a base as rough as its columns' loads would
  // shear the kinematic slab riding on it.
  double airy_width = 20;

  bool active() const { return model != IsostasyModel::None; }
};

}  // namespace orogen
