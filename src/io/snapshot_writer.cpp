#include "io/snapshot_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <type_traits>

#include "io/atomic_file.hpp"
#include "io/dataset_docs.hpp"

namespace orogen {
namespace {

bool is_disc_array(std::string_view name) {
  return std::find(kSnapshotDiscArrays.begin(), kSnapshotDiscArrays.end(), name) != kSnapshotDiscArrays.end();
}

// Index k of a group named output_<k>, or -1 for any other link.
std::int64_t group_index(std::string_view name) {
  constexpr std::string_view prefix = "output_";
  if (!name.starts_with(prefix)) return -1;
  name.remove_prefix(prefix.size());
  std::int64_t k = -1;
  const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), k);
  return ec == std::errc() && end == name.data() + name.size() ? k : -1;
}

// Rejects a bad frame before the file is touched.
void validate(const SnapshotFrame& f) {
  if (f.discs == nullptr) throw std::invalid_argument("snapshot frame has no discs");
  const std::size_t n = f.discs->size();
  for (const auto& [name, value] : f.attrs) {
    (void)value;
    if (name == "step" || name == "time") throw std::invalid_argument("snapshot attribute name '" + name + "' is reserved");
  }
  std::vector<std::string> seen;
  for (const auto& [name, values, units, description] : f.fields) {
    if (name.empty() || is_disc_array(name) || name == "walls" || name.find('/') != std::string::npos)
      throw std::invalid_argument("snapshot field name '" + name + "' is reserved or invalid");
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw std::invalid_argument("snapshot field '" + name + "' given twice");
    seen.push_back(name);
    if (values.size() != n)
      throw std::invalid_argument(fmt::format("snapshot field '{}' has {} values for {} discs", name, values.size(), n));
    if (units.empty() || description.empty())
      throw std::invalid_argument("snapshot field '" + name + "' has no units or no description");
  }
  for (const auto& g : f.groups) {
    validate_snapshot_group(g);
    if (is_disc_array(g.name) || g.name == "walls" || std::find(seen.begin(), seen.end(), g.name) != seen.end())
      throw std::invalid_argument("snapshot group name '" + g.name + "' is reserved or given twice");
    seen.push_back(g.name);
  }
}

// Stores the units and description of one of the writer's own datasets (dataset_docs.cpp).
void document(hid_t group, std::string_view name) {
  const DatasetDoc* doc = find_dataset_doc(name);
  if (doc == nullptr) throw std::logic_error("snapshot dataset '" + std::string(name) + "' has no entry in dataset_docs.cpp");
  h5::set_dataset_attr_string(group, std::string(name), kUnitsAttr, doc->units);
  h5::set_dataset_attr_string(group, std::string(name), kDescriptionAttr, doc->description);
}

// `path` is the group's path in its file ("/" or "/output_000000/"), for the `xy` view.
void write_group(hid_t group, const std::string& path, const SnapshotFrame& f, h5::WriteOptions storage) {
  // for_each_array is the one list of per-disc arrays; it only reads here.
  std::size_t written = 0;
  const_cast<Discs&>(*f.discs).for_each_array([&](std::string_view name, const auto& v) {
    if (Discs::optional_array(name) && !v.empty()) {  // a world of materials: material and slip
      if (v.size() != f.discs->size())
        throw std::invalid_argument(fmt::format("Discs::{} has {} entries for {} discs", name, v.size(), f.discs->size()));
      h5::write(group, std::string(name), std::span(v), storage);
      document(group, name);
      return;
    }
    if (!is_disc_array(name)) return;
    if (v.size() != f.discs->size())
      throw std::invalid_argument(fmt::format("Discs::{} has {} entries for {} discs", name, v.size(), f.discs->size()));
    h5::write(group, std::string(name), std::span(v), storage);
    document(group, name);
    ++written;
  });
  if (written != kSnapshotDiscArrays.size())
    throw std::logic_error("Discs lacks an array that snapshots store; update kSnapshotDiscArrays");
  // x and y as (x, y) rows without a copy: the geometry of the XDMF sidecar (xdmf_writer.cpp).
  h5::write_columns_view(group, "xy", {path + "x", path + "y"}, f.discs->size());
  document(group, "xy");
  for (const auto& field : f.fields) {
    h5::write(group, field.name, std::span(field.values), storage);
    h5::set_dataset_attr_string(group, field.name, kUnitsAttr, field.units);
    h5::set_dataset_attr_string(group, field.name, kDescriptionAttr, field.description);
  }

  std::vector<double> walls;
  for (const auto& w : f.walls) walls.insert(walls.end(), w.begin(), w.end());
  h5::write_2d(group, "walls", walls, f.walls.size(), 4);
  document(group, "walls");
  for (const auto& g : f.groups) write_snapshot_group(group, g, storage);

  h5::set_attr_int64(group, "step", f.step);
  h5::set_attr_double(group, "time", f.time);
  for (const auto& [name, value] : f.attrs) h5::set_attr_double(group, name, value);
}

