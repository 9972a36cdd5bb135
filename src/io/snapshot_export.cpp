#include "io/snapshot_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
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

// A box holding every disc whole, 1 d wider on each side. The walls are left out: a wedge's
// pro base reaches 10^7 d ahead of the S-point, and a box that long makes LAMMPS refuse the file
// ("Too many atom sorting bins"). Only a snapshot without discs is boxed by its walls.
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
  if (s.size() == 0)
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
  const Box b = bounding_box(s);  // the cell OVITO draws and bins by: the discs', 1 d of margin
  std::string out;
  auto o = std::back_inserter(out);
  fmt::format_to(o, "{}\n", s.size());
  fmt::format_to(o,
                 "Lattice=\"{} 0 0 0 {} 0 0 0 1\" Origin=\"{} {} -0.5\" "
                 "Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:id:I:1:cluster_id:I:1 Time={} step={} "
                 "pbc=\"F F F\" comment=\"{}\"\n",
                 num(b.xhi - b.xlo), num(b.yhi - b.ylo), num(b.xlo), num(b.ylo), num(s.time), s.step,
                 header_line(s, src));
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

// The LAMMPS fix of one wall, when it is a line LAMMPS can take (horizontal: yplane, vertical:
// xplane), with the discs on the side they are on; "" for a tilted wall.
std::string wall_plane(const std::array<double, 4>& w, double x_mean, double y_mean) {
  const auto [ax, ay, bx, by] = w;
  if (ay == by) return y_mean >= ay ? fmt::format("yplane {} NULL", num(ay)) : fmt::format("yplane NULL {}", num(ay));
  if (ax == bx) return x_mean >= ax ? fmt::format("xplane {} NULL", num(ax)) : fmt::format("xplane NULL {}", num(ax));
  return "";
}

}  // namespace

std::string lammps_input(const Snapshot& s, const LammpsLaw& law, const std::string& data_file) {
  const DiscState d(s);
  double x_mean = 0, y_mean = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    x_mean += d.x[i] / static_cast<double>(s.size());
    y_mean += d.y[i] / static_cast<double>(s.size());
  }
  const std::string coeffs =
      fmt::format("{} {} {} {} {} 1", num(law.kn), num(law.kt), num(law.gamma_n), num(law.gamma_t), num(law.mu));
  std::string out = fmt::format(
      "# LAMMPS input for {} (orogen export): Orogen's units (lengths in d, time in sqrt(d/g), g = 1, disc\n"
      "# density 1 per unit area), its contact law as gran/hooke/history (gamma per unit effective mass, that of\n"
      "# two discs of diameter 1), its walls as wall/gran planes. Run: lmp -in THIS_FILE [-var steps N]\n"
      "dimension 2\nboundary f f p\natom_style sphere\ncomm_modify vel yes\nnewton off\n"
      "read_data {}\n"
      "set type * density/disc 1.0\n"  // Orogen's masses: pi r^2 (LAMMPS's 2-D default is 4/3 pi r^3)
      "neighbor 0.1 bin\nneigh_modify every 1 delay 0 check yes\n"
      "pair_style gran/hooke/history {}\npair_coeff * *\n"
      "timestep {}\n",
      data_file, data_file, coeffs, num(law.dt));
  std::vector<std::string> planes;
  for (const auto& w : s.walls) {
    const std::string plane = wall_plane(w, x_mean, y_mean);
    if (plane.empty()) {
      out += fmt::format("# wall ({}, {}) - ({}, {}) is tilted: fix wall/gran takes planes along x or y only\n",
                         num(w[0]), num(w[1]), num(w[2]), num(w[3]));
    } else if (std::find(planes.begin(), planes.end(), plane) == planes.end()) {
      planes.push_back(plane);  // a wedge's two bases are one plane here
      out += fmt::format("fix wall{} all wall/gran hooke/history {} {}\n", planes.size(), coeffs, plane);
    }
  }
  out += "fix integrate all nve/sphere disc\nfix gravity all gravity 1.0 vector 0 -1 0\nfix plane all enforce2d\n"
         "thermo_style custom step atoms ke\nthermo 100\nvariable steps index 1000\nrun ${steps}\n";
  return out;
}

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
