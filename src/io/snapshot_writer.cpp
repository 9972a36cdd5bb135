#include "io/snapshot_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <type_traits>

#include "io/atomic_file.hpp"

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
  for (const auto& [name, values] : f.fields) {
    if (name.empty() || is_disc_array(name) || name == "walls" || name.find('/') != std::string::npos)
      throw std::invalid_argument("snapshot field name '" + name + "' is reserved or invalid");
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw std::invalid_argument("snapshot field '" + name + "' given twice");
    seen.push_back(name);
    if (values.size() != n)
      throw std::invalid_argument(fmt::format("snapshot field '{}' has {} values for {} discs", name, values.size(), n));
  }
}

void write_group(hid_t group, const SnapshotFrame& f, h5::WriteOptions storage) {
  // for_each_array is the one list of per-disc arrays; it only reads here.
  std::size_t written = 0;
  const_cast<Discs&>(*f.discs).for_each_array([&](std::string_view name, const auto& v) {
    if (!is_disc_array(name)) return;
    if (v.size() != f.discs->size())
      throw std::invalid_argument(fmt::format("Discs::{} has {} entries for {} discs", name, v.size(), f.discs->size()));
    h5::write(group, std::string(name), std::span(v), storage);
    ++written;
  });
  if (written != kSnapshotDiscArrays.size())
    throw std::logic_error("Discs lacks an array that snapshots store; update kSnapshotDiscArrays");
  for (const auto& [name, values] : f.fields) h5::write(group, name, std::span(values), storage);

  std::vector<double> walls;
  for (const auto& w : f.walls) walls.insert(walls.end(), w.begin(), w.end());
  h5::write_2d(group, "walls", walls, f.walls.size(), 4);

  h5::set_attr_int64(group, "step", f.step);
  h5::set_attr_double(group, "time", f.time);
  for (const auto& [name, value] : f.attrs) h5::set_attr_double(group, name, value);
}

std::int64_t read_count(hid_t file, const std::filesystem::path& path) {
  if (!h5::has_attr(file, "format") || h5::get_attr_string(file, "format") != kSnapshotFormat)
    throw h5::Error("'" + path.string() + "' is not an orogen snapshot file");
  const std::int64_t version = h5::get_attr_int64(file, "version");
  if (version != kSnapshotVersion)
    throw h5::Error(fmt::format("'{}' has snapshot format version {}, this build reads {}", path.string(), version,
                                kSnapshotVersion));
  return h5::get_attr_int64(file, "n_outputs");
}

}  // namespace

std::string snapshot_group_name(std::int64_t k) { return fmt::format("output_{:06d}", k); }

SnapshotWriter::SnapshotWriter(Reopened, std::filesystem::path path, std::int64_t count, h5::WriteOptions storage)
    : path_(std::move(path)), count_(count), storage_(storage) {}

SnapshotWriter::SnapshotWriter(std::filesystem::path path, const SnapshotMetadata& meta, h5::WriteOptions storage)
    : path_(std::move(path)), storage_(storage) {
  for (const auto& name : {"format", "version", "n_outputs"})
    if (meta.numbers.contains(name) || meta.strings.contains(name))
      throw std::invalid_argument(fmt::format("snapshot metadata name '{}' is reserved", name));
  AtomicPath out(path_);
  {
    h5::File f = h5::File::create(out.temp());
    h5::set_attr_string(f.id(), "format", kSnapshotFormat);
    h5::set_attr_int64(f.id(), "version", kSnapshotVersion);
    for (const auto& [k, v] : meta.numbers) h5::set_attr_double(f.id(), k, v);
    for (const auto& [k, v] : meta.strings) h5::set_attr_string(f.id(), k, v);
    h5::set_attr_int64(f.id(), "n_outputs", 0);
    f.close();
  }
  out.commit();
}

SnapshotWriter SnapshotWriter::reopen(std::filesystem::path path, h5::WriteOptions storage) {
  std::int64_t n = 0;
  {
    h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
    n = read_count(f.id(), path);
  }
  truncate_snapshots(path, n);  // drops a group half-written by a killed run
  return SnapshotWriter(Reopened{}, std::move(path), n, storage);
}

void SnapshotWriter::append(const SnapshotFrame& frame) {
  validate(frame);
  h5::File f = h5::File::open(path_, h5::File::Mode::ReadWrite);
  const std::string name = snapshot_group_name(count_);
  if (h5::exists(f.id(), name)) h5::remove(f.id(), name);  // left by a killed append
  {
    h5::Group g = h5::Group::create(f.id(), name);
    write_group(g.id(), frame, storage_);
    g.close();
  }
  // The group must be on disk before n_outputs counts it.
  f.flush();
  fsync_file(path_);
  h5::set_attr_int64(f.id(), "n_outputs", count_ + 1);
  f.flush();
  f.close();
  fsync_file(path_);
  ++count_;
}

void truncate_snapshots(const std::filesystem::path& path, std::int64_t k) {
  h5::File f = h5::File::open(path, h5::File::Mode::ReadWrite);
  const std::int64_t n = read_count(f.id(), path);
  if (k < 0 || k > n)
    throw std::invalid_argument(fmt::format("cannot truncate '{}' to {} outputs: it has {}", path.string(), k, n));
  // Uncount first, so a kill during the deletions leaves only ignored groups behind.
  h5::set_attr_int64(f.id(), "n_outputs", k);
  f.flush();
  for (const auto& link : h5::list(f.id()))
    if (group_index(link) >= k) h5::remove(f.id(), link);
  f.flush();
  f.close();
  fsync_file(path);
}

}  // namespace orogen
