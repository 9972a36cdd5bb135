#pragma once
// DIR/analysis_state.bin: what `orogen analyze` needs to continue with the outputs a run adds
// later (the tracker, the per-output summary and the extent of the files it appends to), in
// the checkpoint archive format, written atomically: it is the truth of how many outputs are
// complete. A state made with other settings, or for another run, is not used.
#include <filesystem>
#include <optional>
#include <string>

#include "exhumation/analysis_results.hpp"

namespace orogen {

struct AnalysisState {
  std::string run_identity;
  AnalysisResults results;
  ExhumationTracker tracker{ExhumationParams{}};
};

void save_analysis_state(const std::filesystem::path& path, const AnalysisState& state);
// Throws (a message naming the file) if it is unreadable or damaged.
AnalysisState load_analysis_state(const std::filesystem::path& path);

}  // namespace orogen
