#include "io/hdf5_file.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace orogen::h5 {
namespace {

// HDF5 prints its error stack to stderr by default; we turn it into exception text instead.
// Silences HDF5's own error printing (errors become exceptions with its message), once per
// process. Also keeps HDF5 from closing, at exit, the files whose close failed: a file that
// could not be flushed (a full disk) is left half-freed inside HDF5 1.10, and its own clean-up
// at exit then dies by SIGSEGV (H5F__close_cb). Every file this program writes is closed
// explicitly (and made durable with fsync) before it counts, so nothing rests on that
// clean-up. H5dont_atexit must come before any other HDF5 call.
void quiet() {
  static const bool no_atexit = H5dont_atexit() >= 0;
  (void)no_atexit;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

// The text between `key = '` and the next quote in HDF5's description, or "".
std::string quoted_field(const std::string& desc, const std::string& key) {
  const std::size_t begin = desc.find(key + " = '");
  if (begin == std::string::npos) return "";
  const std::size_t from = begin + key.size() + 4;
  const std::size_t end = desc.find('\'', from);
  return end == std::string::npos ? "" : desc.substr(from, end - from);
}

// A failed system call is described by HDF5 with buffer addresses and byte counts; keep what
// a user can act on: the system's message and the file.
std::string shorter_reason(const std::string& desc) {
  const std::string message = quoted_field(desc, "error message"), file = quoted_field(desc, "filename");
  if (message.empty()) return desc;
  return file.empty() ? message : message + ", file '" + file + "'";
}

// The innermost description on HDF5's error stack: the most specific reason it has.
std::string reason() {
  std::string out;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
        if (e->desc != nullptr && e->desc[0] != '\0') *static_cast<std::string*>(data) = e->desc;
        return 0;
      },
      &out);
  H5Eclear2(H5E_DEFAULT);
  return shorter_reason(out);
}

[[noreturn]] void fail(const std::string& what) {
  const std::string why = reason();
  throw Error("HDF5: " + what + (why.empty() ? "" : " (" + why + ")"));
}

hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

std::string quoted(const std::string& name) { return "'" + name + "'"; }

Object make_space(std::span<const hsize_t> dims) {
  return {check_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), "cannot create dataspace"),
          H5Sclose};
}

Object make_scalar_space() { return {check_id(H5Screate(H5S_SCALAR), "cannot create dataspace"), H5Sclose}; }

template <class T>
struct Native;
template <>
struct Native<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t mem() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct Native<std::int64_t> {
  static hid_t file() { return H5T_STD_I64LE; }
  static hid_t mem() { return H5T_NATIVE_INT64; }
};
template <>
struct Native<std::int32_t> {
  static hid_t file() { return H5T_STD_I32LE; }
  static hid_t mem() { return H5T_NATIVE_INT32; }
};
template <>
struct Native<std::uint8_t> {
  static hid_t file() { return H5T_STD_U8LE; }
  static hid_t mem() { return H5T_NATIVE_UINT8; }
};

template <class T>
constexpr Kind kind_of() {
  if constexpr (std::is_floating_point_v<T>) return Kind::Float;
  else if constexpr (std::is_signed_v<T>) return Kind::SignedInt;
  else return Kind::UnsignedInt;
}

Kind kind_of_type(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_FLOAT: return Kind::Float;
    case H5T_INTEGER: return H5Tget_sign(type) == H5T_SGN_NONE ? Kind::UnsignedInt : Kind::SignedInt;
    case H5T_STRING: return Kind::String;
    default: return Kind::Other;
  }
}

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Float: return "float";
    case Kind::SignedInt: return "signed integer";
    case Kind::UnsignedInt: return "unsigned integer";
    case Kind::String: return "string";
    default: return "other";
  }
}

// Creation properties without modification times, which HDF5 stores by default: the same run
// then writes the same bytes, not only the same values.
Object untimed(hid_t property_class) {
  Object plist(check_id(H5Pcreate(property_class), "cannot create property list"), H5Pclose);
  check(H5Pset_obj_track_times(plist.id(), false), "cannot switch off object times");
  return plist;
}

