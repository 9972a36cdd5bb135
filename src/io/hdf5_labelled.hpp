#pragma once
// Labelled n-dimensional datasets for files that xarray / netCDF readers open as they are:
// each dimension is a 1-D dataset marked as an HDF5 dimension scale, every variable has its
// scales attached in order and carries `units` and `description` attributes.
//
// The datasets grow: they are chunked with every dimension unlimited (netCDF's unlimited
// dimensions), created empty and given their shape by `resize`, so that a file can be
// extended output by output without being rewritten. Floating-point datasets read NaN where
// nothing was written (a particle absent from an output); the others read 0 there.
#include <hdf5.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace orogen::h5 {

struct VarInfo {
  std::string units, description;
};

using Shape = std::vector<hsize_t>;

// For T in double, float, std::int64_t, std::uint8_t.
// An empty 1-D coordinate `name` that is its own dimension scale.
template <class T>
void create_dimension(hid_t loc, const std::string& name, hsize_t chunk, const VarInfo& info);
// An empty variable over the named dimensions (created before it), stored in chunks of `chunk`.
template <class T>
void create_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims, const Shape& chunk,
                     const VarInfo& info);

Shape shape(hid_t loc, const std::string& name);
// Grows or shrinks a dataset; what is cut off is gone (HDF5 frees or refills those chunks).
void resize(hid_t loc, const std::string& name, const Shape& shape);

// The block of shape `count` at `start`, row-major; within the dataset's current shape.
template <class T>
void write_block(hid_t loc, const std::string& name, const Shape& start, const Shape& count, std::span<const T> v);
template <class T>
std::vector<T> read_block(hid_t loc, const std::string& name, const Shape& start, const Shape& count);

// Resizes to `shape` and writes all of it.
template <class T>
void write_all(hid_t loc, const std::string& name, const Shape& shape, std::span<const T> v) {
  resize(loc, name, shape);
  write_block<T>(loc, name, Shape(shape.size(), 0), shape, v);
}

}  // namespace orogen::h5