std::int64_t read_count(hid_t file, const std::filesystem::path& path) {
  if (!h5::has_attr(file, "format") || h5::get_attr_string(file, "format") != kSnapshotFormat)
    throw SnapshotFormatError("'" + path.string() + "' is not an orogen snapshot file");
  const std::int64_t version = h5::get_attr_int64(file, "version");
  if (version != kSnapshotVersion)
    throw SnapshotFormatError(fmt::format("'{}' has snapshot format version {}, this build reads {}", path.string(), version,
                                kSnapshotVersion));
  return h5::get_attr_int64(file, "n_outputs");
}

void check_metadata(const SnapshotMetadata& meta) {
  for (const auto& name : {"format", "version", "n_outputs"})
    if (meta.numbers.contains(name) || meta.strings.contains(name))
      throw std::invalid_argument(fmt::format("snapshot metadata name '{}' is reserved", name));
}

void write_root_attrs(hid_t root, const SnapshotMetadata& meta, std::int64_t n_outputs) {
  h5::set_attr_string(root, "format", kSnapshotFormat);
  h5::set_attr_int64(root, "version", kSnapshotVersion);
  for (const auto& [k, v] : meta.numbers) h5::set_attr_double(root, k, v);
  for (const auto& [k, v] : meta.strings) h5::set_attr_string(root, k, v);
  h5::set_attr_int64(root, "n_outputs", n_outputs);
}

// "snapshots/output_000042.h5": the data file of output k, relative to the index's folder.
std::filesystem::path output_file(const std::filesystem::path& index, std::int64_t k) {
  return data_folder(index).filename() / (snapshot_group_name(k) + ".h5");
}

// Removes data files from output `keep` on and temporary files a killed write left.
void remove_data_beyond(const std::filesystem::path& index, std::int64_t keep) {
  const auto folder = data_folder(index);
  if (!std::filesystem::is_directory(folder)) return;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const bool temp = name.find(".tmp-") != std::string::npos;
    const std::int64_t k = name.ends_with(".h5") ? group_index(name.substr(0, name.size() - 3)) : -1;
    if (temp || k >= keep) std::filesystem::remove(entry.path());
  }
}

}  // namespace

std::string snapshot_group_name(std::int64_t k) { return fmt::format("output_{:06d}", k); }

std::filesystem::path data_folder(const std::filesystem::path& index) {
  std::filesystem::path folder = index;
  return folder.replace_extension();
}

SnapshotWriter::SnapshotWriter(std::filesystem::path path, SnapshotMetadata meta, std::int64_t count,
                               h5::WriteOptions storage)
    : path_(std::move(path)), meta_(std::move(meta)), count_(count), storage_(storage) {}

SnapshotWriter::SnapshotWriter(std::filesystem::path path, const SnapshotMetadata& meta, h5::WriteOptions storage)
    : path_(std::move(path)), meta_(meta), storage_(storage) {
  check_metadata(meta_);
  remove_data_beyond(path_, 0);
  std::filesystem::create_directories(data_folder(path_));
  write_index();
  write_sidecar();
}

