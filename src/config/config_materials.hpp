#pragma once
// [materials.NAME] and [[layer.units]] (docs/materials.md): the configuration's named materials
// and the incoming section, read beside the flat keys of the schema. Used by config.cpp only.
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "config/config.hpp"

namespace orogen {

// Converts a TOML node to the key's type and checks its range (config.cpp).
ConfigValue convert_value(const KeySpec& spec, const toml::node& node, const std::string& source,
                          const std::string& shown);
// A node as the user wrote it, for messages (config.cpp).
std::string render_node(const toml::node& node);

// Takes `materials` and `layer.units` out of a parsed file into `out`, each value checked.
void take_layering(toml::table& root, const std::string& path, LayeringConfig& out);

// --set materials.NAME.KEY=VALUE (a new NAME makes a new material, last in order).
bool is_material_override(std::string_view name);
void set_material_override(LayeringConfig& out, const std::string& name, const std::string& raw);

// The defaults that follow other keys (friction_residual, bond_shear_strength, rolling_friction:
// contact.rolling_friction), then the checks across keys: a residual above the peak, a bond
// without one of its strengths, units without materials, units thicker than the layer.
void finish_layering(LayeringConfig& l, double layer_thickness, const std::string& thickness_source,
                     double rolling_friction);

// The resolved copy: `units = [...]` (a line of [layer]) and the [materials.NAME] tables.
std::string units_toml(const LayeringConfig& l);
std::string materials_toml(const LayeringConfig& l);

}  // namespace orogen
