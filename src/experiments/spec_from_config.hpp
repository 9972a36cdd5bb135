#pragma once
// The [particles], [layer] and [settle] sections read into the specs every experiment that
// builds a settled packing uses (cross-key checks throw ConfigError).
#include <string>
#include <string_view>
#include <vector>

#include "boundary/wall.hpp"
#include "experiments/packing_experiment.hpp"
#include "isostasy/isostasy_spec.hpp"

namespace orogen {

class Config;

PackingSpec packing_spec(const Config& config);
SettleSpec settle_spec(const Config& config);

// The keys every experiment that settles a layer reads the same way: its spec's packing and
// settle parts and, where the spec has one, its surface column width.
template <class Spec>
void read_layer_keys(const Config& config, Spec& spec) {
  spec.packing = packing_spec(config);
  spec.settle = settle_spec(config);
  if constexpr (requires { spec.column_width_factor; }) spec.column_width_factor = spec.settle.column_width_factor;
}

// [section].basal_weakening and basal_weakening_distance; a weakening base needs the disc slip
// that a world of materials keeps ([materials.NAME]), else ConfigError naming the key.
BaseWeakening base_weakening(const Config& config, std::string_view section);

// The index in [materials] of the material the string key names; -1 when it is empty. A name
// [materials] does not hold is a ConfigError naming the key and the names there are.
std::ptrdiff_t material_named_by(const Config& config, const std::string& key);

// The [surface] keys (surface_from_config.cpp), lengths from h0 units to d, the sediment's
// material as its index in [materials].
SurfaceSpec read_surface_keys(const Config& config, double h0);

// The [isostasy] keys (isostasy_from_config.cpp), lengths from h0 units to d and the rigidity
// from rho g h0^4 to rho g d^4.
IsostasySpec read_isostasy_keys(const Config& config, double h0);

// Refuses (ConfigError) material of length x thickness [d] whose estimated disc count, or whose
// number of surface columns, is above kMaxParticles (or not finite), before anything is
// allocated; the message names size_keys (the keys the size comes from) and the disc sizes.
void check_material_size(const Config& config, double length, double thickness,
                         const std::vector<std::string_view>& size_keys);

// Thesis eq. 4.3: the constant-velocity base must move less per step than the gravitational
// contact overlap m g / k_n of the smallest disc (the speed is the value of `key`). The excess
// as a message naming the keys, or empty when the speed keeps the bound; check_imposed_speed
// throws ConfigError with it. For a backstop it is a quasi-static rule, not a stability limit
// (docs/model.md, "Singly-vergent critical wedge"): singly.speed_bound picks what it does.
std::string imposed_speed_excess(const Config& config, const std::string& key);
void check_imposed_speed(const Config& config, const std::string& key);

// What the configuration allows but the log should say (the run driver logs each line): a
// singly.speed above the bound with singly.speed_bound = "warn".
std::vector<std::string> config_warnings(const Config& config);

}  // namespace orogen
