#pragma once
// `orogen analyze DIR`: the exhumation analysis of a wedge run (thesis chapter 6,
// docs/exhumation.md), finished or still running. Reads only the complete outputs that
// snapshots.h5 lists, never takes run.lock, and continues from DIR/analysis_state.bin so
// that a second call only adds the new outputs. Writes analysis.h5, analysis_flux.csv,
// analysis_columns.csv, analysis_removals.csv and analysis_state.bin, each atomically.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "exhumation/analysis_results.hpp"

namespace orogen {

// Options given on the command line; the others come from the run's [analysis] keys.
struct AnalyzeOptions {
  std::filesystem::path dir;
  std::optional<std::vector<double>> closure;
  std::optional<int> flux_window, particle_stride;
  std::optional<double> steady_fraction;
  std::optional<std::int64_t> trajectory_output;
  bool quiet = false;
};

class Config;

// The settings of a configuration's [analysis] keys; throws ConfigError naming
// analysis.closure_depths if it is not a list of numbers or the settings are bad.
AnalysisSettings analysis_settings(const Config& config);

// Throws ConfigError unless the [analysis] keys are good (checked for every run, since a later
// `orogen analyze` reads them) and, with analysis.in_run, the run is a wedge.
void check_in_run_analysis(const Config& config);

// The settings' problems, one message naming the option (`--closure-depths` or, with
// from_config, the key `analysis.closure_depths`), the value and what is allowed; empty if none.
std::string analysis_settings_error(const AnalysisSettings& s, bool from_config = false);

// "0.15,0.3" -> {0.15, 0.3}; nullopt if a cell is not a number.
std::optional<std::vector<double>> parse_closure_depths(const std::string& text);

// Exit codes: 0 done; 2 bad input (not a run folder, not a wedge run, a damaged
// snapshots.h5 or removals.csv, bad settings), nothing written; 1 an I/O failure.
int analyze_command(const AnalyzeOptions& options);

}  // namespace orogen
