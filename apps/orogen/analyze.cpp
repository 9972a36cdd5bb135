// `orogen analyze DIR`: the exhumation analysis of a wedge run (src/exhumation/analyze_command).
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>

#include "exhumation/analyze_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_analyze(CLI::App& parent) {
  // The run's [analysis] keys unless an option is given: each option is read only when set.
  struct Options {
    AnalyzeOptions analyze;
    std::string dir, closure_text;
    int flux_window = 0, particle_stride = 0;
    double steady_fraction = 0;
    std::int64_t trajectory_output = 0;
    CLI::Option *closure = nullptr, *window = nullptr, *fraction = nullptr, *stride = nullptr,
                *trajectory = nullptr;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand("analyze", "exhumation analysis of a wedge run (finished or running): depths, "
                                               "closure-depth ages, erosion, flux steady state (docs/exhumation.md)");
  cmd->add_option("dir", o->dir, "run folder")->required();
  o->closure = cmd->add_option(
      "--closure-depths", o->closure_text,
      "closure depths h_i below the surface [h0], ascending, comma-separated (default: the run's analysis.closure_depths)");
  o->window = cmd->add_option("--flux-window", o->flux_window,
                              "outputs averaged by the flux steady-state rule (default: analysis.flux_window)")
                  ->check(not_empty());
  o->fraction = cmd->add_option("--steady-fraction", o->steady_fraction,
                                "averaged eroded flux / incoming flux v h0 that counts as steady "
                                "(default: analysis.steady_fraction)")
                    ->check(not_empty());
  o->stride = cmd->add_option("--particle-stride", o->particle_stride,
                              "per-particle series keep the ids divisible by this "
                              "(default: analysis.particle_stride)")
                  ->check(not_empty());
  o->trajectory = cmd->add_option("--trajectory-output", o->trajectory_output,
                                  "trace back the surface particles of this output (default -1: the last)")
                      ->check(not_empty());
  return {cmd, [o] {
            AnalyzeOptions& analyze = o->analyze;
            analyze.dir = o->dir;
            if (o->closure->count() > 0) {
              analyze.closure = parse_closure_depths(o->closure_text);
              if (!analyze.closure) {
                std::cerr << "error: --closure-depths " << o->closure_text
                          << ": not a comma-separated list of numbers; give depths in h0, e.g. 0.15,0.3,0.5\n";
                return 2;
              }
            }
            if (o->window->count() > 0) analyze.flux_window = o->flux_window;
            if (o->fraction->count() > 0) analyze.steady_fraction = o->steady_fraction;
            if (o->stride->count() > 0) analyze.particle_stride = o->particle_stride;
            if (o->trajectory->count() > 0) analyze.trajectory_output = o->trajectory_output;
            return analyze_command(analyze);
          }};
}

}  // namespace orogen::cli
