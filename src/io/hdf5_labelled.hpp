#pragma once
// Labelled n-dimensional datasets for files that xarray / netCDF readers open as they are:
// each dimension is a 1-D dataset marked as an HDF5 dimension scale, every variable has its
// scales attached in order and carries `units` and `description` attributes.
#include <hdf5.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace orogen::h5 {

struct VarInfo {
  std::string units, description;
};

// A 1-D coordinate `name` that is its own dimension scale.
void write_dimension(hid_t loc, const std::string& name, std::span<const double> values, const VarInfo& info);
void write_dimension(hid_t loc, const std::string& name, std::span<const std::int64_t> values, const VarInfo& info);

// A variable over the named dimensions (already written with write_dimension), row-major.
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const double> values, const VarInfo& info);
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const float> values, const VarInfo& info);
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const std::int64_t> values, const VarInfo& info);
void write_variable(hid_t loc, const std::string& name, const std::vector<std::string>& dims,
                    std::span<const std::uint8_t> values, const VarInfo& info);

}  // namespace orogen::h5
