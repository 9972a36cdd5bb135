#include "run/kept_files.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>

#include "io/binary_archive.hpp"
#include "io/snapshot_reader.hpp"
#include "run/removal_log.hpp"
#include "run/run_folder.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", path.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void check_outputs(const fs::path& dir, const KeptFiles& kept) {
  const fs::path index = dir / "snapshots.h5";
  if (!fs::exists(index)) throw RunFolderError(fmt::format("{} is missing: the run's outputs are gone", index.string()));
  const SnapshotReader reader(index);
  const auto& meta = reader.metadata().strings;
  const auto it = meta.find("run_identity");
  if (it == meta.end() || it->second != kept.identity)
    throw RunFolderError(fmt::format("{} comes from another run (identity {}, this configuration's is {})",
                                     index.string(), it == meta.end() ? "none" : it->second, kept.identity));
  const auto outputs = static_cast<std::int64_t>(kept.output_times.size());
  if (reader.count() < outputs)
    throw RunFolderError(fmt::format("{} lists {} outputs but the checkpoint counts {}: the files are not of one run",
                                     index.string(), reader.count(), outputs));
  for (std::int64_t k = 0; k < outputs; ++k) {
    const OutputStamp stamp = reader.stamp(k);
    if (const std::string why = foreign_output(reader, k, stamp, kept.identity, kept.config_toml); !why.empty())
      throw RunFolderError(why);
    const double expected = kept.output_times[static_cast<std::size_t>(k)];
    if (stamp.time != expected)
      throw RunFolderError(fmt::format("{} is not this run's output {}: its time is {:.9g}, the checkpoint's {:.9g}",
                                       reader.output_path(k).string(), k, stamp.time, expected));
  }
}

CsvSeries check_series(const fs::path& dir, const KeptFiles& kept) {
  const fs::path path = dir / "series.csv";
  CsvSeries series = CsvSeries::load(path);
  const std::size_t n = kept.output_times.size();
  if (series.rows().size() < n)
    throw RunFolderError(fmt::format("{} has {} rows but the checkpoint counts {} outputs: the files are not of one run",
                                     path.string(), series.rows().size(), n));
  std::vector<std::string> names;
  for (const auto& col : series.columns()) names.push_back(col.name);
  if (names != kept.series_columns)
    throw RunFolderError(fmt::format("{} comes from another run: its columns are not this experiment's", path.string()));
  if (kept.series_digest && series.digest(n) != *kept.series_digest)
    throw RunFolderError(fmt::format("{} comes from another run: its first {} rows are not those this run wrote",
                                     path.string(), n));
  return series;
}

void check_vtp_files(const fs::path& dir, const KeptFiles& kept) {
  for (std::size_t k = 0; k < kept.vtp_digests.size() && k < kept.output_times.size(); ++k) {
    const fs::path vtp = dir / vtp_file_name(static_cast<std::int64_t>(k));
    if (kept.vtp_digests[k] != 0 && fs::exists(vtp) && fnv1a64(file_bytes(vtp)) != kept.vtp_digests[k])
      throw RunFolderError(
          fmt::format("{} comes from another run: it is not the file this run wrote at output {}", vtp.string(), k));
  }
}

}  // namespace

std::string vtp_file_name(std::int64_t k) { return fmt::format("vtp/output_{:06d}.vtp", k); }

CsvSeries check_kept_files_of_run(const fs::path& dir, const KeptFiles& kept) {
  check_outputs(dir, kept);
  CsvSeries series = check_series(dir, kept);
  if (const std::string diff = removal_log_difference(dir / "removals.csv", kept.removals, kept.step); !diff.empty())
    throw RunFolderError(fmt::format("{} comes from another run: {}", (dir / "removals.csv").string(), diff));
  check_vtp_files(dir, kept);
  return series;
}

}  // namespace orogen
