// What a surface update costs against the wedge's steps (issue 40's target: under 5% of the
// steps between two updates at the default interval). One process, alternating blocks on the
// same wedge: `steps` time steps (World::advance, no surface laws), then `updates` surface
// updates of the configuration's [surface] laws on that world, over the whole layer (more
// columns than a run's, which starts one h0 before the pro window). Prints the time per step,
// per update, and the update's cost as a fraction of surface.every steps (medians of the rounds).
//   bench_surface [--config FILE] [--set KEY=VALUE ...] [--warmup 100000] [--rounds 9]
//                 [--steps 2000] [--updates 20]
// docs/performance.md ("Surface processes").
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/spec_from_config.hpp"
#include "median.hpp"
#include "surface/surface_processes.hpp"
#include "world/world.hpp"

int main(int argc, char** argv) {
  CLI::App app{"The cost of a surface update against the wedge's steps"};
  std::optional<std::string> config_file;
  std::vector<std::string> sets;
  int rounds = 9, steps = 2000, updates = 20;
  long warmup = 100000;
  app.add_option("--config", config_file, "configuration file (default: the main job's, with --set surface keys)");
  app.add_option("--set", sets, "KEY=VALUE overrides, as orogen run --set");
  app.add_option("--warmup", warmup, "steps before timing (a wedge to erode)")->check(CLI::NonNegativeNumber);
  app.add_option("--rounds", rounds, "rounds")->check(CLI::Range(1, 1000));
  app.add_option("--steps", steps, "time steps per round")->check(CLI::Range(1, 10000000));
  app.add_option("--updates", updates, "surface updates per round")->check(CLI::Range(1, 100000));
  CLI11_PARSE(app, argc, argv);

  omp_set_num_threads(1);
  std::unique_ptr<orogen::Experiment> experiment;
  orogen::World world;
  orogen::SurfaceSpec spec;
  double h0 = 0;
  try {
    const orogen::Config config =
        orogen::Config::load(config_file ? std::optional<std::filesystem::path>(*config_file) : std::nullopt, sets);
    experiment = orogen::make_experiment(config);
    orogen::apply_engine_config(config, world);
    experiment->setup(world);
    h0 = experiment->h0();
    spec = orogen::read_surface_keys(config, h0);
  } catch (const orogen::ConfigError& e) {
    fmt::print(stderr, "bench_surface: {}\n", e.what());
    return 2;
  }
  if (!spec.has_laws()) {
    fmt::print(stderr, "bench_surface: no surface law: --set surface.diffusivity=... or surface.erodibility=...\n");
    return 2;
  }
  for (long s = 0; s < warmup && experiment->advance(world); ++s) {
  }
  if (spec.column_width <= 0) spec.column_width = 2.3 * orogen::mean_radius(world.discs());
  orogen::SurfaceProcesses surface(spec, {0.4, 0.45, 0.5}, 1);
  const double dt = spec.every * world.dt();
  std::vector<double> step_us, update_us, fraction;
  for (int r = 0; r < rounds; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) world.advance();
    const auto t1 = std::chrono::steady_clock::now();
    const auto [lo, hi] = std::minmax_element(world.discs().x.begin(), world.discs().x.end());
    for (int u = 0; u < updates; ++u) surface.update(world, *lo, *hi, dt);
    const auto t2 = std::chrono::steady_clock::now();
    step_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() / steps);
    update_us.push_back(std::chrono::duration<double, std::micro>(t2 - t1).count() / updates);
    fraction.push_back(update_us.back() / (spec.every * step_us.back()));
    fmt::print("round {}: {:.1f} us/step, {:.1f} us/update, {:.3g}% of {} steps; {} discs\n", r + 1, step_us.back(),
               update_us.back(), 100 * fraction.back(), spec.every, world.discs().size());
  }
  fmt::print("{} rounds: median {:.1f} us/step, {:.1f} us/update; an update every {} steps costs {:.3g}% of them\n",
             rounds, orogen::bench::median(step_us), orogen::bench::median(update_us), spec.every,
             100 * orogen::bench::median(fraction));
  return 0;
}
