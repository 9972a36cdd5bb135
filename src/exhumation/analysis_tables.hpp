#pragma once
// The CSV tables beside analysis.h5 (series format: '#' lines say what each column is):
// analysis_columns.csv grows by the rows of each output; analysis_flux.csv and
// analysis_removals.csv are small and rewritten whole, atomically.
#include <filesystem>
#include <string>

#include "exhumation/analysis_results.hpp"

namespace orogen {

std::string columns_csv_header(const ExhumationParams& p);
// The rows of output `t` (one per column).
std::string columns_csv_rows(std::size_t t, const OutputRecord& r, const ExhumationParams& p);

void write_flux_csv(const std::filesystem::path& path, const AnalysisResults& res);
void write_removals_csv(const std::filesystem::path& path, const ExhumationTracker& tracker);

}  // namespace orogen
