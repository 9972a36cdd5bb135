#pragma once
// The layout of analysis.h5 (docs/output-files.md): labelled for xarray, every dataset
// extendible, so that each output adds its rows (time x column, time x particle) to the file
// on disk and only the small whole-run parts (flux, removals, trajectories, attributes) are
// rewritten at the end of a call.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "exhumation/analysis_results.hpp"

namespace orogen {

// Creates the datasets, empty, and the fixed coordinates (column, closure).
void create_analysis_h5(hid_t root, const std::string& run_identity, const AnalysisResults& res,
                        const ExhumationParams& p);

// Checks that the file continues `res` (same run, settings and grid; at least the outputs and
// discs the state counts); throws h5::Error saying what does not match. True if it holds rows
// beyond the state's counts (left by a call killed before it saved its state).
bool check_analysis_h5(hid_t root, const std::string& run_identity, const AnalysisResults& res,
                       const ExhumationParams& p);
// Cuts the time and particle dimensions back to the state's counts.
void trim_analysis_h5(hid_t root, const AnalysisResults& res);

// Appends output `t` (== res.outputs.size() before the call): its summary to `res`, new disc
// ids to res.particle_ids and `slot` (id -> index along the particle dimension), its rows to
// the file.
void append_analysis_h5(hid_t root, const OutputRecord& r, AnalysisResults& res,
                        std::unordered_map<std::int64_t, std::size_t>& slot, const ExhumationParams& p);

// Rewrites the parts that depend on the whole run so far: flux balance, removals,
// trajectories (read back from the file) and the root attributes.
void finish_analysis_h5(hid_t root, const AnalysisResults& res, const std::unordered_map<std::int64_t, std::size_t>& slot,
                        const ExhumationTracker& tracker);

}  // namespace orogen
