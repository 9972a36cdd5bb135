#include "io/snapshot_reader.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace orogen {

const std::vector<double>& Snapshot::field(const std::string& name) const {
  const auto it = fields.find(name);
  if (it == fields.end()) throw std::out_of_range("snapshot has no field '" + name + "'");
  return it->second;
}

SnapshotReader::SnapshotReader(const std::filesystem::path& path)
    : path_(path), file_(h5::File::open(path, h5::File::Mode::ReadOnly)) {
  const hid_t root = file_.id();
  if (!h5::has_attr(root, "format") || h5::get_attr_string(root, "format") != kSnapshotFormat)
    throw SnapshotFormatError("'" + path.string() + "' is not an orogen snapshot file");
  const std::int64_t version = h5::get_attr_int64(root, "version");
  if (version != kSnapshotVersion)
    throw SnapshotFormatError(fmt::format("'{}' has snapshot format version {}, this build reads {}", path.string(), version,
                                kSnapshotVersion));
  count_ = h5::get_attr_int64(root, "n_outputs");
  meta_ = read_snapshot_metadata(path);
}

bool SnapshotReader::has_group(std::int64_t k, const std::string& group) const {
  check_index(k);
  h5::Group g = h5::Group::open(file_.id(), snapshot_group_name(k));
  return h5::exists(g.id(), group) && h5::is_group(g.id(), group);
}

h5::Matrix SnapshotReader::read_group_dataset(std::int64_t k, const std::string& group, const std::string& name) const {
  if (!has_group(k, group))
    throw h5::Error(fmt::format("'{}' output {} has no group '{}'", path_.string(), k, group));
  h5::Group out = h5::Group::open(file_.id(), snapshot_group_name(k));
  h5::Group g = h5::Group::open(out.id(), group);
  if (h5::dataset_info(g.id(), name).dims.size() == 1) {
    h5::Matrix m;
    m.data = h5::read<double>(g.id(), name);
    m.rows = m.data.size();
    m.cols = 1;
    return m;
  }
  return h5::read_2d(g.id(), name);
}

OutputStamp SnapshotReader::stamp(std::int64_t k) const {
  check_index(k);
  h5::Group g = h5::Group::open(file_.id(), snapshot_group_name(k));
  OutputStamp s{.step = h5::get_attr_int64(g.id(), "step"), .time = h5::get_attr_double(g.id(), "time"), .config_toml = {}};
  if (h5::has_attr(g.id(), kConfigAttr)) s.config_toml = h5::get_attr_string(g.id(), kConfigAttr);
  return s;
}

std::filesystem::path SnapshotReader::output_path(std::int64_t k) const {
  return data_folder(path_) / (snapshot_group_name(k) + ".h5");
}

void SnapshotReader::check_index(std::int64_t k) const {
  if (k < 0 || k >= count_)
    throw std::out_of_range(fmt::format("'{}' has {} complete outputs, no output {}", path_.string(), count_, k));
}

Snapshot SnapshotReader::read(std::int64_t k) const {
  check_index(k);
  h5::Group g = h5::Group::open(file_.id(), snapshot_group_name(k));
  Snapshot s;
  s.step = h5::get_attr_int64(g.id(), "step");
  s.time = h5::get_attr_double(g.id(), "time");
  for (const auto& a : h5::list_attrs(g.id()))
    if (a.name != "step" && a.name != "time" && a.kind != h5::Kind::String && a.kind != h5::Kind::Other)
      s.attrs[a.name] = h5::get_attr_double(g.id(), a.name);

  for (const auto& name : h5::list(g.id())) {
    if (name == "walls" || h5::is_group(g.id(), name)) continue;  // extra groups: read by name
    const h5::DatasetInfo info = h5::dataset_info(g.id(), name);
    if (info.dims.size() != 1) continue;
    if (name == "id") s.id = h5::read<std::int64_t>(g.id(), name);
    else if (name == "cluster_id") s.cluster_id = h5::read<std::int64_t>(g.id(), name);
    else if (name == "motion") s.motion = h5::read<std::uint8_t>(g.id(), name);
    else if (name == "material") s.material = h5::read<std::uint8_t>(g.id(), name);
    else if (info.kind == h5::Kind::Float) s.fields[name] = h5::read<double>(g.id(), name);
  }
  const std::size_t n = s.id.size();
  auto check_size = [&](const std::string& name, std::size_t size) {
    if (size != n)
      throw h5::Error(fmt::format("'{}' output {}: '{}' has {} entries, 'id' has {}", path_.string(), k, name, size, n));
  };
  check_size("cluster_id", s.cluster_id.size());
  check_size("motion", s.motion.size());
  if (!s.material.empty()) check_size("material", s.material.size());
  for (const auto& [name, v] : s.fields) check_size(name, v.size());

  const h5::Matrix w = h5::read_2d(g.id(), "walls");
  if (w.cols != 4) throw h5::Error(fmt::format("'{}' output {}: 'walls' must have 4 columns", path_.string(), k));
  for (std::size_t r = 0; r < w.rows; ++r)
    s.walls.push_back({w.data[4 * r], w.data[4 * r + 1], w.data[4 * r + 2], w.data[4 * r + 3]});
  return s;
}

}  // namespace orogen
