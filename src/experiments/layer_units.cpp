#include "experiments/layer_units.hpp"

namespace orogen {

std::size_t apply_units(World& w, std::size_t first, std::size_t last, std::uint64_t seed) {
  if (w.materials().empty()) return 0;
  if (!w.discs().has_materials) w.enable_materials();
  for (std::size_t i = first; i < last; ++i)
    w.set_material(i, static_cast<std::uint8_t>(material_at_height(w.materials().units, w.discs().y[i])));
  return w.make_bonds(first, last, seed);
}

}  // namespace orogen
