#pragma once
// Checkpoint archive: a flat, tagged binary file of named arrays, bit-exact on reload.
//   "OROGENCK" | u32 version | records... | u64 FNV-1a of every byte before it
//   record = u32 name length | name | u8 type code | u8 element size | u64 count | raw bytes
// Little-endian, native memory images. The whole file is written atomically.
#include <array>
#include <concepts>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace orogen {

inline constexpr std::uint32_t kArchiveVersion = 1;

// Type codes stored in each record.
enum class ArchiveType : std::uint8_t { Float = 1, SignedInt = 2, UnsignedInt = 3, String = 4, Int32x3 = 5 };

template <class T>
concept ArchiveScalar = std::is_arithmetic_v<T> && !std::same_as<T, bool>;

template <class T>
concept ArchiveElement = ArchiveScalar<T> || std::same_as<T, std::array<std::int32_t, 3>>;

template <ArchiveElement T>
constexpr ArchiveType archive_type() {
  if constexpr (std::same_as<T, std::array<std::int32_t, 3>>) return ArchiveType::Int32x3;
  else if constexpr (std::is_floating_point_v<T>) return ArchiveType::Float;
  else if constexpr (std::is_signed_v<T>) return ArchiveType::SignedInt;
  else return ArchiveType::UnsignedInt;
}

class ArchiveWriter {
 public:
  template <ArchiveElement T>
  void put(std::string_view name, const std::vector<T>& v) {
    put_raw(name, archive_type<T>(), sizeof(T), v.size(), v.data());
  }
  template <ArchiveScalar T>
  void put_scalar(std::string_view name, T v) {
    put_raw(name, archive_type<T>(), sizeof(T), 1, &v);
  }
  void put_string(std::string_view name, std::string_view s);

  // Appends the checksum and writes the file atomically. The writer is spent afterwards.
  void finish(const std::filesystem::path& path);

 private:
  void put_raw(std::string_view name, ArchiveType type, std::size_t element_size, std::size_t count, const void* data);
  std::string bytes_;
  std::map<std::string, int, std::less<>> names_;
  bool finished_ = false;
};

class ArchiveReader {
 public:
  // Reads the whole file and verifies magic, version and checksum.
  explicit ArchiveReader(const std::filesystem::path& path);

  template <ArchiveElement T>
  void get(std::string_view name, std::vector<T>& out) const {
    const Record& r = find(name, archive_type<T>(), sizeof(T));
    out.resize(r.count);
    copy_out(r, out.data());
  }
  template <ArchiveScalar T>
  T get_scalar(std::string_view name) const {
    const Record& r = find(name, archive_type<T>(), sizeof(T));
    expect_scalar(name, r);
    T v{};
    copy_out(r, &v);
    return v;
  }
  std::string get_string(std::string_view name) const;

  bool has(std::string_view name) const { return records_.find(name) != records_.end(); }
  std::vector<std::string> names() const;  // in file order
  const std::filesystem::path& path() const { return path_; }

 private:
  struct Record {
    ArchiveType type;
    std::size_t element_size, count, offset, order;
  };
  const Record& find(std::string_view name, ArchiveType type, std::size_t element_size) const;
  void expect_scalar(std::string_view name, const Record& r) const;
  void copy_out(const Record& r, void* dst) const;

  std::filesystem::path path_;
  std::string bytes_;
  std::map<std::string, Record, std::less<>> records_;
};

// 64-bit FNV-1a, the archive checksum.
std::uint64_t fnv1a64(std::string_view bytes);

}  // namespace orogen
