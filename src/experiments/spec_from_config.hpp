#pragma once
// The [particles], [layer] and [settle] sections read into the specs every experiment that
// builds a settled packing uses (cross-key checks throw ConfigError).
#include <string>

#include "experiments/packing_experiment.hpp"

namespace orogen {

class Config;

PackingSpec packing_spec(const Config& config);
SettleSpec settle_spec(const Config& config);

// Thesis eq. 4.3: a boundary that pushes the material (a plate, a backstop) must move less per
// step than the gravitational contact overlap m g / k_n of the smallest disc; the speed is the
// value of `key`. Throws ConfigError otherwise.
void check_imposed_speed(const Config& config, const std::string& key);

}  // namespace orogen
