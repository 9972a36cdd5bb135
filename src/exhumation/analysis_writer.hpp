#pragma once
// The files of one `orogen analyze` call, written output by output (docs/exhumation.md,
// "Files and crash safety"). A fresh analysis builds analysis.h5 and analysis_columns.csv
// under temporary names and renames them into place at commit(); a continued one appends to
// them in place, first cutting off what lies beyond the state's counts (rows of a call killed
// after it closed the files). A file killed while open for writing (root attribute
// `incomplete` = 1) is not continued: the analysis starts over. Either way
// analysis_state.bin, saved by the caller after commit(), is the truth of how many outputs
// are complete. Without commit() the destructor undoes what it can: the
// temporary files are removed, the rows appended in place are cut off again.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "exhumation/analysis_results.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace orogen {

class AnalysisWriter {
 public:
  // Continues the files in `dir` at the counts of `res`; throws (naming what does not match)
  // if they are missing or do not continue it. Nothing is changed until append() or commit().
  static AnalysisWriter resume(const std::filesystem::path& dir, const std::string& run_identity,
                               AnalysisResults& res, const ExhumationParams& p);
  // New files, for `res` with no outputs yet.
  static AnalysisWriter fresh(const std::filesystem::path& dir, const std::string& run_identity,
                              AnalysisResults& res, const ExhumationParams& p);
  AnalysisWriter(AnalysisWriter&&) noexcept;
  ~AnalysisWriter();

  // One output: its summary to `res`, its rows to analysis.h5 and analysis_columns.csv.
  void append(const OutputRecord& r);
  // The whole-run parts (flux, removals, trajectories; analysis_flux.csv and
  // analysis_removals.csv), then the files flushed to disk and, if new, renamed into place.
  void commit(const ExhumationTracker& tracker);

 private:
  struct Impl;
  explicit AnalysisWriter(std::unique_ptr<Impl> impl);
  void open_for_writing();
  std::unique_ptr<Impl> impl_;
};

}  // namespace orogen
