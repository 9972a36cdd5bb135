#include "io/vtp_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"
#include "io/wall_display.hpp"
#include "io/xml_escape.hpp"

namespace orogen {
namespace {

// The files say byte_order="LittleEndian" and hold raw memory images.
static_assert(std::endian::native == std::endian::little, "VTK output assumes a little-endian host");

std::string base64(std::span<const unsigned char> in) {
  static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= in.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t{in[i]} << 16) | (std::uint32_t{in[i + 1]} << 8) | in[i + 2];
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (const std::size_t rest = in.size() - i; rest > 0) {
    std::uint32_t v = std::uint32_t{in[i]} << 16;
    if (rest == 2) v |= std::uint32_t{in[i + 1]} << 8;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += rest == 2 ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string xml_unescape(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const std::size_t end = s.find(';', i);
    const std::string_view ent = s.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i + 1);
    if (ent == "&amp;") out += '&';
    else if (ent == "&lt;") out += '<';
    else if (ent == "&gt;") out += '>';
    else if (ent == "&quot;") out += '"';
    else if (ent == "&apos;") out += '\'';
    else throw std::runtime_error("unknown XML entity '" + std::string(ent) + "'");
    i += ent.size() - 1;
  }
  return out;
}

template <class T>
constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

// One DataArray: base64 of (UInt64 byte count, then the raw values) encoded as one
// stream, which is how VTK's reader decodes uncompressed inline binary data.
template <class T>
void data_array(std::string& out, std::string_view name, std::span<const T> values, int components = 1) {
  const std::uint64_t bytes = values.size_bytes();
  std::vector<unsigned char> buf(sizeof bytes + bytes);
  std::memcpy(buf.data(), &bytes, sizeof bytes);
  if (bytes > 0) std::memcpy(buf.data() + sizeof bytes, values.data(), bytes);
  out += fmt::format("        <DataArray type=\"{}\" Name=\"{}\"", vtk_type<T>(), xml_escape(name));
  if (components > 1) out += fmt::format(" NumberOfComponents=\"{}\"", components);
  out += " format=\"binary\">\n          ";
  out += base64(buf);
  out += "\n        </DataArray>\n";
}

// x, y of every disc interleaved with a zero third component.
std::vector<double> with_zero_z(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(3 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[3 * i] = a[i];
    out[3 * i + 1] = b[i];
    out[3 * i + 2] = 0.0;
  }
  return out;
}

std::string attribute(std::string_view tag, std::string_view name) {
  std::string key(" ");  // built piecewise: GCC 12 warns falsely on " " + std::string
  key.append(name).append("=\"");
  const std::size_t at = tag.find(key);
  if (at == std::string_view::npos) return {};
  const std::size_t begin = at + key.size();
  const std::size_t end = tag.find('"', begin);
  if (end == std::string_view::npos) throw std::runtime_error("unterminated attribute in '" + std::string(tag) + "'");
  return xml_unescape(tag.substr(begin, end - begin));
}

// A per-disc array followed by `pad` copies of `fill`: the wall end points are points too, and
// every point array needs a value for them.
template <class T>
std::vector<T> padded(const std::vector<T>& v, std::size_t pad, T fill) {
  std::vector<T> out(v);
  out.insert(out.end(), pad, fill);
  return out;
}

}  // namespace

