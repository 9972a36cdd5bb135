#include "io/csv_series.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"

namespace orogen {
namespace {

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = line.find(sep, begin);
    out.push_back(line.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin));
    if (end == std::string_view::npos) return out;
    begin = end + 1;
  }
}

// One row as the file holds it: the shortest form of each value that reads back to the same
// double (so a loaded series formats as it was written, NaN included).
void append_row_text(std::string& out, const std::vector<double>& row) {
  for (std::size_t j = 0; j < row.size(); ++j) {
    if (j) out += ',';
    out += fmt::format("{}", row[j]);
  }
  out += '\n';
}

[[noreturn]] void bad_file(const std::filesystem::path& path, std::size_t line, const std::string& why) {
  throw std::runtime_error(fmt::format("'{}' line {}: {}", path.string(), line, why));
}

}  // namespace

CsvSeries::CsvSeries(std::filesystem::path path, std::vector<Column> columns, std::vector<std::string> preamble)
    : path_(std::move(path)), columns_(std::move(columns)), preamble_(std::move(preamble)) {
  if (columns_.empty()) throw std::invalid_argument("CSV series needs at least one column");
  for (const auto& c : columns_) {
    if (c.name.empty() || c.name.find_first_of(",\"\r\n#") != std::string::npos || c.name.find(": ") != std::string::npos)
      throw std::invalid_argument("bad CSV column name '" + c.name + "'");
    if (c.description.find_first_of("\r\n") != std::string::npos)
      throw std::invalid_argument("CSV column description of '" + c.name + "' has a line break");
  }
  for (const auto& p : preamble_)
    if (p.find_first_of("\r\n") != std::string::npos) throw std::invalid_argument("CSV comment has a line break");
}

void CsvSeries::add_row(std::vector<double> row) {
  if (row.size() != columns_.size())
    throw std::invalid_argument(
        fmt::format("CSV row has {} values for {} columns in '{}'", row.size(), columns_.size(), path_.string()));
  rows_.push_back(std::move(row));
  save();
}

void CsvSeries::truncate(std::size_t k) {
  if (k > rows_.size())
    throw std::invalid_argument(fmt::format("cannot keep {} rows of '{}': it has {}", k, path_.string(), rows_.size()));
  rows_.resize(k);
  save();
}

void CsvSeries::save() const {
  std::string out;
  for (const auto& p : preamble_) out += p.empty() ? "#\n" : "# " + p + "\n";
  for (const auto& c : columns_) out += "# " + c.name + ": " + c.description + "\n";
  for (std::size_t j = 0; j < columns_.size(); ++j) out += (j ? "," : "") + columns_[j].name;
  out += '\n';
  for (const auto& row : rows_) append_row_text(out, row);
  write_file_atomically(path_, out);
}

std::uint64_t CsvSeries::digest(std::size_t k) const {
  if (k > rows_.size())
    throw std::invalid_argument(fmt::format("no digest of {} rows of '{}': it has {}", k, path_.string(), rows_.size()));
  std::string text;
  for (const auto& c : columns_) text += c.name + '\n';
  for (std::size_t i = 0; i < k; ++i) append_row_text(text, rows_[i]);
  return fnv1a64(text);
}

CsvSeries CsvSeries::load(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  std::vector<std::string> comments;
  std::vector<std::string_view> names;
  std::string header;
  std::vector<std::vector<double>> rows;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (header.empty()) {
      if (line.starts_with("#")) {
        comments.push_back(line.size() > 1 && line[1] == ' ' ? line.substr(2) : line.substr(1));
        continue;
      }
      header = line;
      names = split(header, ',');
      continue;
    }
    if (line.empty()) continue;
    const auto cells = split(line, ',');
    if (cells.size() != names.size())
      bad_file(path, line_no, fmt::format("{} values for {} columns", cells.size(), names.size()));
    std::vector<double>& row = rows.emplace_back();
    for (const auto cell : cells) {
      double v = 0;
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
      if (ec != std::errc() || end != cell.data() + cell.size()) bad_file(path, line_no, "bad number '" + std::string(cell) + "'");
      row.push_back(v);
    }
  }
  if (header.empty()) bad_file(path, line_no, "no header row");
  // The last comment lines describe the columns, one each, in order; earlier ones are free.
  if (comments.size() < names.size()) bad_file(path, line_no, "missing column descriptions");
  const std::size_t first = comments.size() - names.size();
  std::vector<Column> columns;
  for (std::size_t j = 0; j < names.size(); ++j) {
    const std::string& c = comments[first + j];
    const std::string prefix = std::string(names[j]) + ": ";
    if (!c.starts_with(prefix)) bad_file(path, first + j + 1, "expected the description of column '" + std::string(names[j]) + "'");
    columns.push_back({std::string(names[j]), c.substr(prefix.size())});
  }
  comments.resize(first);
  CsvSeries s(path, std::move(columns), std::move(comments));
  s.rows_ = std::move(rows);
  return s;
}

}  // namespace orogen
