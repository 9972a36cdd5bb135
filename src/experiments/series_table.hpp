#pragma once
// An experiment's series.csv as one table: each entry names a column, its unit and meaning,
// and the field of the experiment's sample (a struct measured once per output) that holds
// its value. columns() and measure() both read the table, so a column and its value cannot
// drift apart, and code that needs a value reads the sample's field by name.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "experiments/experiment.hpp"

namespace orogen {

template <class Sample>
struct SeriesEntry {
  const char* name;
  const char* unit;
  const char* description;
  double Sample::*value;
};

// The header of series.csv: each column's name and "meaning [unit]".
template <class Sample, std::size_t N>
std::vector<SeriesColumn> series_columns(const std::array<SeriesEntry<Sample>, N>& table) {
  std::vector<SeriesColumn> out;
  out.reserve(N);
  for (const auto& e : table) out.push_back({e.name, std::string(e.description) + " [" + e.unit + "]"});
  return out;
}

// One row of series.csv: the sample's fields in the table's order.
template <class Sample, std::size_t N>
std::vector<double> series_values(const std::array<SeriesEntry<Sample>, N>& table, const Sample& sample) {
  std::vector<double> out;
  out.reserve(N);
  for (const auto& e : table) out.push_back(sample.*e.value);
  return out;
}

}  // namespace orogen
