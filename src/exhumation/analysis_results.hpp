#pragma once
// What `orogen analyze` keeps of a run between calls: the settings, the per-output summary
// and the bookkeeping of the files it appends to. The time x particle and time x column
// series are not kept: each output's record goes to the files and is dropped.
#include <cstdint>
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

// The per-output values the flux balance and the time axis need.
struct OutputSummary {
  std::int64_t step = 0;
  double time = 0, S = 0;
  double eroded_area = 0;
  std::int64_t eroded_count = 0;
};

struct AnalysisResults {
  AnalysisSettings settings;
  double flux_in = 0;  // incoming solid area flux v h0 phi0 [d^2 / time]
  double v = 0, solid_fraction = 0;
  std::vector<OutputSummary> outputs;       // one per output analysed; its size is the count complete
  std::vector<std::int64_t> particle_ids;   // analysis.h5's particle dimension, in order of first appearance
  std::uint64_t columns_csv_bytes = 0;      // length of analysis_columns.csv holding those outputs
};

}  // namespace orogen
