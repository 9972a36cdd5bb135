#pragma once
// series.csv: one row of scalars per output step. The file starts with comment lines
// (free preamble lines, then `# name: meaning [unit]` for each column), then a header row
// of column names, then the rows. Doubles are written in shortest round-trip form, so a
// reload is bit-exact and the output deterministic. The file is small and is rewritten
// atomically on every add_row, so a killed run never leaves a torn last line.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace orogen {

class CsvSeries {
 public:
  struct Column {
    std::string name;         // no commas, quotes or line breaks
    std::string description;  // "meaning [unit]"
  };

  CsvSeries(std::filesystem::path path, std::vector<Column> columns, std::vector<std::string> preamble_comments = {});

  // Restores a series from an existing file (for resume).
  static CsvSeries load(const std::filesystem::path& path);

  // Appends a row (one value per column) and rewrites the file.
  void add_row(std::vector<double> row);
  // Keeps the first k rows and rewrites the file.
  void truncate(std::size_t k);
  // Writes the file as it stands (header only when there are no rows).
  void save() const;
  // A fingerprint of the column names and the first k rows as written: a checkpoint keeps
  // it so that a resume recognises a series of another run.
  std::uint64_t digest(std::size_t k) const;

  const std::filesystem::path& path() const { return path_; }
  const std::vector<Column>& columns() const { return columns_; }
  const std::vector<std::string>& preamble() const { return preamble_; }
  const std::vector<std::vector<double>>& rows() const { return rows_; }

 private:
  std::filesystem::path path_;
  std::vector<Column> columns_;
  std::vector<std::string> preamble_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace orogen
