#include "io/hdf5_labelled.hpp"

#include <H5DSpublic.h>

#include <functional>

#include "io/hdf5_file.hpp"

namespace orogen::h5 {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error("HDF5: cannot " + what);
}

// Creates and fills a dataset of the given shape; returns it open (the caller closes it).
Object create(hid_t loc, const std::string& name, hid_t type, const std::vector<hsize_t>& dims, const void* data) {
  Object space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (space.id() < 0) throw Error("HDF5: cannot make the dataspace of " + name);
  // No modification times: the same analysis gives the same bytes.
  Object dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  check(H5Pset_obj_track_times(dcpl.id(), false), "switch off times for " + name);
  Object set(H5Dcreate2(loc, name.c_str(), type, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT), H5Dclose);
  if (set.id() < 0) throw Error("HDF5: cannot create dataset " + name);
  hsize_t total = 1;
  for (auto d : dims) total *= d;
  if (total > 0) check(H5Dwrite(set.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
  return set;
}

void describe(hid_t set, const VarInfo& info) {
  set_attr_string(set, "units", info.units);
  set_attr_string(set, "description", info.description);
}

template <class T>
void dimension(hid_t loc, const std::string& name, std::span<const T> v, hid_t type, const VarInfo& info) {
  Object set = create(loc, name, type, {v.size()}, v.data());
  check(H5DSset_scale(set.id(), name.c_str()), "mark " + name + " as a dimension scale");
  describe(set.id(), info);
}

template <class T>
void variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims, std::span<const T> v,
              hid_t type, const VarInfo& info) {
  std::vector<hsize_t> shape;
  std::vector<Object> scales;
  for (const auto& d : dims) {
    scales.emplace_back(H5Dopen2(loc, d.c_str(), H5P_DEFAULT), H5Dclose);
    if (scales.back().id() < 0) throw Error("HDF5: no dimension " + d + " for " + name);
    Object space(H5Dget_space(scales.back().id()), H5Sclose);
    hsize_t n = 0;
    H5Sget_simple_extent_dims(space.id(), &n, nullptr);
    shape.push_back(n);
  }
  hsize_t total = 1;
  for (auto n : shape) total *= n;
  if (total != v.size()) throw Error("HDF5: " + name + " has " + std::to_string(v.size()) + " values for its shape");
  Object set = create(loc, name, type, shape, v.data());
  for (unsigned k = 0; k < dims.size(); ++k)
    check(H5DSattach_scale(set.id(), scales[k].id(), k), "attach dimension " + dims[k] + " to " + name);
  describe(set.id(), info);
}

}  // namespace

void write_dimension(hid_t loc, const std::string& name, std::span<const double> v, const VarInfo& info) {
  dimension(loc, name, v, H5T_NATIVE_DOUBLE, info);
}
void write_dimension(hid_t loc, const std::string& name, std::span<const std::int64_t> v, const VarInfo& info) {
  dimension(loc, name, v, H5T_NATIVE_INT64, info);
}
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const double> v, const VarInfo& info) {
  variable(loc, name, dims, v, H5T_NATIVE_DOUBLE, info);
}
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const float> v, const VarInfo& info) {
  variable(loc, name, dims, v, H5T_NATIVE_FLOAT, info);
}
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const std::int64_t> v, const VarInfo& info) {
  variable(loc, name, dims, v, H5T_NATIVE_INT64, info);
}
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const std::uint8_t> v, const VarInfo& info) {
  variable(loc, name, dims, v, H5T_NATIVE_UINT8, info);
}

}  // namespace orogen::h5
