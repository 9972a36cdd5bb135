#include "io/snapshot_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace orogen {
namespace {

// The per-disc float arrays every snapshot has, in the order the text formats list them.
constexpr const char* kCoreFields[] = {"x", "y", "theta", "vx", "vy", "omega", "radius", "x0", "y0", "depth0"};

// The unit of a snapshot field (docs/output-files.md), for the CSV header.
std::string unit_of(const std::string& field) {
  if (field == "theta") return "rad";
  if (field == "omega") return "rad/sqrt(d/g)";
  if (field == "vx" || field == "vy") return "sqrt(g d)";
  return "d";  // positions, radius, depth0 and the wedge's displacement fields
}

int atom_type(const Snapshot& s, std::size_t i) { return s.cluster_id[i] >= 0 ? 2 : 1; }

// "%.17g": every double reads back to the same bits.
std::string num(double v) { return fmt::format("{:.17g}", v); }

// A box holding every disc whole and every wall, 1 d wider on each side.
struct Box {
  double xlo, xhi, ylo, yhi;
};
Box bounding_box(const Snapshot& s) {
  Box b{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max(),
        std::numeric_limits<double>::lowest()};
  const auto& x = s.field("x");
  const auto& y = s.field("y");
  const auto& r = s.field("radius");
  for (std::size_t i = 0; i < s.size(); ++i) {
    b.xlo = std::min(b.xlo, x[i] - r[i]);
    b.xhi = std::max(b.xhi, x[i] + r[i]);
    b.ylo = std::min(b.ylo, y[i] - r[i]);
    b.yhi = std::max(b.yhi, y[i] + r[i]);
  }
  for (const auto& w : s.walls) {
    b.xlo = std::min({b.xlo, w[0], w[2]});
    b.xhi = std::max({b.xhi, w[0], w[2]});
    b.ylo = std::min({b.ylo, w[1], w[3]});
    b.yhi = std::max({b.yhi, w[1], w[3]});
  }
  if (b.xlo > b.xhi) b = {0, 0, 0, 0};  // no discs, no walls
  return {b.xlo - 1, b.xhi + 1, b.ylo - 1, b.yhi + 1};
}

// The per-disc arrays every format writes.
struct DiscState {
  explicit DiscState(const Snapshot& s)
      : x(s.field("x")), y(s.field("y")), r(s.field("radius")), vx(s.field("vx")), vy(s.field("vy")),
        omega(s.field("omega")) {}
  const std::vector<double>&x, &y, &r, &vx, &vy, &omega;
};

std::string header_line(const Snapshot& s, const ExportSource& src) {
  return fmt::format("Orogen {} output {} of {} (step {}, t = {}): 2-D discs, lengths in d, time in sqrt(d/g)",
                     OROGEN_VERSION, src.output, src.run, s.step, num(s.time));
}

std::string lammps_data(const Snapshot& s, const ExportSource& src) {
  const Box b = bounding_box(s);
  const DiscState d(s);
  std::string out = header_line(s, src) + "; atom id = disc id + 1, type 1 free disc, 2 cluster member\n\n";
  auto o = std::back_inserter(out);
  fmt::format_to(o, "{} atoms\n2 atom types\n\n", s.size());
  fmt::format_to(o, "{} {} xlo xhi\n{} {} ylo yhi\n-0.5 0.5 zlo zhi\n\n", num(b.xlo), num(b.xhi), num(b.ylo),
                 num(b.yhi));
  out += "Atoms # sphere\n\n";
  for (std::size_t i = 0; i < s.size(); ++i)
    fmt::format_to(o, "{} {} {} 1 {} {} 0\n", s.id[i] + 1, atom_type(s, i), num(2 * d.r[i]), num(d.x[i]), num(d.y[i]));
  out += "\nVelocities\n\n";
  for (std::size_t i = 0; i < s.size(); ++i)
    fmt::format_to(o, "{} {} {} 0 0 0 {}\n", s.id[i] + 1, num(d.vx[i]), num(d.vy[i]), num(d.omega[i]));
  return out;
}

std::string lammps_dump(const Snapshot& s, const ExportSource&) {
  const Box b = bounding_box(s);
  const DiscState d(s);
  std::string out;
  auto o = std::back_inserter(out);
  fmt::format_to(o, "ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\nITEM: BOX BOUNDS ff ff pp\n{} {}\n{} {}\n-0.5 0.5\n",
                 s.step, s.size(), num(b.xlo), num(b.xhi), num(b.ylo), num(b.yhi));
  out += "ITEM: ATOMS id type x y z radius vx vy vz omegaz\n";
  for (std::size_t i = 0; i < s.size(); ++i)
    fmt::format_to(o, "{} {} {} {} 0 {} {} {} 0 {}\n", s.id[i] + 1, atom_type(s, i), num(d.x[i]), num(d.y[i]),
                   num(d.r[i]), num(d.vx[i]), num(d.vy[i]), num(d.omega[i]));
  return out;
}

std::string xyz(const Snapshot& s, const ExportSource& src) {
  const DiscState d(s);
  std::string out;
  auto o = std::back_inserter(out);
  fmt::format_to(o, "{}\n", s.size());
  fmt::format_to(o,
                 "Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:id:I:1:cluster_id:I:1 Time={} step={} "
                 "pbc=\"F F F\" comment=\"{}\"\n",
                 num(s.time), s.step, header_line(s, src));
  for (std::size_t i = 0; i < s.size(); ++i)
    fmt::format_to(o, "{} {} {} 0 {} {} 0 {} {} {}\n", atom_type(s, i) == 2 ? "C" : "D", num(d.x[i]), num(d.y[i]),
                   num(d.vx[i]), num(d.vy[i]), num(d.r[i]), s.id[i], s.cluster_id[i]);
  return out;
}

std::string csv(const Snapshot& s, const ExportSource& src) {
  // The core fields first, then the experiment's extra fields by name.
  std::vector<std::string> names(std::begin(kCoreFields), std::end(kCoreFields));
  for (const auto& [name, values] : s.fields)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  std::string out = "# " + header_line(s, src) + "\n# one row per disc; units in brackets\n";
  out += "id,cluster_id,motion";
  for (const auto& n : names) out += fmt::format(",{} [{}]", n, unit_of(n));
  out += "\n";
  auto o = std::back_inserter(out);
  for (std::size_t i = 0; i < s.size(); ++i) {
    fmt::format_to(o, "{},{},{}", s.id[i], s.cluster_id[i], static_cast<int>(s.motion[i]));
    for (const auto& n : names) {
      out += ',';  // not "," + num(...): GCC 12 warns falsely (-Wrestrict) on that
      out += num(s.field(n)[i]);
    }
    out += "\n";
  }
  return out;
}

}  // namespace

ExportFormat parse_export_format(const std::string& name) {
  if (name == "lammps-data") return ExportFormat::LammpsData;
  if (name == "lammps-dump") return ExportFormat::LammpsDump;
  if (name == "xyz") return ExportFormat::Xyz;
  if (name == "csv") return ExportFormat::Csv;
  throw std::invalid_argument(fmt::format("--format {}: unknown format; choose one of {}", name, export_format_names()));
}

const char* export_format_names() { return "lammps-data, lammps-dump, xyz, csv"; }

std::string export_snapshot(const Snapshot& s, ExportFormat format, const ExportSource& source) {
  switch (format) {
    case ExportFormat::LammpsData: return lammps_data(s, source);
    case ExportFormat::LammpsDump: return lammps_dump(s, source);
    case ExportFormat::Xyz: return xyz(s, source);
    case ExportFormat::Csv: return csv(s, source);
  }
  return {};
}

}  // namespace orogen