// Chunked + shuffled + deflated storage when asked for and the filter is present.
Object make_dcpl(std::span<const hsize_t> dims, WriteOptions opt) {
  Object dcpl = untimed(H5P_DATASET_CREATE);
  const bool empty = std::any_of(dims.begin(), dims.end(), [](hsize_t d) { return d == 0; });
  if (opt.deflate > 0 && !empty && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    // About 64 Ki elements per chunk: large enough to compress well, small for the cache.
    std::vector<hsize_t> chunk(dims.begin(), dims.end());
    hsize_t inner = 1;
    for (std::size_t k = 1; k < chunk.size(); ++k) inner *= chunk[k];
    chunk[0] = std::min<hsize_t>(chunk[0], std::max<hsize_t>(1, 65536 / inner));
    check(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), "cannot set chunking");
    check(H5Pset_shuffle(dcpl.id()), "cannot set shuffle filter");
    check(H5Pset_deflate(dcpl.id(), static_cast<unsigned>(std::min(opt.deflate, 9))), "cannot set deflate");
  }
  return dcpl;
}

template <class T>
void write_nd(hid_t loc, const std::string& name, const T* data, std::span<const hsize_t> dims, WriteOptions opt) {
  Object space = make_space(dims);
  Object dcpl = make_dcpl(dims, opt);
  Object ds(check_id(H5Dcreate2(loc, name.c_str(), Native<T>::file(), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                  "cannot create dataset " + quoted(name)),
            H5Dclose);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  if (total > 0)
    check(H5Dwrite(ds.id(), Native<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "cannot write dataset " + quoted(name));
  ds.close();
}

Object open_dataset(hid_t loc, const std::string& name) {
  return {check_id(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "cannot open dataset " + quoted(name)), H5Dclose};
}

std::vector<hsize_t> dims_of(const Object& ds, const std::string& name) {
  Object space(check_id(H5Dget_space(ds.id()), "cannot get dataspace of " + quoted(name)), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0) fail("cannot get rank of " + quoted(name));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr) < 0)
    fail("cannot get dimensions of " + quoted(name));
  return dims;
}

// Checks that the stored element type is exactly T, so reads never convert silently.
template <class T>
void expect_type(const Object& ds, const std::string& name) {
  Object type(check_id(H5Dget_type(ds.id()), "cannot get type of " + quoted(name)), H5Tclose);
  const Kind k = kind_of_type(type.id());
  if (k != kind_of<T>() || H5Tget_size(type.id()) != sizeof(T))
    throw Error("HDF5: dataset " + quoted(name) + " holds " + std::to_string(H5Tget_size(type.id())) + "-byte " +
                kind_name(k) + " values, expected " + std::to_string(sizeof(T)) + "-byte " + kind_name(kind_of<T>()));
}

Object open_attr(hid_t obj, const std::string& name) {
  return {check_id(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "cannot open attribute " + quoted(name)), H5Aclose};
}

// Opens `name` for rewriting if it already has the wanted type, else (re)creates it.
Object attr_for_write(hid_t obj, const std::string& name, hid_t file_type, bool variable_string) {
  if (has_attr(obj, name)) {
    Object a = open_attr(obj, name);
    Object t(check_id(H5Aget_type(a.id()), "cannot get type of attribute " + quoted(name)), H5Tclose);
    const bool same = variable_string ? (H5Tget_class(t.id()) == H5T_STRING && H5Tis_variable_str(t.id()) > 0)
                                      : H5Tequal(t.id(), file_type) > 0;
    Object s(check_id(H5Aget_space(a.id()), "cannot get dataspace of attribute " + quoted(name)), H5Sclose);
    if (same && H5Sget_simple_extent_npoints(s.id()) == 1) return a;
    a.close();
    check(H5Adelete(obj, name.c_str()), "cannot delete attribute " + quoted(name));
  }
  Object space = make_scalar_space();
  return {check_id(H5Acreate2(obj, name.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                "cannot create attribute " + quoted(name)),
          H5Aclose};
}

Object vlen_string_type() {
  Object t(check_id(H5Tcopy(H5T_C_S1), "cannot copy string type"), H5Tclose);
  check(H5Tset_size(t.id(), H5T_VARIABLE), "cannot size string type");
  check(H5Tset_cset(t.id(), H5T_CSET_UTF8), "cannot set string charset");
  return t;
}

void expect_scalar(const Object& a, const std::string& name) {
  Object s(check_id(H5Aget_space(a.id()), "cannot get dataspace of attribute " + quoted(name)), H5Sclose);
  if (H5Sget_simple_extent_npoints(s.id()) != 1) throw Error("HDF5: attribute " + quoted(name) + " is not a scalar");
}

Kind attr_kind(const Object& a, const std::string& name) {
  Object t(check_id(H5Aget_type(a.id()), "cannot get type of attribute " + quoted(name)), H5Tclose);
  return kind_of_type(t.id());
}

}  // namespace

