// The registry of experiments: run.experiment names one; adding an experiment adds a line here.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/packing_experiment.hpp"
#include "experiments/wedge_experiment.hpp"

namespace orogen {
namespace {

// Thesis eq. 4.3: the plate must move less per step than the gravitational contact overlap,
// v dt < m g / k_n, for the smallest disc.
void check_convergence_step(const Config& c, const WedgeSpec& w) {
  const double kn = c.get_float("contact.kn");
  const double d_min = c.get_float("particles.d_min");
  const double m_min = std::numbers::pi * 0.25 * d_min * d_min;
  const double limit = stable_time_step(kn, 0.5 * m_min);
  const double dt = c.get_float("time.dt") > 0 ? c.get_float("time.dt") : c.get_float("time.dt_fraction") * limit;
  const double overlap = m_min / kn;
  if (dt > limit) return;  // apply_engine_config refuses the time step itself
  if (w.v * dt >= overlap)
    throw config_error(c.source_of("wedge.speed"), "wedge.speed", fmt::format("{}", w.v),
                       fmt::format("the plate would move {:.3g} d per step, more than the gravitational contact "
                                   "overlap m g / k_n = {:.3g} d of the smallest disc (thesis eq. 4.3); "
                                   "use wedge.speed < {:.4g}, or a smaller time.dt",
                                   w.v * dt, overlap, overlap / dt));
}

PackingSpec packing_spec(const Config& c) {
  PackingSpec p;
  p.kind = packing_kind_from_name(c.get_string("particles.packing"));
  p.length = c.get_float("layer.length");
  p.thickness = c.get_float("layer.thickness");
  p.d_min = c.get_float("particles.d_min");
  p.d_max = c.get_float("particles.d_max");
  p.seed = static_cast<std::uint64_t>(c.get_int("run.seed"));
  p.mu_wall = c.get_float("contact.mu_wall");
  if (p.d_min > p.d_max)
    throw config_error(c.source_of("particles.d_min"), "particles.d_min", fmt::format("{}", p.d_min),
                       fmt::format("must not exceed particles.d_max = {}", p.d_max));
  return p;
}

SettleSpec settle_spec(const Config& c) {
  SettleSpec s;
  s.drag = c.get_float("settle.drag");
  s.ke_threshold = c.get_float("settle.ke_threshold");
  s.max_time = c.get_float("settle.max_time");
  s.relax_time = c.get_float("settle.relax_time");
  s.mu = c.get_float("settle.mu");
  s.column_width_factor = c.get_float("layer.column_width_factor");
  return s;
}

std::unique_ptr<Experiment> make_packing(const Config& c) {
  return std::make_unique<PackingExperiment>(packing_spec(c), settle_spec(c));
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
  w.outputs = static_cast<int>(c.get_int("wedge.outputs"));
  w.window = c.get_float("wedge.window");
  w.retro_length = c.get_float("wedge.retro_length");
  w.initial_active = c.get_float("wedge.initial_active");
  w.tile_length = c.get_float("wedge.tile_length");
  w.erosion_height = c.get_float("wedge.erosion_height");
  w.erosion_every = static_cast<int>(c.get_int("wedge.erosion_every"));
  w.marker_height = c.get_float("wedge.marker_height");
  w.column_width_factor = c.get_float("layer.column_width_factor");
  w.packing_file = c.get_string("wedge.packing_file");
  w.packing = packing_spec(c);
  w.settle = settle_spec(c);
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
                         std::string("an existing packing.h5 written by a packing run (") + e.what() + ")");
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
  check_convergence_step(c, w);
  return std::make_unique<WedgeExperiment>(std::move(w));
}

}  // namespace

std::unique_ptr<Experiment> make_experiment(const Config& c) {
  const auto& name = c.get_string("run.experiment");
  if (name == "packing") return make_packing(c);
  if (name == "wedge") return make_wedge(c);
  throw config_error(c.source_of("run.experiment"), "run.experiment", name, "one of: packing, wedge");
}

}  // namespace orogen
