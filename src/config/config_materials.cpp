#include "config/config_materials.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace orogen {
namespace {

constexpr std::string_view kSet = "--set";

std::string material_key_names() {
  std::string out;
  for (const auto& k : material_schema()) out += (out.empty() ? "" : ", ") + k.name;
  return out;
}

std::string material_names(const LayeringConfig& l) {
  std::string out;
  for (const auto& m : l.materials.list) out += (out.empty() ? "" : ", ") + m.name;
  return out.empty() ? "none" : out;
}

double& field(Material& m, std::string_view key) {
  if (key == "friction") return m.friction;
  if (key == "friction_residual") return m.friction_residual;
  if (key == "weakening_distance") return m.weakening_distance;
  if (key == "rolling_friction") return m.rolling_friction;
  if (key == "bond_tensile_strength") return m.bond.tensile_strength;
  if (key == "bond_shear_strength") return m.bond.shear_strength;
  if (key == "bond_stiffness") return m.bond.stiffness;
  if (key == "bond_radius_factor") return m.bond.radius_factor;
  if (key == "bond_strength_scatter") return m.bond.strength_scatter;
  return m.bond.gap;  // bond_gap (the keys are checked against material_schema first)
}

// A material name is a bare TOML key: letters, digits, '_' and '-'.
bool plain_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::size_t material_index(LayeringConfig& l, const std::string& name, const std::string& source) {
  for (std::size_t k = 0; k < l.materials.size(); ++k)
    if (l.materials.list[k].name == name) return k;
  if (!plain_name(name))
    throw config_error(source, "materials." + name, "", "a material name of letters, digits, '_' and '-'");
  if (l.materials.size() >= 255)
    throw config_error(source, "materials." + name, "", "at most 255 materials");
  Material m;
  m.name = name;
  m.friction = std::nan("");  // required: finish_layering says so if it stays unset
  l.materials.list.push_back(m);
  l.given.emplace_back();
  return l.materials.size() - 1;
}

void set_value(LayeringConfig& l, std::size_t k, const std::string& key, const toml::node& node,
               const std::string& source) {
  const std::string full = "materials." + l.materials.list[k].name + "." + key;
  const KeySpec* spec = find_material_key(key);
  if (spec == nullptr)
    throw config_error(source, full, render_node(node), "unknown key (keys of a material: " + material_key_names() + ")");
  KeySpec named = *spec;
  named.name = full;
  field(l.materials.list[k], key) = std::get<double>(convert_value(named, node, source, render_node(node)));
  auto& given = l.given[k];
  if (std::find(given.begin(), given.end(), key) == given.end()) given.push_back(key);
}

bool given(const LayeringConfig& l, std::size_t k, std::string_view key) {
  return std::find(l.given[k].begin(), l.given[k].end(), key) != l.given[k].end();
}

}  // namespace

void take_layering(toml::table& root, const std::string& path, LayeringConfig& out) {
  if (toml::node* node = root.get("materials")) {
    const toml::table* table = node->as_table();
    if (table == nullptr)
      throw config_error(path, "materials", render_node(*node), "a table of materials: [materials.NAME] and its keys");
    // In file order (toml++ keeps keys sorted): material 0 is the first the file names.
    std::vector<std::pair<std::string, const toml::node*>> entries;
    for (const auto& [name, material] : *table) entries.emplace_back(std::string(name.str()), &material);
    std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
      const auto &ra = a.second->source().begin, &rb = b.second->source().begin;
      return std::pair(ra.line, ra.column) < std::pair(rb.line, rb.column);
    });
    for (const auto& [name, material] : entries) {
      const std::string src = path + ", line " + std::to_string(material->source().begin.line);
      const toml::table* keys = material->as_table();
      if (keys == nullptr)
        throw config_error(src, "materials." + name, render_node(*material),
                           "a table: write [materials." + name + "] and its keys below it");
      const std::size_t k = material_index(out, name, src);
      for (const auto& [key, value] : *keys)
        set_value(out, k, std::string(key.str()), value, path + ", line " + std::to_string(value.source().begin.line));
    }
    out.source = path;
    root.erase("materials");
  }
  toml::table* layer = root.get("layer") ? root.get("layer")->as_table() : nullptr;
  if (layer == nullptr || layer->get("units") == nullptr) return;
  const toml::node& units = *layer->get("units");
  const std::string src = path + ", line " + std::to_string(units.source().begin.line);
  const toml::array* list = units.as_array();
  if (list == nullptr || !list->is_array_of_tables())
    throw config_error(src, "layer.units", render_node(units),
                       "an array of tables: [[layer.units]] with material and thickness, one per unit from the base up");
  for (const auto& entry : *list) {
    const toml::table& unit = *entry.as_table();
    const std::string where = path + ", line " + std::to_string(entry.source().begin.line);
    for (const auto& [key, value] : unit)
      if (key.str() != "material" && key.str() != "thickness")
        throw config_error(where, "layer.units." + std::string(key.str()), render_node(value),
                           "unknown key (keys of a unit: material, thickness)");
    const auto material = unit["material"].value_exact<std::string>();
    if (!material)
      throw config_error(where, "layer.units.material", unit.get("material") ? render_node(*unit.get("material")) : "",
                         "required: the name of one of [materials] (" + material_names(out) + ")");
    std::size_t index = out.materials.size();
    for (std::size_t k = 0; k < out.materials.size(); ++k)
      if (out.materials.list[k].name == *material) index = k;
    if (index == out.materials.size())
      throw config_error(where, "layer.units.material", "\"" + *material + "\"",
                         "the name of one of [materials] (" + material_names(out) + ")");
    const toml::node* thickness = unit.get("thickness");
    if (thickness == nullptr) throw config_error(where, "layer.units.thickness", "", "required: a number > 0 [d]");
    KeySpec spec{"layer.units.thickness", KeyType::Float, 1.0, Bound{0, false}, std::nullopt, {}, ""};
    const double t = std::get<double>(convert_value(spec, *thickness, where, render_node(*thickness)));
    out.materials.units.push_back({index, t});
  }
  out.source = path;
  layer->erase("units");
}