Object& Object::operator=(Object&& o) noexcept {
  if (this != &o) {
    release();
    id_ = o.id_;
    closer_ = o.closer_;
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Object::release() noexcept {
  if (id_ >= 0 && closer_ != nullptr) closer_(id_);
  id_ = H5I_INVALID_HID;
}

void Object::close() {
  const hid_t id = id_;
  id_ = H5I_INVALID_HID;
  if (id >= 0 && closer_ != nullptr && closer_(id) < 0) fail("cannot close object");
}

File File::create(const std::filesystem::path& path) {
  quiet();
  Object fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), "cannot create property list"), H5Pclose);
  // Closing the file with objects still open is a bug: make it an error, not a leak.
  check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "cannot set close degree");
  File f(check_id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.id()),
               "cannot create file '" + path.string() + "'"),
         H5Fclose);
  f.path_ = path;
  return f;
}

File File::create_in_memory() {
  quiet();
  Object fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), "cannot create property list"), H5Pclose);
  check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "cannot set close degree");
  check(H5Pset_fapl_core(fapl.id(), 1 << 20, false), "cannot set the in-memory driver");
  // The name is only a label for the core driver without a backing store.
  File f(check_id(H5Fcreate("orogen-in-memory.h5", H5F_ACC_TRUNC, H5P_DEFAULT, fapl.id()),
               "cannot create an in-memory file"),
         H5Fclose);
  f.path_ = "(in memory)";
  return f;
}

std::string File::image() {
  flush();
  const ssize_t size = H5Fget_file_image(id(), nullptr, 0);
  if (size < 0) fail("cannot get the image of file '" + path_.string() + "'");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(id(), bytes.data(), bytes.size()) != size) fail("cannot copy the image of file '" + path_.string() + "'");
  return bytes;
}

File File::open(const std::filesystem::path& path, Mode mode) {
  quiet();
  Object fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), "cannot create property list"), H5Pclose);
  check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "cannot set close degree");
  const unsigned flags = mode == Mode::ReadWrite ? H5F_ACC_RDWR : H5F_ACC_RDONLY;
  File f(check_id(H5Fopen(path.c_str(), flags, fapl.id()), "cannot open file '" + path.string() + "'"), H5Fclose);
  f.path_ = path;
  return f;
}

void File::flush() { check(H5Fflush(id(), H5F_SCOPE_GLOBAL), "cannot flush file '" + path_.string() + "'"); }

Group Group::create(hid_t loc, const std::string& name) {
  Object gcpl = untimed(H5P_GROUP_CREATE);
  return {check_id(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT),
                "cannot create group " + quoted(name)),
          H5Gclose};
}

Group Group::open(hid_t loc, const std::string& name) {
  return {check_id(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), "cannot open group " + quoted(name)), H5Gclose};
}

bool exists(hid_t loc, const std::string& name) {
  const htri_t r = H5Lexists(loc, name.c_str(), H5P_DEFAULT);
  if (r < 0) fail("cannot look up " + quoted(name));
  return r > 0;
}

void remove(hid_t loc, const std::string& name) {
  check(H5Ldelete(loc, name.c_str(), H5P_DEFAULT), "cannot delete " + quoted(name));
}

