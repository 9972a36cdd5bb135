// The wedge's factory: its keys read into a WedgeSpec, with the checks across keys.
#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "config/config.hpp"
#include "experiments/spec_from_config.hpp"
#include "experiments/wedge_experiment.hpp"

namespace orogen {
namespace {

// The material a wedge run holds at its end: the retro-side layer, the pro-side stretch, the
// convergence fed in (S h0) and the kinematic slab's tiles (two tile lengths at most).
void check_wedge_size(const Config& c, const WedgeSpec& w) {
  const double length =
      (w.retro_length + std::max(w.window, w.initial_active) + w.s_end + 2 * w.tile_length) * w.h0 +
      2 * WedgeExperiment::tile_margin_for(w.h0);
  check_material_size(c, length, w.h0,
                      {"layer.thickness", "wedge.retro_length", "wedge.window", "wedge.initial_active",
                       "wedge.s_end", "wedge.tile_length"});
}

// Reads the packing file now, so that a wrong file is a configuration error before anything
// is written.
void check_packing_file(const Config& c, const WedgeSpec& w) {
  std::string problem;
  try {
    problem = WedgeExperiment::tile_problem(load_tile(w.packing_file), w.h0);
  } catch (const std::exception& e) {
    problem = std::string("must be the packing.h5 of a packing run: ") + e.what();
  }
  if (!problem.empty()) throw config_error(c.source_of("wedge.packing_file"), "wedge.packing_file", w.packing_file, problem);
}

// gamma_b is eq. 4.1's drag coefficient: under the Coulomb belt it would change nothing, so a
// value set away from its default there is a mistake (an older configuration that tunes the
// drag), not a silent no-op.
void check_drag_coefficient(const Config& c, const WedgeSpec& w) {
  const auto& spec = schema()[*find_key("wedge.gamma_b")];
  if (w.basal != BasalCondition::Traction || w.traction_law != TractionLaw::Spring ||
      w.gamma_b == std::get<double>(spec.default_value))
    return;
  throw config_error(c.source_of("wedge.gamma_b"), "wedge.gamma_b", format_float(w.gamma_b),
                     "acts only with wedge.traction_law = \"drag\" (eq. 4.1's drag); this run's pro plate is the "
                     "Coulomb belt (\"spring\", the default), which has no drag coefficient: set "
                     "wedge.traction_law = \"drag\" or leave wedge.gamma_b out");
}

}  // namespace

std::unique_ptr<Experiment> make_wedge_experiment(const Config& c) {
  WedgeSpec w;
  w.basal = c.get_string("wedge.basal") == "traction" ? BasalCondition::Traction : BasalCondition::ConstantVelocity;
  w.h0 = c.get_float("layer.thickness");
  w.v = c.get_float("wedge.speed");
  w.mu_bp = c.get_float("wedge.mu_bp");
  w.mu_br = c.get_float("wedge.mu_br");
  w.base_weakening = base_weakening(c, "wedge");
  w.traction_law = c.get_string("wedge.traction_law") == "drag" ? TractionLaw::Drag : TractionLaw::Spring;
  w.fronts = c.get_string("wedge.fronts") == "discs" ? FrontRule::Discs : FrontRule::Surface;
  w.gamma_b = c.get_float("wedge.gamma_b");
  w.s_end = c.get_float("wedge.s_end");
  w.outputs = c.get_int32("wedge.outputs");
  w.window = c.get_float("wedge.window");
  w.retro_length = c.get_float("wedge.retro_length");
  w.initial_active = c.get_float("wedge.initial_active");
  w.tile_length = c.get_float("wedge.tile_length");
  w.erosion_height = c.get_float("wedge.erosion_height");
  w.erosion_every = c.get_int32("wedge.erosion_every");
  w.analysis_in_run = c.get_bool("analysis.in_run");
  w.analysis_every = c.get_int("analysis.every");
  w.marker_height = c.get_float("wedge.marker_height");
  w.packing_file = c.get_string("wedge.packing_file");
  read_layer_keys(c, w);
  w.surface = read_surface_keys(c, w.h0);
  w.isostasy = read_isostasy_keys(c, w.h0);
  check_wedge_size(c, w);
  check_drag_coefficient(c, w);
  if (!w.packing_file.empty()) check_packing_file(c, w);
  check_imposed_speed(c, "wedge.speed");
  return std::make_unique<WedgeExperiment>(std::move(w));
}

}  // namespace orogen
