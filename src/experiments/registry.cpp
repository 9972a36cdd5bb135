// The registry of experiments: run.experiment names one; adding an experiment adds a line here.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/biaxial_experiment.hpp"
#include "experiments/packing_experiment.hpp"
#include "experiments/repose_experiment.hpp"
#include "experiments/singly_vergent_experiment.hpp"
#include "experiments/spec_from_config.hpp"
#include "experiments/wedge_experiment.hpp"

namespace orogen {
namespace {

std::unique_ptr<Experiment> make_packing(const Config& c) {
  check_material_size(c, c.get_float("layer.length"), c.get_float("layer.thickness"),
                      {"layer.length", "layer.thickness"});
  return std::make_unique<PackingExperiment>(packing_spec(c), settle_spec(c), c.to_toml());
}

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

std::unique_ptr<Experiment> make_wedge(const Config& c) {
  WedgeSpec w;
  w.basal = c.get_string("wedge.basal") == "traction" ? BasalCondition::Traction : BasalCondition::ConstantVelocity;
  w.h0 = c.get_float("layer.thickness");
  w.v = c.get_float("wedge.speed");
  w.mu_bp = c.get_float("wedge.mu_bp");
  w.mu_br = c.get_float("wedge.mu_br");
  w.gamma_b = c.get_float("wedge.gamma_b");
  w.s_end = c.get_float("wedge.s_end");
  w.outputs = c.get_int32("wedge.outputs");
  w.window = c.get_float("wedge.window");
  w.retro_length = c.get_float("wedge.retro_length");
  w.initial_active = c.get_float("wedge.initial_active");
  w.tile_length = c.get_float("wedge.tile_length");
  w.erosion_height = c.get_float("wedge.erosion_height");
  w.erosion_every = c.get_int32("wedge.erosion_every");
  w.marker_height = c.get_float("wedge.marker_height");
  w.column_width_factor = c.get_float("layer.column_width_factor");
  w.packing_file = c.get_string("wedge.packing_file");
  w.packing = packing_spec(c);
  w.settle = settle_spec(c);
  check_wedge_size(c, w);
  if (!w.packing_file.empty()) {
    // Read it now, so that a wrong file is a configuration error before anything is written.
    const double needed = w.h0 + 2 * WedgeExperiment::tile_margin_for(w.h0);
    double length = 0, thickness = 0;
    try {
      const Tile tile = load_tile(w.packing_file);
      length = tile.length;
      thickness = tile.thickness;
    } catch (const std::exception& e) {
      throw config_error(c.source_of("wedge.packing_file"), "wedge.packing_file", w.packing_file,
                         std::string("must be the packing.h5 of a packing run: ") + e.what());
    }
    if (std::fabs(thickness - w.h0) > 1e-9 * w.h0)
      throw config_error(c.source_of("wedge.packing_file"), "wedge.packing_file", w.packing_file,
                         fmt::format("a packing as thick as layer.thickness = {} (this one is {} thick: set "
                                     "layer.thickness = {})",
                                     w.h0, thickness, thickness));
    if (length < needed)
      throw config_error(c.source_of("wedge.packing_file"), "wedge.packing_file", w.packing_file,
                         fmt::format("a packing at least {} d long for layer.thickness = {} (this one is {} d)",
                                     needed, w.h0, length));
  }
  check_imposed_speed(c, "wedge.speed");
  return std::make_unique<WedgeExperiment>(std::move(w));
}

}  // namespace

std::unique_ptr<Experiment> make_experiment(const Config& c) {
  const auto& name = c.get_string("run.experiment");
  if (name == "packing") return make_packing(c);
  if (name == "wedge") return make_wedge(c);
  if (name == "repose") return make_repose_experiment(c);
  if (name == "singly_vergent") return make_singly_vergent_experiment(c);
  if (name == "biaxial") return make_biaxial_experiment(c);
  throw config_error(c.source_of("run.experiment"), "run.experiment", name,
                     "one of: packing, wedge, repose, singly_vergent, biaxial");
}

}  // namespace orogen