void link_external(hid_t loc, const std::string& name, const std::string& file, const std::string& object) {
  check(H5Lcreate_external(file.c_str(), object.c_str(), loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
        "cannot link " + quoted(name) + " to " + quoted(file));
}

bool is_group(hid_t loc, const std::string& name) {
  Object obj(check_id(H5Oopen(loc, name.c_str(), H5P_DEFAULT), "cannot open " + quoted(name)), H5Oclose);
  return H5Iget_type(obj.id()) == H5I_GROUP;
}

bool is_external_link(hid_t loc, const std::string& name) {
  H5L_info_t info;
  check(H5Lget_info(loc, name.c_str(), &info, H5P_DEFAULT), "cannot look up " + quoted(name));
  return info.type == H5L_TYPE_EXTERNAL;
}

std::vector<std::string> list(hid_t loc) {
  std::vector<std::string> names;
  hsize_t index = 0;
  // A generic lambda converts to the callback type of HDF5 1.10 and 1.12+ alike.
  check(H5Literate(
            loc, H5_INDEX_NAME, H5_ITER_INC, &index,
            [](hid_t, const char* name, const auto*, void* data) -> herr_t {
              static_cast<std::vector<std::string>*>(data)->emplace_back(name);
              return 0;
            },
            &names),
        "cannot list links");
  return names;
}

void write(hid_t loc, const std::string& name, std::span<const double> v, WriteOptions opt) {
  const std::array<hsize_t, 1> dims{v.size()};
  write_nd(loc, name, v.data(), dims, opt);
}
void write(hid_t loc, const std::string& name, std::span<const std::int64_t> v, WriteOptions opt) {
  const std::array<hsize_t, 1> dims{v.size()};
  write_nd(loc, name, v.data(), dims, opt);
}
void write(hid_t loc, const std::string& name, std::span<const std::int32_t> v, WriteOptions opt) {
  const std::array<hsize_t, 1> dims{v.size()};
  write_nd(loc, name, v.data(), dims, opt);
}
void write(hid_t loc, const std::string& name, std::span<const std::uint8_t> v, WriteOptions opt) {
  const std::array<hsize_t, 1> dims{v.size()};
  write_nd(loc, name, v.data(), dims, opt);
}

void write_2d(hid_t loc, const std::string& name, std::span<const double> v, std::size_t rows, std::size_t cols,
              WriteOptions opt) {
  if (v.size() != rows * cols)
    throw Error("HDF5: dataset " + quoted(name) + ": " + std::to_string(v.size()) + " values for a " +
                std::to_string(rows) + " x " + std::to_string(cols) + " matrix");
  const std::array<hsize_t, 2> dims{rows, cols};
  write_nd(loc, name, v.data(), dims, opt);
}

void write_2d(hid_t loc, const std::string& name, std::span<const std::int64_t> v, std::size_t rows,
              std::size_t cols, WriteOptions opt) {
  if (v.size() != rows * cols)
    throw Error("HDF5: dataset " + quoted(name) + ": " + std::to_string(v.size()) + " values for a " +
                std::to_string(rows) + " x " + std::to_string(cols) + " matrix");
  const std::array<hsize_t, 2> dims{rows, cols};
  write_nd(loc, name, v.data(), dims, opt);
}

void write_columns_view(hid_t loc, const std::string& name, const std::vector<std::string>& columns, std::size_t n) {
  const std::array<hsize_t, 2> dims{n, columns.size()};
  const std::array<hsize_t, 1> column_dims{n};
  Object space = make_space(dims);
  Object source = make_space(column_dims);
  Object dcpl = untimed(H5P_DATASET_CREATE);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    // Column c of the view: rows 0..n-1, one element wide, from the whole source dataset.
    const std::array<hsize_t, 2> start{0, c}, count{n, 1};
    check(H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          "cannot select column " + std::to_string(c) + " of " + quoted(name));
    check(H5Pset_virtual(dcpl.id(), space.id(), ".", columns[c].c_str(), source.id()),
          "cannot map " + quoted(columns[c]) + " into " + quoted(name));
  }
  check(H5Sselect_all(space.id()), "cannot select all of " + quoted(name));
  Object ds(check_id(H5Dcreate2(loc, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                     "cannot create the virtual dataset " + quoted(name)),
            H5Dclose);
  ds.close();
}

template <class T>
std::vector<T> read(hid_t loc, const std::string& name) {
  Object ds = open_dataset(loc, name);
  expect_type<T>(ds, name);
  const auto dims = dims_of(ds, name);
  if (dims.size() != 1) throw Error("HDF5: dataset " + quoted(name) + " is not one-dimensional");
  std::vector<T> out(dims[0]);
  if (!out.empty())
    check(H5Dread(ds.id(), Native<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()),
          "cannot read dataset " + quoted(name));
  return out;
}
template std::vector<double> read<double>(hid_t, const std::string&);
template std::vector<std::int64_t> read<std::int64_t>(hid_t, const std::string&);
template std::vector<std::int32_t> read<std::int32_t>(hid_t, const std::string&);
template std::vector<std::uint8_t> read<std::uint8_t>(hid_t, const std::string&);

Matrix read_2d(hid_t loc, const std::string& name) {
  Object ds = open_dataset(loc, name);
  expect_type<double>(ds, name);
  const auto dims = dims_of(ds, name);
  if (dims.size() != 2) throw Error("HDF5: dataset " + quoted(name) + " is not two-dimensional");
  Matrix m{std::vector<double>(dims[0] * dims[1]), dims[0], dims[1]};
  if (!m.data.empty())
    check(H5Dread(ds.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, m.data.data()),
          "cannot read dataset " + quoted(name));
  return m;
}

DatasetInfo dataset_info(hid_t loc, const std::string& name) {
  Object ds = open_dataset(loc, name);
  Object type(check_id(H5Dget_type(ds.id()), "cannot get type of " + quoted(name)), H5Tclose);
  DatasetInfo info;
  info.kind = kind_of_type(type.id());
  info.element_size = H5Tget_size(type.id());
  for (hsize_t d : dims_of(ds, name)) info.dims.push_back(d);
  return info;
}

void set_attr_double(hid_t obj, const std::string& name, double value) {
  Object a = attr_for_write(obj, name, H5T_IEEE_F64LE, false);
  check(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, &value), "cannot write attribute " + quoted(name));
  a.close();
}

