#include "io/xdmf_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/wall_display.hpp"
#include "io/xml_escape.hpp"

namespace orogen {
namespace {

std::string number_type(const h5::DatasetInfo& info) {
  switch (info.kind) {
    case h5::Kind::Float: return "Float";
    case h5::Kind::SignedInt: return info.element_size == 1 ? "Char" : "Int";
    case h5::Kind::UnsignedInt: return info.element_size == 1 ? "UChar" : "UInt";
    default: return "";
  }
}

// A DataItem reading dataset `name` of output `o` (HDF5 paths: "file:/group/name").
std::string hdf_item(const XdmfOutput& o, const std::string& name, const std::string& dims, const std::string& type,
                     std::size_t precision) {
  return fmt::format(R"(<DataItem Dimensions="{}" NumberType="{}" Precision="{}" Format="HDF">{}:{}{}</DataItem>)",
                     dims, type, precision, xml_escape(o.file), xml_escape(o.group), xml_escape(name));
}

// The discs' cells: vertex k is point k, the first n entries of the index file's 0, 1, 2, ...
// ParaView's default XDMF reader (Xdmf3) draws a point set only with explicit cells.
std::string disc_cells(const XdmfIndex& index, const std::string& n) {
  return fmt::format("            <DataItem ItemType=\"HyperSlab\" Dimensions=\"{0} 1\" Type=\"HyperSlab\">\n"
                     "              <DataItem Dimensions=\"3 1\" Format=\"XML\">0 1 {0}</DataItem>\n"
                     "              <DataItem Dimensions=\"{1}\" NumberType=\"Int\" Precision=\"4\" "
                     "Format=\"HDF\">{2}:/{3}</DataItem>\n"
                     "            </DataItem>\n",
                     n, index.size, xml_escape(index.file), kDiscIndexDataset);
}

void write_discs(std::string& out, const XdmfOutput& o, const XdmfIndex& index) {
  const std::string n = std::to_string(o.n_discs);
  if (o.has_xy && index.size >= o.n_discs) {
    // The geometry is the (n, 2) view `xy`: the default reader takes only a plain array.
    out += fmt::format("        <Grid Name=\"discs\" GridType=\"Uniform\">\n"
                       "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" NodesPerElement=\"1\">\n"
                       "{}          </Topology>\n"
                       "          <Geometry GeometryType=\"XY\">\n            {}\n          </Geometry>\n",
                       n, disc_cells(index, n), hdf_item(o, "xy", n + " 2", "Float", 8));
  } else {
    // Outputs written before `xy` existed: x and y joined into XY pairs (the legacy reader only).
    out += fmt::format("        <Grid Name=\"discs\" GridType=\"Uniform\">\n"
                       "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\"/>\n",
                       n);
    out += fmt::format("          <Geometry GeometryType=\"XY\">\n"
                       "            <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1)\" Dimensions=\"{} 2\">\n"
                       "              {}\n              {}\n"
                       "            </DataItem>\n          </Geometry>\n",
                       n, hdf_item(o, "x", n, "Float", 8), hdf_item(o, "y", n, "Float", 8));
  }
  for (const auto& a : o.arrays)
    out += fmt::format("          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                       "            {}\n          </Attribute>\n",
                       xml_escape(a.name), hdf_item(o, a.name, n, a.number_type, a.precision));
  out += "        </Grid>\n";
}

void write_walls(std::string& out, const XdmfOutput& o) {
  // Wall w is the line from point 2w (ax, ay) to point 2w + 1 (bx, by).
  // The cells are explicit: without them the default reader (Xdmf3) makes none.
  std::string xy, cells;
  for (const auto& w : o.walls) xy += fmt::format(" {} {} {} {}", w[0], w[1], w[2], w[3]);
  for (std::size_t k = 0; k < 2 * o.walls.size(); ++k) cells += fmt::format(" {}", k);
  out += fmt::format("        <Grid Name=\"walls\" GridType=\"Uniform\">\n"
                     "          <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"{0}\">\n"
                     "            <DataItem Dimensions=\"{0} 2\" NumberType=\"Int\" Format=\"XML\">{3}</DataItem>\n"
                     "          </Topology>\n"
                     "          <Geometry GeometryType=\"XY\">\n"
                     "            <DataItem Dimensions=\"{1} 2\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">{2}</DataItem>\n"
                     "          </Geometry>\n        </Grid>\n",
                     o.walls.size(), 2 * o.walls.size(), xy, cells);
}

void write_contacts(std::string& out, const XdmfOutput& o) {
  // Contact k is the line from point 2k to point 2k + 1 of contacts/segment_points (snapshot_groups).
  const std::string c = std::to_string(o.n_contacts);
  const std::string points = std::to_string(2 * o.n_contacts) + " 2";
  out += fmt::format("        <Grid Name=\"contacts\" GridType=\"Uniform\">\n"
                     "          <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" "
                     "NumberOfElements=\"{}\">\n"
                     "            {}\n          </Topology>\n"
                     "          <Geometry GeometryType=\"XY\">\n            {}\n          </Geometry>\n",
                     c, hdf_item(o, "contacts/segment_cells", c + " 2", "Int", 8),
                     hdf_item(o, "contacts/segment_points", points, "Float", 8));
  for (const char* name : {"fn", "ft", "overlap"})
    out += fmt::format("          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
                       "            {}\n          </Attribute>\n",
                       name, hdf_item(o, std::string("contacts/") + name, c, "Float", 8));
  out += "        </Grid>\n";
}

}  // namespace

XdmfOutput describe_xdmf_output(hid_t group, std::string file, std::string group_path) {
  XdmfOutput o;
  o.file = std::move(file);
  o.group = std::move(group_path);
  o.time = h5::get_attr_double(group, "time");
  const auto x = h5::dataset_info(group, "x");
  if (x.dims.size() != 1) throw h5::Error("snapshot dataset 'x' is not 1-D");
  o.n_discs = x.dims[0];
  o.has_xy = h5::exists(group, "xy");
  if (h5::exists(group, "walls")) {
    const h5::Matrix m = h5::read_2d(group, "walls");
    std::vector<std::array<double, 4>> walls(m.rows);
    if (m.cols == 4)
      for (std::size_t r = 0; r < m.rows; ++r) std::copy_n(m.data.begin() + 4 * r, 4, walls[r].begin());
    o.walls = walls_for_display(walls, h5::read<double>(group, "x"), h5::read<double>(group, "y"));
  }
  if (h5::exists(group, "contacts") && h5::is_group(group, "contacts")) {
    const auto fn = h5::dataset_info(group, "contacts/fn");
    if (fn.dims.size() == 1) o.n_contacts = fn.dims[0];
  }
  for (const auto& name : h5::list(group)) {
    if (name == "walls" || h5::is_group(group, name)) continue;  // extra groups: contacts below, others not shown
    const auto info = h5::dataset_info(group, name);
    const std::string type = number_type(info);
    if (info.dims.size() != 1 || info.dims[0] != o.n_discs || type.empty()) continue;
    o.arrays.push_back({name, type, info.element_size});
  }
  return o;
}

void write_xdmf(const std::filesystem::path& path, const std::vector<XdmfOutput>& outputs, const XdmfIndex& index) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"2.0\">\n  <Domain>\n"
      "    <Grid Name=\"outputs\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& o : outputs) {
    out += fmt::format("      <Grid Name=\"output\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
                       "        <Time Value=\"{}\"/>\n",
                       o.time);
    if (o.n_discs > 0) write_discs(out, o, index);
    if (!o.walls.empty()) write_walls(out, o);
    if (o.n_contacts > 0) write_contacts(out, o);
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  write_file_atomically(path, out);
}

std::size_t most_discs(const std::vector<XdmfOutput>& outputs) {
  std::size_t n = 0;
  for (const auto& o : outputs) n = std::max(n, o.n_discs);
  return n;
}

void write_disc_index(hid_t file, std::size_t n) {
  std::vector<std::int32_t> index(n);
  for (std::size_t k = 0; k < n; ++k) index[k] = static_cast<std::int32_t>(k);
  h5::write(file, kDiscIndexDataset, std::span<const std::int32_t>(index));
  h5::set_dataset_attr_string(file, kDiscIndexDataset, "units", "-");
  h5::set_dataset_attr_string(file, kDiscIndexDataset, "description",
                              "0, 1, 2, ...: vertex k is disc k; the discs' cells of the XDMF sidecar "
                              "(snapshots.xmf, packing.xmf)");
}

std::filesystem::path xdmf_sidecar(const std::filesystem::path& h5_file) {
  std::filesystem::path p = h5_file;
  return p.replace_extension(".xmf");
}

}  // namespace orogen
