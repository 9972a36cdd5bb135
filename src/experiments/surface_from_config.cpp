// The [surface] keys read into a SurfaceSpec (docs/surface.md), with the checks across keys.
#include <fmt/format.h>

#include "config/config.hpp"
#include "experiments/spec_from_config.hpp"

namespace orogen {

SurfaceSpec read_surface_keys(const Config& c, double h0) {
  SurfaceSpec s;
  s.every = c.get_int32("surface.every");
  s.column_width = c.get_float("surface.column_width");
  s.diffusivity = c.get_float("surface.diffusivity");
  s.critical_slope = c.get_float("surface.critical_slope");
  s.erodibility = c.get_float("surface.erodibility");
  s.area_exponent = c.get_float("surface.area_exponent");
  s.slope_exponent = c.get_float("surface.slope_exponent");
  s.precipitation = c.get_float("surface.precipitation");
  const std::string windward = c.get_string("surface.windward");
  s.windward = windward == "pro" ? Windward::Pro : windward == "retro" ? Windward::Retro : Windward::None;
  s.windward_factor = c.get_float("surface.windward_factor");
  s.base_level = c.get_float("surface.base_level") * h0;
  s.deposition = c.get_bool("surface.deposition");
  s.recycling = c.get_float("surface.recycling");
  if (s.windward == Windward::None && s.windward_factor != 1)
    throw config_error(c.sources_of({"surface.windward_factor", "surface.windward"}), "surface.windward_factor",
                       format_float(s.windward_factor),
                       "1 unless surface.windward names the side the rain comes from (\"pro\" or \"retro\"): an "
                       "orographic pattern needs a windward side");
  if (s.recycling > 0 && !s.deposition)
    throw config_error(c.sources_of({"surface.recycling", "surface.deposition"}), "surface.recycling",
                       format_float(s.recycling),
                       "0 unless surface.deposition = true: recycled sediment is laid as discs");
  s.sediment_supply = c.get_float("surface.sediment_supply");
  const std::string supply_to = c.get_string("surface.supply_to");
  s.supply_to = supply_to == "pro" ? SupplySide::Pro : supply_to == "retro" ? SupplySide::Retro : SupplySide::Both;
  if (s.sediment_supply > 0 && !s.deposition)
    throw config_error(c.sources_of({"surface.sediment_supply", "surface.deposition"}), "surface.sediment_supply",
                       format_float(s.sediment_supply),
                       "0 unless surface.deposition = true: the supplied sediment is laid as discs");
  if (const auto k = material_named_by(c, "surface.sediment_material"); k >= 0)
    s.sediment_material = static_cast<std::uint8_t>(k);
  return s;
}

}  // namespace orogen