void set_attr_int64(hid_t obj, const std::string& name, std::int64_t value) {
  Object a = attr_for_write(obj, name, H5T_STD_I64LE, false);
  check(H5Awrite(a.id(), H5T_NATIVE_INT64, &value), "cannot write attribute " + quoted(name));
  a.close();
}

void set_attr_string(hid_t obj, const std::string& name, std::string_view value) {
  Object type = vlen_string_type();
  Object a = attr_for_write(obj, name, type.id(), true);
  const std::string copy(value);  // HDF5 wants a NUL-terminated char*
  const char* p = copy.c_str();
  check(H5Awrite(a.id(), type.id(), &p), "cannot write attribute " + quoted(name));
  a.close();
}

void set_dataset_attr_string(hid_t loc, const std::string& dataset, const std::string& name, std::string_view value) {
  Object ds = open_dataset(loc, dataset);
  set_attr_string(ds.id(), name, value);
  ds.close();
}

std::string get_dataset_attr_string(hid_t loc, const std::string& dataset, const std::string& name) {
  const Object ds = open_dataset(loc, dataset);
  return get_attr_string(ds.id(), name);
}

bool has_attr(hid_t obj, const std::string& name) {
  const htri_t r = H5Aexists(obj, name.c_str());
  if (r < 0) fail("cannot look up attribute " + quoted(name));
  return r > 0;
}

double get_attr_double(hid_t obj, const std::string& name) {
  Object a = open_attr(obj, name);
  expect_scalar(a, name);
  const Kind k = attr_kind(a, name);
  if (k != Kind::Float && k != Kind::SignedInt && k != Kind::UnsignedInt)
    throw Error("HDF5: attribute " + quoted(name) + " is not numeric");
  double value = 0;
  check(H5Aread(a.id(), H5T_NATIVE_DOUBLE, &value), "cannot read attribute " + quoted(name));
  return value;
}

std::int64_t get_attr_int64(hid_t obj, const std::string& name) {
  Object a = open_attr(obj, name);
  expect_scalar(a, name);
  const Kind k = attr_kind(a, name);
  if (k != Kind::SignedInt && k != Kind::UnsignedInt)
    throw Error("HDF5: attribute " + quoted(name) + " is not an integer");
  std::int64_t value = 0;
  check(H5Aread(a.id(), H5T_NATIVE_INT64, &value), "cannot read attribute " + quoted(name));
  return value;
}

std::string get_attr_string(hid_t obj, const std::string& name) {
  Object a = open_attr(obj, name);
  expect_scalar(a, name);
  Object ftype(check_id(H5Aget_type(a.id()), "cannot get type of attribute " + quoted(name)), H5Tclose);
  if (H5Tget_class(ftype.id()) != H5T_STRING) throw Error("HDF5: attribute " + quoted(name) + " is not a string");
  Object mtype(check_id(H5Tcopy(ftype.id()), "cannot copy string type"), H5Tclose);
  if (H5Tis_variable_str(ftype.id()) > 0) {
    char* p = nullptr;
    check(H5Aread(a.id(), mtype.id(), &p), "cannot read attribute " + quoted(name));
    std::string out = p != nullptr ? p : "";
    H5free_memory(p);
    return out;
  }
  std::string buf(H5Tget_size(ftype.id()), '\0');
  check(H5Aread(a.id(), mtype.id(), buf.data()), "cannot read attribute " + quoted(name));
  buf.resize(buf.find('\0') == std::string::npos ? buf.size() : buf.find('\0'));
  return buf;
}

std::vector<AttrInfo> list_attrs(hid_t obj) {
  std::vector<std::string> names;
  hsize_t index = 0;
  check(H5Aiterate2(
            obj, H5_INDEX_NAME, H5_ITER_INC, &index,
            [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
              static_cast<std::vector<std::string>*>(data)->emplace_back(name);
              return 0;
            },
            &names),
        "cannot list attributes");
  std::vector<AttrInfo> out;
  for (const auto& n : names) {
    Object a = open_attr(obj, n);
    out.push_back({n, attr_kind(a, n)});
  }
  return out;
}

}  // namespace orogen::h5
