#include "io/hdf5_labelled.hpp"

#include <H5DSpublic.h>

#include <limits>
#include <type_traits>

#include "io/hdf5_file.hpp"

namespace orogen::h5 {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error("HDF5: cannot " + what);
}

template <class T>
hid_t native();
template <>
hid_t native<double>() { return H5T_NATIVE_DOUBLE; }
template <>
hid_t native<float>() { return H5T_NATIVE_FLOAT; }
template <>
hid_t native<std::int64_t>() { return H5T_NATIVE_INT64; }
template <>
hid_t native<std::uint8_t>() { return H5T_NATIVE_UINT8; }

Object open(hid_t loc, const std::string& name) {
  Object set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.id() < 0) throw Error("HDF5: no dataset " + name);
  return set;
}

Shape shape_of(hid_t set) {
  Object space(H5Dget_space(set), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0) throw Error("HDF5: cannot read a dataset's shape");
  Shape s(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id(), s.data(), nullptr);
  return s;
}

// An empty chunked dataset, unlimited along every dimension; returned open.
template <class T>
Object create(hid_t loc, const std::string& name, const Shape& chunk) {
  const Shape zero(chunk.size(), 0), unlimited(chunk.size(), H5S_UNLIMITED);
  Object space(H5Screate_simple(static_cast<int>(chunk.size()), zero.data(), unlimited.data()), H5Sclose);
  if (space.id() < 0) throw Error("HDF5: cannot make the dataspace of " + name);
  Object dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // No modification times: the same analysis gives the same values and attributes.
  check(H5Pset_obj_track_times(dcpl.id(), false), "switch off times for " + name);
  check(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), "chunk " + name);
  if constexpr (std::is_floating_point_v<T>) {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    check(H5Pset_fill_value(dcpl.id(), native<T>(), &nan), "set the fill value of " + name);
  }
  Object set(H5Dcreate2(loc, name.c_str(), native<T>(), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT), H5Dclose);
  if (set.id() < 0) throw Error("HDF5: cannot create dataset " + name);
  return set;
}

void describe(hid_t set, const VarInfo& info) {
  set_attr_string(set, "units", info.units);
  set_attr_string(set, "description", info.description);
}

// A hyperslab of the dataset's space and a matching memory space.
struct Selection {
  Object file, memory;
};

Selection select(hid_t set, const std::string& name, const Shape& start, const Shape& count) {
  Selection s{Object(H5Dget_space(set), H5Sclose),
              Object(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), H5Sclose)};
  if (s.file.id() < 0 || s.memory.id() < 0) throw Error("HDF5: cannot select in " + name);
  check(H5Sselect_hyperslab(s.file.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
        "select a block of " + name);
  return s;
}

hsize_t product(const Shape& s) {
  hsize_t n = 1;
  for (auto d : s) n *= d;
  return n;
}

}  // namespace

template <class T>
void create_dimension(hid_t loc, const std::string& name, hsize_t chunk, const VarInfo& info) {
  Object set = create<T>(loc, name, {chunk});
  check(H5DSset_scale(set.id(), name.c_str()), "mark " + name + " as a dimension scale");
  describe(set.id(), info);
}

template <class T>
void create_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims, const Shape& chunk,
                     const VarInfo& info) {
  if (dims.size() != chunk.size()) throw Error("HDF5: " + name + ": one chunk length per dimension");
  Object set = create<T>(loc, name, chunk);
  for (unsigned k = 0; k < dims.size(); ++k) {
    Object scale = open(loc, dims[k]);
    check(H5DSattach_scale(set.id(), scale.id(), k), "attach dimension " + dims[k] + " to " + name);
  }
  describe(set.id(), info);
}

Shape shape(hid_t loc, const std::string& name) { return shape_of(open(loc, name).id()); }

void resize(hid_t loc, const std::string& name, const Shape& s) {
  Object set = open(loc, name);
  if (shape_of(set.id()) != s) check(H5Dset_extent(set.id(), s.data()), "resize " + name);
}

template <class T>
void write_block(hid_t loc, const std::string& name, const Shape& start, const Shape& count, std::span<const T> v) {
  if (product(count) != v.size())
    throw Error("HDF5: " + name + ": " + std::to_string(v.size()) + " values for a block of " +
                std::to_string(product(count)));
  if (v.empty()) return;
  Object set = open(loc, name);
  const Selection s = select(set.id(), name, start, count);
  check(H5Dwrite(set.id(), native<T>(), s.memory.id(), s.file.id(), H5P_DEFAULT, v.data()), "write " + name);
}

template <class T>
std::vector<T> read_block(hid_t loc, const std::string& name, const Shape& start, const Shape& count) {
  std::vector<T> v(product(count));
  if (v.empty()) return v;
  Object set = open(loc, name);
  const Selection s = select(set.id(), name, start, count);
  check(H5Dread(set.id(), native<T>(), s.memory.id(), s.file.id(), H5P_DEFAULT, v.data()), "read " + name);
  return v;
}

#define OROGEN_LABELLED(T)                                                                                    \
  template void create_dimension<T>(hid_t, const std::string&, hsize_t, const VarInfo&);                     \
  template void create_variable<T>(hid_t, const std::string&, const std::vector<std::string>&, const Shape&, \
                                   const VarInfo&);                                                          \
  template void write_block<T>(hid_t, const std::string&, const Shape&, const Shape&, std::span<const T>);   \
  template std::vector<T> read_block<T>(hid_t, const std::string&, const Shape&, const Shape&);
OROGEN_LABELLED(double)
OROGEN_LABELLED(float)
OROGEN_LABELLED(std::int64_t)
OROGEN_LABELLED(std::uint8_t)
#undef OROGEN_LABELLED

}  // namespace orogen::h5
