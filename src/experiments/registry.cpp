// The registry of experiments: run.experiment names one; adding an experiment adds a line here.
#include <fmt/format.h>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/packing_experiment.hpp"

namespace orogen {
namespace {

std::unique_ptr<Experiment> make_packing(const Config& c) {
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
  SettleSpec s;
  s.drag = c.get_float("settle.drag");
  s.ke_threshold = c.get_float("settle.ke_threshold");
  s.max_time = c.get_float("settle.max_time");
  s.relax_time = c.get_float("settle.relax_time");
  s.column_width_factor = c.get_float("layer.column_width_factor");
  return std::make_unique<PackingExperiment>(p, s);
}

}  // namespace

std::unique_ptr<Experiment> make_experiment(const Config& c) {
  const auto& name = c.get_string("run.experiment");
  if (name == "packing") return make_packing(c);
  throw config_error(c.source_of("run.experiment"), "run.experiment", name, "one of: packing");
}

}  // namespace orogen
