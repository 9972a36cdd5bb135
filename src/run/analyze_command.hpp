#pragma once
// `orogen analyze DIR`: the exhumation analysis of a wedge run (thesis chapter 6,
// docs/exhumation.md), finished or still running. Reads only the complete outputs that
// snapshots.h5 lists, never takes run.lock, and continues from DIR/analysis_state.bin so
// that a second call only adds the new outputs. Writes analysis.h5, analysis_flux.csv,
// analysis_columns.csv, analysis_removals.csv and analysis_state.bin, each atomically.
#include <filesystem>

#include "exhumation/analysis_results.hpp"

namespace orogen {

struct AnalyzeOptions {
  std::filesystem::path dir;
  AnalysisSettings settings;
  bool quiet = false;
};

// The settings' problems, one message naming the option, the value and what is allowed;
// empty if none.
std::string analysis_settings_error(const AnalysisSettings& s);

// Exit codes: 0 done; 2 bad input (not a run folder, not a wedge run, a damaged
// snapshots.h5 or removals.csv, bad settings), nothing written; 1 an I/O failure.
int analyze_command(const AnalyzeOptions& options);

}  // namespace orogen
