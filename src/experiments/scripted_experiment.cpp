#include "experiments/scripted_experiment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "config/config.hpp"
#include "experiments/series_table.hpp"
#include "util/units.hpp"

namespace orogen {
namespace {

double mean_kinetic_energy(const World& w) {
  if (w.discs().size() == 0) return 0;
  return w.kinetic_energy() / static_cast<double>(w.discs().size()) / kUnitDiscMass;
}

}  // namespace

bool ScriptedExperiment::advance(World& w) {
  // The output grid's own tolerance, so that the last step lands on the last output.
  const double end = spec_.duration - 1e-9 * spec_.duration / spec_.outputs;
  if (w.time() >= end) return false;
  w.advance();
  return w.time() < end;
}

namespace {

// One output's measurements, in the units of series.csv (kSeries names each field's column).
struct ScriptedSample {
  double step, time, n_discs, n_removed, kinetic_energy, x_min, x_max, y_max;
};

using Entry = SeriesEntry<ScriptedSample>;
constexpr std::array kSeries = {
    Entry{"step", "-", "model time step", &ScriptedSample::step},
    Entry{"time", "sqrt(d/g)", "model time", &ScriptedSample::time},
    Entry{"n_discs", "-", "discs in the world", &ScriptedSample::n_discs},
    Entry{"n_removed", "-", "discs removed so far (removals.csv says why)", &ScriptedSample::n_removed},
    Entry{"kinetic_energy", "m g d", "mean kinetic energy per disc", &ScriptedSample::kinetic_energy},
    Entry{"x_min", "d", "left edge of the leftmost disc (NaN without discs)", &ScriptedSample::x_min},
    Entry{"x_max", "d", "right edge of the rightmost disc (NaN without discs)", &ScriptedSample::x_max},
    Entry{"y_max", "d", "top of the highest disc (NaN without discs)", &ScriptedSample::y_max},
};

}  // namespace

std::vector<SeriesColumn> ScriptedExperiment::columns() const { return series_columns(kSeries); }

std::vector<double> ScriptedExperiment::measure(const World& w) const {
  const auto& d = w.discs();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double x_min = nan, x_max = nan, y_max = nan;
  for (std::size_t i = 0; i < d.size(); ++i) {
    x_min = i ? std::min(x_min, d.x[i] - d.radius[i]) : d.x[i] - d.radius[i];
    x_max = i ? std::max(x_max, d.x[i] + d.radius[i]) : d.x[i] + d.radius[i];
    y_max = i ? std::max(y_max, d.y[i] + d.radius[i]) : d.y[i] + d.radius[i];
  }
  const ScriptedSample sample{.step = static_cast<double>(w.step()),
                              .time = w.time(),
                              .n_discs = static_cast<double>(d.size()),
                              .n_removed = static_cast<double>(w.removals().size()),
                              .kinetic_energy = mean_kinetic_energy(w),
                              .x_min = x_min,
                              .x_max = x_max,
                              .y_max = y_max};
  return series_values(kSeries, sample);
}

std::string ScriptedExperiment::status(const World& w) const {
  return fmt::format("t = {:.4g} of {:.4g}, {} discs, KE/disc {:.2e}", w.time(), spec_.duration, w.discs().size(),
                     mean_kinetic_energy(w));
}

// Everything the user built: the discs and the walls that are switched on, with a disc of margin.
std::array<double, 4> ScriptedExperiment::view_box(const World& w) const {
  const double inf = std::numeric_limits<double>::infinity();
  std::array<double, 4> box{inf, -inf, inf, -inf};
  auto take = [&box](double x0, double x1, double y0, double y1) {
    box = {std::min(box[0], x0), std::max(box[1], x1), std::min(box[2], y0), std::max(box[3], y1)};
  };
  const auto& d = w.discs();
  for (std::size_t i = 0; i < d.size(); ++i)
    take(d.x[i] - d.radius[i], d.x[i] + d.radius[i], d.y[i] - d.radius[i], d.y[i] + d.radius[i]);
  for (const auto& wall : w.walls())
    if (wall.enabled)
      take(std::min(wall.ax, wall.bx), std::max(wall.ax, wall.bx), std::min(wall.ay, wall.by),
           std::max(wall.ay, wall.by));
  if (!(box[0] <= box[1])) return {-1.0, 1.0, -1.0, 1.0};  // nothing built
  return {box[0] - 1.0, box[1] + 1.0, box[2] - 1.0, box[3] + 1.0};
}

std::unique_ptr<Experiment> make_scripted_experiment(const Config& c) {
  ScriptedSpec s;
  s.duration = c.get_float("scripted.duration");
  s.outputs = c.get_int32("scripted.outputs");
  // A scripted run has no other end, and no default could fit what the user builds.
  if (!(s.duration > 0))
    throw config_error(c.source_of("scripted.duration"), "scripted.duration", format_value(ConfigValue{s.duration}),
                       "the model time the scripted run lasts, > 0 (it has no default): set it, e.g. "
                       "--set scripted.duration=50");
  return std::make_unique<ScriptedExperiment>(s);
}

}  // namespace orogen