std::uint64_t write_vtp(const std::filesystem::path& path, const SnapshotFrame& frame) {
  if (frame.discs == nullptr) throw std::invalid_argument("vtp frame has no discs");
  const Discs& d = *frame.discs;
  const std::size_t n = d.size();
  for (const auto& field : frame.fields)
    if (field.values.size() != n)
      throw std::invalid_argument(
          fmt::format("vtp field '{}' has {} values for {} discs", field.name, field.values.size(), n));
  const auto walls = walls_for_display(frame.walls, d.x, d.y);
  const std::size_t n_walls = walls.size(), pad = 2 * n_walls;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <PolyData>\n";
  // TimeValue is the field ParaView reads as the dataset's time.
  out += "    <FieldData>\n";
  out += fmt::format(
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
      frame.time);
  out += fmt::format(
      "      <DataArray type=\"Int64\" Name=\"step\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n", frame.step);
  for (const auto& [name, value] : frame.attrs)
    out += fmt::format(
        "      <DataArray type=\"Float64\" Name=\"{}\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
        xml_escape(name), value);
  out += "    </FieldData>\n";
  out += fmt::format(
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" "
      "NumberOfPolys=\"0\">\n",
      n + pad, n, n_walls);

  // Wall end points: radius 0 (no glyph), id and cluster_id -1, kinematic, at rest, NaN fields.
  out += "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
  data_array<double>(out, "radius", padded(d.radius, pad, 0.0));
  data_array<std::int64_t>(out, "id", padded(d.id, pad, std::int64_t{-1}));
  data_array<std::int64_t>(out, "cluster_id", padded(d.cluster_id, pad, std::int64_t{-1}));
  data_array<std::uint8_t>(out, "motion", padded(d.motion, pad, std::uint8_t{1}));
  data_array<double>(out, "velocity", padded(with_zero_z(d.vx, d.vy), 3 * pad, 0.0), 3);
  data_array<double>(out, "omega", padded(d.omega, pad, 0.0));
  data_array<double>(out, "theta", padded(d.theta, pad, 0.0));
  data_array<double>(out, "depth0", padded(d.depth0, pad, kNaN));
  for (const auto& field : frame.fields) data_array<double>(out, field.name, padded(field.values, pad, kNaN));
  out += "      </PointData>\n";

  std::vector<double> points = with_zero_z(d.x, d.y);
  for (const auto& w : walls) points.insert(points.end(), {w[0], w[1], 0.0, w[2], w[3], 0.0});
  out += "      <Points>\n";
  data_array<double>(out, "Points", points, 3);
  out += "      </Points>\n";

  // One vertex cell per disc: connectivity 0..n-1, offsets 1..n.
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  out += "      <Verts>\n";
  data_array<std::int64_t>(out, "connectivity", connectivity);
  data_array<std::int64_t>(out, "offsets", offsets);
  out += "      </Verts>\n";
  // One line cell per wall, between its two end points after the discs.
  std::vector<std::int64_t> line_points(pad), line_offsets(n_walls);
  for (std::size_t k = 0; k < pad; ++k) line_points[k] = static_cast<std::int64_t>(n + k);
  for (std::size_t w = 0; w < n_walls; ++w) line_offsets[w] = static_cast<std::int64_t>(2 * (w + 1));
  out += "      <Lines>\n";
  data_array<std::int64_t>(out, "connectivity", line_points);
  data_array<std::int64_t>(out, "offsets", line_offsets);
  out += "      </Lines>\n";
  out += "    </Piece>\n";
  out += "  </PolyData>\n";
  out += "</VTKFile>\n";
  write_file_atomically(path, out);
  return fnv1a64(out);
}

void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::string>>& entries) {
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const auto& [time, file] : entries)
    out += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time, xml_escape(file));
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  write_file_atomically(path, out);
}

std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open '" + path.string() + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<std::pair<double, std::string>> entries;
  for (std::size_t at = text.find("<DataSet"); at != std::string::npos; at = text.find("<DataSet", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) throw std::runtime_error("'" + path.string() + "': unterminated <DataSet>");
    const std::string_view tag(text.data() + at, end - at);
    const std::string t = attribute(tag, "timestep");
    double time = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), time);
    if (ec != std::errc() || p != t.data() + t.size())
      throw std::runtime_error("'" + path.string() + "': bad timestep '" + t + "'");
    entries.emplace_back(time, attribute(tag, "file"));
  }
  return entries;
}

}  // namespace orogen
