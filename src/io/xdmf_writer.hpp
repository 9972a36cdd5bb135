#pragma once
// XDMF (version 2) sidecars that let ParaView and VisIt open Orogen's HDF5 snapshots with their
// stock XDMF readers: a temporal collection with, per output, the discs as a point set
// (Polyvertex, every per-disc dataset an attribute, pointing straight at the datasets of that
// output's HDF5 file), the walls as line cells, clipped around the discs and written inline, and,
// where the output stored its contacts, the contacts as line cells coloured by their forces
// (docs/output-files.md).
#include <hdf5.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace orogen {

struct XdmfArray {
  std::string name;         // dataset name
  std::string number_type;  // XDMF NumberType: Float, Int, UInt, Char, UChar
  std::size_t precision = 8;
};

// One output as the sidecar lists it.
struct XdmfOutput {
  std::string file;   // the HDF5 file, relative to the sidecar's folder
  std::string group;  // the output's group in that file, ending in '/': "/" or "/output_000000/"
  double time = 0;
  std::size_t n_discs = 0;
  bool has_xy = false;  // the output has the (n, 2) view `xy` (outputs written before it lack it)
  std::vector<std::array<double, 4>> walls;  // clipped for display (wall_display.hpp), written inline
  std::vector<XdmfArray> arrays;  // the 1-D per-disc datasets, in name order
  std::size_t n_contacts = 0;     // rows of the `contacts` group (output.contacts), 0 = none stored
};

// Reads what the sidecar needs from an output's group (its `time` attribute, `x`, `y` and
// `walls`, every 1-D dataset with one value per disc, and the size of a `contacts` group).
XdmfOutput describe_xdmf_output(hid_t group, std::string file, std::string group_path);

// The discs' vertex cells of every output read the first n entries of one dataset 0, 1, 2, ...
// (kDiscIndexDataset at the root of `file`, the run's index file, relative to the sidecar's
// folder), `size` entries long: at least the largest output's number of discs.
inline constexpr const char* kDiscIndexDataset = "disc_index";
struct XdmfIndex {
  std::string file;
  std::size_t size = 0;
};
std::size_t most_discs(const std::vector<XdmfOutput>& outputs);
// Writes kDiscIndexDataset, 0 to n - 1 as int32, at the root of an HDF5 file.
void write_disc_index(hid_t file, std::size_t n);

// Writes the sidecar (atomically): one temporal collection of the outputs, in order.
void write_xdmf(const std::filesystem::path& path, const std::vector<XdmfOutput>& outputs, const XdmfIndex& index);

// "snapshots.xmf" beside "snapshots.h5".
std::filesystem::path xdmf_sidecar(const std::filesystem::path& h5_file);

}  // namespace orogen
