#pragma once
// Thin RAII wrappers over the HDF5 C API: handles close themselves, failures throw
// orogen::h5::Error with what was being done, to which object, and HDF5's own reason.
// HDF5's automatic printing of its error stack is switched off.
#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace orogen::h5 {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Owns one hid_t and closes it with the matching H5?close.
class Object {
 public:
  using Closer = herr_t (*)(hid_t);
  Object() = default;
  Object(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Object() { release(); }
  Object(Object&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = H5I_INVALID_HID; }
  Object& operator=(Object&& o) noexcept;
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  hid_t id() const { return id_; }
  // Closes now and throws if HDF5 reports an error (the destructor cannot).
  void close();

 private:
  void release() noexcept;
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

class File : public Object {
 public:
  enum class Mode { ReadOnly, ReadWrite };
  static File create(const std::filesystem::path& path);  // truncates an existing file
  // A file that lives in memory only (HDF5's core driver); image() gives its bytes, which the
  // caller writes itself. Writers use it so that a failing disk is met in our own code:
  // HDF5 1.10 cannot recover from a write that fails while it closes a file on disk (it
  // crashes at exit).
  static File create_in_memory();
  std::string image();  // the whole file as bytes (flushes first)
  static File open(const std::filesystem::path& path, Mode mode);
  void flush();  // H5Fflush of the whole file
  const std::filesystem::path& path() const { return path_; }

 private:
  using Object::Object;
  std::filesystem::path path_;
};

class Group : public Object {
 public:
  static Group create(hid_t loc, const std::string& name);
  static Group open(hid_t loc, const std::string& name);

 private:
  using Object::Object;
};

// Links (groups or datasets) directly under `loc`.
bool exists(hid_t loc, const std::string& name);
void remove(hid_t loc, const std::string& name);  // H5Ldelete; space is not reclaimed
std::vector<std::string> list(hid_t loc);         // names in ascending name order
// A link `name` under `loc` to `object` in another file; a relative `file` is found from the
// directory of the file that holds the link (HDF5's rule), so a run folder can be moved whole.
void link_external(hid_t loc, const std::string& name, const std::string& file, const std::string& object);
bool is_external_link(hid_t loc, const std::string& name);
bool is_group(hid_t loc, const std::string& name);  // false for a dataset

// Dataset storage: 0 = contiguous; 1..9 = chunked with shuffle + deflate at that level.
struct WriteOptions {
  int deflate = 0;
};

void write(hid_t loc, const std::string& name, std::span<const double> v, WriteOptions opt = {});
void write(hid_t loc, const std::string& name, std::span<const std::int64_t> v, WriteOptions opt = {});
void write(hid_t loc, const std::string& name, std::span<const std::int32_t> v, WriteOptions opt = {});
void write(hid_t loc, const std::string& name, std::span<const std::uint8_t> v, WriteOptions opt = {});
// A rows x cols matrix of doubles stored row-major in `v`.
void write_2d(hid_t loc, const std::string& name, std::span<const double> v, std::size_t rows, std::size_t cols,
              WriteOptions opt = {});
void write_2d(hid_t loc, const std::string& name, std::span<const std::int64_t> v, std::size_t rows,
              std::size_t cols, WriteOptions opt = {});

// A (n x columns.size()) float64 virtual dataset whose column c reads the 1-D float64 dataset
// columns[c] (n values, a path in the same file): no data is copied. It lets a reader that
// wants interleaved coordinates (ParaView's default XDMF reader) read x and y as (x, y) rows.
void write_columns_view(hid_t loc, const std::string& name, const std::vector<std::string>& columns, std::size_t n);

// Reads a 1-D dataset of exactly the matching element type (bit-exact round trip).
template <class T>
std::vector<T> read(hid_t loc, const std::string& name);
extern template std::vector<double> read<double>(hid_t, const std::string&);
extern template std::vector<std::int64_t> read<std::int64_t>(hid_t, const std::string&);
extern template std::vector<std::int32_t> read<std::int32_t>(hid_t, const std::string&);
extern template std::vector<std::uint8_t> read<std::uint8_t>(hid_t, const std::string&);

struct Matrix {
  std::vector<double> data;  // row-major
  std::size_t rows = 0, cols = 0;
};
Matrix read_2d(hid_t loc, const std::string& name);

enum class Kind { Float, SignedInt, UnsignedInt, String, Other };

struct DatasetInfo {
  Kind kind = Kind::Other;
  std::size_t element_size = 0;
  std::vector<std::size_t> dims;
};
DatasetInfo dataset_info(hid_t loc, const std::string& name);

// Scalar attributes on a file (its root group) or a group. Setting an existing attribute
// of the same kind rewrites it in place; otherwise it is replaced.
void set_attr_double(hid_t obj, const std::string& name, double value);
void set_attr_int64(hid_t obj, const std::string& name, std::int64_t value);
void set_attr_string(hid_t obj, const std::string& name, std::string_view value);  // UTF-8, variable length
bool has_attr(hid_t obj, const std::string& name);
// The same on the dataset `dataset` under `loc` (opened by name for the call).
void set_dataset_attr_string(hid_t loc, const std::string& dataset, const std::string& name, std::string_view value);
std::string get_dataset_attr_string(hid_t loc, const std::string& dataset, const std::string& name);
double get_attr_double(hid_t obj, const std::string& name);       // any numeric attribute
std::int64_t get_attr_int64(hid_t obj, const std::string& name);  // integer attributes only
std::string get_attr_string(hid_t obj, const std::string& name);  // fixed or variable length

struct AttrInfo {
  std::string name;
  Kind kind = Kind::Other;
};
std::vector<AttrInfo> list_attrs(hid_t obj);  // in ascending name order

}  // namespace orogen::h5
