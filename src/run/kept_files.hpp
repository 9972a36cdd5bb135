#pragma once
// A resume keeps the files a run wrote up to its checkpoint; each must be of that run, or the
// resumed run would carry another run's results under its name. The checks read every kept
// file and change none, so a refused resume leaves the folder as it was.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/csv_series.hpp"
#include "world/world.hpp"

namespace orogen {

// "vtp/output_000042.vtp": the ParaView file of output k, relative to the run folder.
std::string vtp_file_name(std::int64_t k);

// What the checkpoint says of the files written up to it.
struct KeptFiles {
  std::string identity;                        // run_identity of the run
  std::string config_toml;                     // its resolved configuration (for messages)
  std::vector<double> output_times;            // one per kept output
  std::vector<std::uint64_t> vtp_digests;      // per output, 0 where none was written
  std::optional<std::uint64_t> series_digest;  // CsvSeries::digest of the kept rows
  std::vector<std::string> series_columns;     // the experiment's column names
  std::vector<RemovalRecord> removals;         // every removal up to `step`
  std::uint64_t step = 0;                      // the checkpoint's step
};

// Checks the snapshot index and each kept output (identity, time), series.csv (columns, rows
// against the digest), removals.csv (rows up to the checkpoint's step) and the .vtp files,
// throwing RunFolderError that names the first file of another run; returns series.csv as
// loaded. Checks made from checkpoints written before a digest was kept are skipped.
CsvSeries check_kept_files_of_run(const std::filesystem::path& dir, const KeptFiles& kept);

}  // namespace orogen