bool is_material_override(std::string_view name) { return name.starts_with("materials."); }

void set_material_override(LayeringConfig& out, const std::string& name, const std::string& raw) {
  const std::string rest = name.substr(std::string_view("materials.").size());
  const auto dot = rest.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == rest.size())
    throw config_error(kSet, name, raw, "expected materials.NAME.KEY=value (keys: " + material_key_names() + ")");
  const std::size_t k = material_index(out, rest.substr(0, dot), std::string(kSet));
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + raw);
  } catch (const toml::parse_error&) {
  }
  const toml::node* node = parsed.size() == 1 ? parsed.get("v") : nullptr;
  if (node == nullptr) throw config_error(kSet, name, raw.empty() ? "\"\"" : raw, "expected a number");
  set_value(out, k, rest.substr(dot + 1), *node, std::string(kSet));
  if (out.source == "default") out.source = std::string(kSet);
}

void finish_layering(LayeringConfig& l, double layer_thickness, const std::string& thickness_source,
                     double rolling_friction) {
  for (std::size_t k = 0; k < l.materials.size(); ++k) {
    Material& m = l.materials.list[k];
    const std::string prefix = "materials." + m.name + ".";
    if (std::isnan(m.friction))
      throw config_error(l.source, prefix + "friction", "", "required: the material's peak Coulomb coefficient, >= 0");
    if (!given(l, k, "friction_residual")) m.friction_residual = m.friction;
    if (!given(l, k, "rolling_friction")) m.rolling_friction = rolling_friction;
    if (!given(l, k, "bond_shear_strength")) m.bond.shear_strength = m.bond.tensile_strength;
    if (m.friction_residual > m.friction)
      throw config_error(l.source, prefix + "friction_residual", format_float(m.friction_residual),
                         fmt::format("at most the peak friction ({}friction = {}): weakening lowers friction",
                                     prefix, format_float(m.friction)));
    if (m.bond.bonds() && (m.bond.tensile_strength <= 0 || m.bond.shear_strength <= 0)) {
      const bool tensile = m.bond.tensile_strength <= 0;
      throw config_error(l.source, prefix + (tensile ? "bond_tensile_strength" : "bond_shear_strength"), "0",
                         "> 0 for a material that bonds (both strengths > 0, or both 0 for no bonds)");
    }
  }
  if (l.materials.units.empty()) return;
  double total = 0;
  for (const auto& u : l.materials.units) total += u.thickness;
  if (total > layer_thickness * (1 + 1e-12))
    throw config_error(l.source, "layer.units", fmt::format("{} units, {} d in all", l.materials.units.size(), format_float(total)),
                       fmt::format("units that fit the layer: at most layer.thickness = {} d ({}) in all",
                                   format_float(layer_thickness), thickness_source));
}

std::string units_toml(const LayeringConfig& l) {
  if (l.materials.units.empty()) return "";
  std::string out = "# the incoming section from the base up: material and thickness [d] of each unit\nunits = [";
  for (std::size_t k = 0; k < l.materials.units.size(); ++k)
    out += fmt::format("{}{{ material = \"{}\", thickness = {} }}", k ? ", " : "",
                       l.materials.list[l.materials.units[k].material].name, format_float(l.materials.units[k].thickness));
  return out + "]\n";
}

std::string materials_toml(const LayeringConfig& l) {
  std::string out;
  for (const auto& m : l.materials.list) {
    out += "\n[materials." + m.name + "]\n";
    Material copy = m;
    for (const auto& spec : material_schema())
      out += "# " + spec.doc + "\n" + spec.name + " = " + format_float(field(copy, spec.name)) + "\n";
  }
  return out;
}

}  // namespace orogen
