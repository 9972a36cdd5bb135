#pragma once
// Everything `orogen analyze` has computed so far for one run: the tracker (to continue with
// later outputs) and the records of the outputs seen, and the files made from them.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "exhumation/exhumation_tracker.hpp"

namespace orogen {

struct AnalysisSettings {
  std::vector<double> closure = {0.15, 0.3, 0.5, 0.7, 0.9};  // [h0], ascending, within (0, 1]
  int flux_window = 10;           // outputs averaged by the flux steady-state rule
  double steady_fraction = 0.9;   // eroded flux / incoming flux that counts as steady
  int particle_stride = 1;        // per-particle series: ids divisible by this
  std::int64_t trajectory_output = -1;  // surface particles traced back from this output (-1: last)
};

struct AnalysisResults {
  AnalysisSettings settings;
  double flux_in = 0;  // incoming solid area flux v h0 phi0 [d^2 / time]
  double v = 0, solid_fraction = 0;
  std::vector<OutputRecord> records;
};

// DIR/analysis.h5 (built in memory, written atomically) and the CSV tables beside it.
void write_analysis_files(const std::filesystem::path& dir, const AnalysisResults& results,
                          const ExhumationTracker& tracker);

}  // namespace orogen
