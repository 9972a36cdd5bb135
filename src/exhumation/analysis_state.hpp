#pragma once
// DIR/analysis_state.bin: what `orogen analyze` needs to continue with the outputs a run adds
// later (the tracker and the records so far), in the checkpoint archive format, written
// atomically. A state made with other settings, or for another run, is not used.
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
