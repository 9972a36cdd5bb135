// The [isostasy] keys read into an IsostasySpec (docs/isostasy.md), with the checks across keys.
#include <fmt/format.h>

#include <cmath>

#include "config/config.hpp"
#include "experiments/spec_from_config.hpp"
#include "isostasy/plate_flexure.hpp"

namespace orogen {
namespace {

// The plate's solve reaches four flexural parameters beyond the model on each side; farther
// than this, the base would bend under loads the model does not hold.
constexpr double kMaxFlexuralParameter = 50;  // [h0]

}  // namespace

IsostasySpec read_isostasy_keys(const Config& c, double h0) {
  IsostasySpec s;
  const std::string model = c.get_string("isostasy.model");
  s.model = model == "airy" ? IsostasyModel::Airy : model == "flexure" ? IsostasyModel::Flexure : IsostasyModel::None;
  s.mantle_density = c.get_float("isostasy.mantle_density");
  const double rigidity = c.get_float("isostasy.rigidity");
  s.rigidity = rigidity * std::pow(h0, 4);
  s.every = c.get_int32("isostasy.every");
  s.segment_length = c.get_float("isostasy.segment_length") * h0;
  s.airy_width = 2 * h0;
  const auto both = c.sources_of({"isostasy.rigidity", "isostasy.model"});
  if (s.model == IsostasyModel::Flexure && rigidity == 0)
    throw config_error(both, "isostasy.rigidity", format_float(rigidity),
                       "greater than 0 with isostasy.model = \"flexure\" (a plate without rigidity is Airy's local "
                       "balance: set isostasy.model = \"airy\")");
  if (s.model != IsostasyModel::Flexure && rigidity != 0)
    throw config_error(both, "isostasy.rigidity", format_float(rigidity),
                       "0 unless isostasy.model = \"flexure\": only the elastic plate has a rigidity");
  if (s.model == IsostasyModel::Flexure) {
    const double alpha = flexural_parameter(rigidity, s.mantle_density);
    if (alpha > kMaxFlexuralParameter)
      throw config_error(
          both, "isostasy.rigidity", format_float(rigidity),
          fmt::format("at most {} with isostasy.mantle_density = {}: this plate spreads a load over a flexural "
                      "parameter of {:.3g} h0, and its base would bend {:.3g} h0 beyond the model (the solve "
                      "reaches at most {} h0, four flexural parameters of {} h0)",
                      format_float(s.mantle_density * std::pow(kMaxFlexuralParameter, 4) / 4),
                      format_float(s.mantle_density), alpha, 4 * alpha, 4 * kMaxFlexuralParameter,
                      kMaxFlexuralParameter));
  }
  if (s.active() && s.every % 100 != 0)
    throw config_error(c.source_of("isostasy.every"), "isostasy.every", std::to_string(s.every),
                       "a multiple of 100 (the wedge moves its kinematic slab onto the base every 100 steps)");
  return s;
}

}  // namespace orogen