SnapshotWriter SnapshotWriter::reopen(std::filesystem::path path, std::int64_t keep, h5::WriteOptions storage) {
  std::int64_t n = 0;
  SnapshotMetadata meta;
  {
    h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
    n = read_count(f.id(), path);
    if (n > 0 && !h5::is_external_link(f.id(), snapshot_group_name(0)))
      throw h5::Error("'" + path.string() + "' holds its outputs inside (written by Orogen before 0.2); it cannot be "
                      "continued by this build");
  }
  meta = read_snapshot_metadata(path);
  if (keep < 0 || keep > n)
    throw h5::Error(fmt::format("'{}' has {} complete outputs, fewer than the {} the checkpoint counts", path.string(),
                                n, keep));
  for (std::int64_t k = 0; k < keep; ++k)
    if (!std::filesystem::exists(path.parent_path() / output_file(path, k)))
      throw h5::Error(fmt::format("'{}' is missing: output {} of the run is gone",
                                  (path.parent_path() / output_file(path, k)).string(), k));
  SnapshotWriter w(std::move(path), std::move(meta), keep, storage);
  w.write_index();  // uncount first, then delete what lies beyond
  remove_data_beyond(w.path_, keep);
  for (std::int64_t k = 0; k < keep; ++k) {
    const std::string file = output_file(w.path_, k).string();
    h5::File f = h5::File::open(w.path_.parent_path() / file, h5::File::Mode::ReadOnly);
    w.xdmf_.push_back(describe_xdmf_output(f.id(), file, "/"));
  }
  w.write_index();  // its disc_index now covers the kept outputs
  w.write_sidecar();
  return w;
}

void SnapshotWriter::write_index() const {
  h5::File f = h5::File::create_in_memory();
  write_root_attrs(f.id(), meta_, count_);
  for (std::int64_t k = 0; k < count_; ++k)
    h5::link_external(f.id(), snapshot_group_name(k), output_file(path_, k).string(), "/");
  write_disc_index(f.id(), most_discs(xdmf_));
  write_file_atomically(path_, f.image());
}

void SnapshotWriter::write_sidecar() const {
  write_xdmf(xdmf_sidecar(path_), xdmf_, {path_.filename().string(), most_discs(xdmf_)});
}

void SnapshotWriter::append(const SnapshotFrame& frame) {
  validate(frame);
  {
    h5::File f = h5::File::create_in_memory();
    write_group(f.id(), "/", frame, storage_);
    // Each output file carries the configuration too, so that one copied alone says what it is.
    if (const auto it = meta_.strings.find(kConfigAttr); it != meta_.strings.end())
      h5::set_attr_string(f.id(), kConfigAttr, it->second);
    XdmfOutput listed = describe_xdmf_output(f.id(), output_file(path_, count_).string(), "/");
    write_file_atomically(path_.parent_path() / output_file(path_, count_), f.image());
    xdmf_.push_back(std::move(listed));  // only once the file is there
  }
  ++count_;
  write_index();
  write_sidecar();
}

void SnapshotWriter::set_metadata_string(const std::string& name, const std::string& value) {
  SnapshotMetadata m = meta_;
  m.strings[name] = value;
  check_metadata(m);
  meta_ = std::move(m);
  write_index();
}

void write_single_snapshot(const std::filesystem::path& path, const SnapshotMetadata& meta, const SnapshotFrame& frame,
                           h5::WriteOptions storage) {
  check_metadata(meta);
  validate(frame);
  h5::File f = h5::File::create_in_memory();
  write_root_attrs(f.id(), meta, 1);
  XdmfOutput xdmf;
  {
    h5::Group g = h5::Group::create(f.id(), snapshot_group_name(0));
    std::string group_path("/");  // built piecewise: GCC 12 warns falsely on "/" + std::string
    group_path.append(snapshot_group_name(0)).append("/");
    write_group(g.id(), group_path, frame, storage);
    xdmf = describe_xdmf_output(g.id(), path.filename().string(), group_path);
    g.close();
  }
  write_disc_index(f.id(), xdmf.n_discs);
  write_file_atomically(path, f.image());
  write_xdmf(xdmf_sidecar(path), {xdmf}, {path.filename().string(), xdmf.n_discs});
}

SnapshotMetadata read_snapshot_metadata(const std::filesystem::path& path) {
  h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
  read_count(f.id(), path);
  SnapshotMetadata meta;
  for (const auto& a : h5::list_attrs(f.id())) {
    if (a.name == "format" || a.name == "version" || a.name == "n_outputs") continue;
    if (a.kind == h5::Kind::String) meta.strings[a.name] = h5::get_attr_string(f.id(), a.name);
    else if (a.kind != h5::Kind::Other) meta.numbers[a.name] = h5::get_attr_double(f.id(), a.name);
  }
  return meta;
}

}  // namespace orogen
