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

void write_discs(std::string& out, const XdmfOutput& o) {
  const std::string n = std::to_string(o.n_discs);
  out += fmt::format("        <Grid Name=\"discs\" GridType=\"Uniform\">\n"
                     "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\"/>\n",
                     n);
  // x and y are stored apart; XDMF 2 has no X_Y geometry, so join them into XY pairs.
  out += fmt::format("          <Geometry GeometryType=\"XY\">\n"
                     "            <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1)\" Dimensions=\"{} 2\">\n"
                     "              {}\n              {}\n"
                     "            </DataItem>\n          </Geometry>\n",
                     n, hdf_item(o, "x", n, "Float", 8), hdf_item(o, "y", n, "Float", 8));
  for (const auto& a : o.arrays)
    out += fmt::format("          <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                       "            {}\n          </Attribute>\n",
                       xml_escape(a.name), hdf_item(o, a.name, n, a.number_type, a.precision));
  out += "        </Grid>\n";
}

void write_walls(std::string& out, const XdmfOutput& o) {
  // Wall w is the line from point 2w (ax, ay) to point 2w + 1 (bx, by).
  std::string xy;
  for (const auto& w : o.walls) xy += fmt::format(" {} {} {} {}", w[0], w[1], w[2], w[3]);
  out += fmt::format("        <Grid Name=\"walls\" GridType=\"Uniform\">\n"
                     "          <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"{}\"/>\n"
                     "          <Geometry GeometryType=\"XY\">\n"
                     "            <DataItem Dimensions=\"{} 2\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">{}</DataItem>\n"
                     "          </Geometry>\n        </Grid>\n",
                     o.walls.size(), 2 * o.walls.size(), xy);
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

void write_xdmf(const std::filesystem::path& path, const std::vector<XdmfOutput>& outputs) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"2.0\">\n  <Domain>\n"
      "    <Grid Name=\"outputs\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& o : outputs) {
    out += fmt::format("      <Grid Name=\"output\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
                       "        <Time Value=\"{}\"/>\n",
                       o.time);
    if (o.n_discs > 0) write_discs(out, o);
    if (!o.walls.empty()) write_walls(out, o);
    if (o.n_contacts > 0) write_contacts(out, o);
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  write_file_atomically(path, out);
}

std::filesystem::path xdmf_sidecar(const std::filesystem::path& h5_file) {
  std::filesystem::path p = h5_file;
  return p.replace_extension(".xmf");
}

}  // namespace orogen
