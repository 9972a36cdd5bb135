#include "io/binary_archive.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace orogen {
namespace {

static_assert(std::endian::native == std::endian::little, "the archive stores little-endian memory images");

constexpr std::string_view kMagic = "OROGENCK";

template <class T>
void append_pod(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

const char* type_name(ArchiveType t) {
  switch (t) {
    case ArchiveType::Float: return "float";
    case ArchiveType::SignedInt: return "signed integer";
    case ArchiveType::UnsignedInt: return "unsigned integer";
    case ArchiveType::String: return "string";
    case ArchiveType::Int32x3: return "int32 triple";
  }
  return "unknown";
}

// Bounds-checked reading of the archive body; running past the end means truncation.
class Cursor {
 public:
  Cursor(const std::string& bytes, std::size_t end, const std::filesystem::path& path)
      : bytes_(bytes), end_(end), path_(path) {}
  template <class T>
  T pod() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  const char* take(std::size_t n) {
    if (n > end_ - at_) throw std::runtime_error(fmt::format("archive '{}' is truncated", path_.string()));
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::size_t at() const { return at_; }
  bool done() const { return at_ == end_; }
  void seek(std::size_t at) { at_ = at; }

 private:
  const std::string& bytes_;
  std::size_t end_, at_ = 0;
  const std::filesystem::path& path_;
};

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

void ArchiveWriter::put_raw(std::string_view name, ArchiveType type, std::size_t element_size, std::size_t count,
                            const void* data) {
  if (finished_) throw std::logic_error("archive writer used after finish()");
  if (name.empty()) throw std::invalid_argument("archive record needs a name");
  if (!names_.emplace(std::string(name), 0).second)
    throw std::invalid_argument("archive record '" + std::string(name) + "' written twice");
  if (bytes_.empty()) {
    bytes_.append(kMagic);
    append_pod(bytes_, kArchiveVersion);
  }
  append_pod(bytes_, static_cast<std::uint32_t>(name.size()));
  bytes_.append(name);
  append_pod(bytes_, static_cast<std::uint8_t>(type));
  append_pod(bytes_, static_cast<std::uint8_t>(element_size));
  append_pod(bytes_, static_cast<std::uint64_t>(count));
  if (count > 0) bytes_.append(static_cast<const char*>(data), count * element_size);
}

void ArchiveWriter::put_string(std::string_view name, std::string_view s) {
  put_raw(name, ArchiveType::String, 1, s.size(), s.data());
}

void ArchiveWriter::finish(const std::filesystem::path& path) {
  if (finished_) throw std::logic_error("archive writer finished twice");
  if (bytes_.empty()) {  // an archive with no records is still a valid archive
    bytes_.append(kMagic);
    append_pod(bytes_, kArchiveVersion);
  }
  append_pod(bytes_, fnv1a64(bytes_));
  write_file_atomically(path, bytes_);
  finished_ = true;
  bytes_.clear();
}

ArchiveReader::ArchiveReader(const std::filesystem::path& path) : path_(path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open archive '" + path.string() + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  bytes_ = std::move(ss).str();

  const std::size_t header = kMagic.size() + sizeof(std::uint32_t);
  if (bytes_.size() < kMagic.size() || std::string_view(bytes_).substr(0, kMagic.size()) != kMagic)
    throw std::runtime_error(fmt::format("'{}' is not an orogen archive (bad magic)", path.string()));
  if (bytes_.size() < header + sizeof(std::uint64_t))
    throw std::runtime_error(fmt::format("archive '{}' is truncated", path.string()));
  const std::size_t body = bytes_.size() - sizeof(std::uint64_t);
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes_.data() + body, sizeof stored);
  if (stored != fnv1a64(std::string_view(bytes_).substr(0, body)))
    throw std::runtime_error(fmt::format("archive '{}' fails its checksum (corrupt or truncated)", path.string()));

  Cursor c(bytes_, body, path_);
  c.seek(kMagic.size());
  if (const auto version = c.pod<std::uint32_t>(); version != kArchiveVersion)
    throw std::runtime_error(
        fmt::format("archive '{}' has version {}, this build reads {}", path.string(), version, kArchiveVersion));
  while (!c.done()) {
    const auto len = c.pod<std::uint32_t>();
    std::string name(c.take(len), len);
    Record r{};
    r.type = static_cast<ArchiveType>(c.pod<std::uint8_t>());
    r.element_size = c.pod<std::uint8_t>();
    r.count = c.pod<std::uint64_t>();
    r.offset = c.at();
    r.order = records_.size();
    if (r.element_size == 0 || r.count > body / r.element_size)
      throw std::runtime_error(fmt::format("archive '{}' record '{}' is malformed", path.string(), name));
    c.take(r.count * r.element_size);
    if (!records_.emplace(std::move(name), r).second)
      throw std::runtime_error(fmt::format("archive '{}' has a duplicate record", path.string()));
  }
}

const ArchiveReader::Record& ArchiveReader::find(std::string_view name, ArchiveType type,
                                                 std::size_t element_size) const {
  const auto it = records_.find(name);
  if (it == records_.end())
    throw std::runtime_error(fmt::format("archive '{}' has no record '{}'", path_.string(), name));
  const Record& r = it->second;
  if (r.type != type || r.element_size != element_size)
    throw std::runtime_error(fmt::format("archive '{}' record '{}' holds {}-byte {} values, asked for {}-byte {}",
                                         path_.string(), name, r.element_size, type_name(r.type), element_size,
                                         type_name(type)));
  return r;
}

void ArchiveReader::expect_scalar(std::string_view name, const Record& r) const {
  if (r.count != 1)
    throw std::runtime_error(fmt::format("archive '{}' record '{}' has {} values, not one", path_.string(), name, r.count));
}

void ArchiveReader::copy_out(const Record& r, void* dst) const {
  if (r.count > 0) std::memcpy(dst, bytes_.data() + r.offset, r.count * r.element_size);
}

std::string ArchiveReader::get_string(std::string_view name) const {
  const Record& r = find(name, ArchiveType::String, 1);
  return bytes_.substr(r.offset, r.count);
}

std::vector<std::string> ArchiveReader::names() const {
  std::vector<std::string> out(records_.size());
  for (const auto& [name, r] : records_) out[r.order] = name;
  return out;
}

}  // namespace orogen
