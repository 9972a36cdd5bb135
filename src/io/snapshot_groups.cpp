#include "io/snapshot_groups.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <stdexcept>
#include <type_traits>

namespace orogen {
namespace {

bool bad_name(const std::string& name) { return name.empty() || name.find('/') != std::string::npos; }

template <class T>
void write_values(hid_t group, const SnapshotDataset& d, const std::vector<T>& v, h5::WriteOptions storage) {
  if constexpr (std::is_same_v<T, std::uint8_t>) {
    h5::write(group, d.name, std::span<const T>(v), storage);  // flags are 1-D only
  } else {
    if (d.columns > 1) h5::write_2d(group, d.name, std::span<const T>(v), v.size() / d.columns, d.columns, storage);
    else h5::write(group, d.name, std::span<const T>(v), storage);
  }
}

}  // namespace

void validate_snapshot_group(const SnapshotGroup& g) {
  if (bad_name(g.name)) throw std::invalid_argument("snapshot group name '" + g.name + "' is invalid");
  std::vector<std::string> seen;
  for (const auto& d : g.datasets) {
    if (bad_name(d.name) || std::find(seen.begin(), seen.end(), d.name) != seen.end())
      throw std::invalid_argument(fmt::format("snapshot group '{}': dataset name '{}' is invalid or given twice",
                                              g.name, d.name));
    seen.push_back(d.name);
    const std::size_t n = std::visit([](const auto& v) { return v.size(); }, d.values);
    const bool flags = std::holds_alternative<std::vector<std::uint8_t>>(d.values);
    if (d.columns == 0 || n % d.columns != 0 || (flags && d.columns != 1))
      throw std::invalid_argument(fmt::format("snapshot group '{}': dataset '{}' has {} values for {} columns", g.name,
                                              d.name, n, d.columns));
  }
}

void write_snapshot_group(hid_t parent, const SnapshotGroup& g, h5::WriteOptions storage) {
  h5::Group group = h5::Group::create(parent, g.name);
  if (!g.description.empty()) h5::set_attr_string(group.id(), "description", g.description);
  for (const auto& [name, value] : g.attrs) h5::set_attr_double(group.id(), name, value);
  for (const auto& d : g.datasets) {
    std::visit([&](const auto& v) { write_values(group.id(), d, v, storage); }, d.values);
    // Attributes on the dataset itself: open it by name for the call.
    const hid_t id = H5Dopen2(group.id(), d.name.c_str(), H5P_DEFAULT);
    if (id < 0) throw h5::Error("HDF5: cannot open dataset '" + d.name + "' just written");
    h5::Object ds(id, H5Dclose);
    h5::set_attr_string(ds.id(), "units", d.units);
    h5::set_attr_string(ds.id(), "description", d.description);
  }
  group.close();
}

}  // namespace orogen
