// A wedge's step on one thread against N threads, in one process, in alternating blocks of
// steps on the same wedge: on a shared VM whose speed drifts by +-20% from one run to the
// next, only an A/B this close together resolves a 10% effect. Results do not depend on the
// thread count (the tests check it), so both step the same wedge on. Prints the time per step
// of each and the speed-up of N threads (median of the rounds' ratios).
//   bench_wedge_step [--config FILE] [--set KEY=VALUE ...] [--threads 2] [--warmup 20000]
//                    [--rounds 16] [--steps 3000]
// The default is the main job's wedge (no --config); docs/performance.md ("A faster wedge").
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "median.hpp"
#include "world/world.hpp"

int main(int argc, char** argv) {
  CLI::App app{"A wedge step on one thread against N, in one process"};
  std::optional<std::string> config_file;
  std::vector<std::string> sets;
  int threads = 2, rounds = 16, steps = 3000;
  long warmup = 20000;
  app.add_option("--config", config_file, "configuration file (default: the main job's)");
  app.add_option("--set", sets, "KEY=VALUE overrides, as orogen run --set");
  app.add_option("--threads", threads, "threads")->check(CLI::Range(2, 64));
  app.add_option("--warmup", warmup, "steps before timing")->check(CLI::NonNegativeNumber);
  app.add_option("--rounds", rounds, "rounds, each one block of steps per variant")->check(CLI::Range(1, 1000));
  app.add_option("--steps", steps, "steps per block")->check(CLI::Range(1, 10000000));
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<orogen::Experiment> experiment;
  orogen::World world;
  omp_set_num_threads(threads);
  try {  // bad keys and an unstable set-up end as `orogen run` ends them: exit 2 and 3
    const orogen::Config config =
        orogen::Config::load(config_file ? std::optional<std::filesystem::path>(*config_file) : std::nullopt, sets);
    experiment = orogen::make_experiment(config);
    orogen::apply_engine_config(config, world);
    experiment->setup(world);
  } catch (const orogen::ConfigError& e) {
    fmt::print(stderr, "bench_wedge_step: {}\n", e.what());
    return 2;
  } catch (const orogen::InstabilityError& e) {
    fmt::print(stderr, "bench_wedge_step: {}\n", e.what());
    return 3;
  }
  for (long s = 0; s < warmup && experiment->advance(world); ++s) {
  }
  std::vector<double> one, all, ratio;
  for (int r = 0; r < rounds; ++r) {
    double us[2];
    for (int k = 0; k < 2; ++k) {
      const bool single = (k + r) % 2 == 0;  // alternate which goes first
      omp_set_num_threads(single ? 1 : threads);
      const auto t0 = std::chrono::steady_clock::now();
      for (int s = 0; s < steps; ++s) {
        if (!experiment->advance(world)) {
          fmt::print(stderr, "bench_wedge_step: the run ended at step {}; ask for fewer --rounds or --steps\n",
                     world.step());
          return 2;
        }
      }
      const auto t1 = std::chrono::steady_clock::now();
      us[single ? 0 : 1] = std::chrono::duration<double, std::micro>(t1 - t0).count() / steps;
    }
    one.push_back(us[0]);
    all.push_back(us[1]);
    ratio.push_back(us[0] / us[1]);
    fmt::print("round {}: 1 thread {:.2f} us/step, {} threads {:.2f} us/step, {} discs\n", r + 1, us[0], threads,
               us[1], world.discs().size());
  }
  fmt::print("{} rounds of {} steps: median 1 thread {:.2f} us/step, {} threads {:.2f} us/step; speed-up median {:.3f}\n",
             rounds, steps, orogen::bench::median(one), threads, orogen::bench::median(all), orogen::bench::median(ratio));
  return 0;
}
