#include "analysis/contact_output.hpp"

#include <cstdint>
#include <utility>

#include "analysis/contact_forces.hpp"
#include "analysis/love_weber_stress.hpp"

namespace orogen {
namespace {

constexpr const char* kStressUnits = "m g / d";  // 2-D stress: force per length

template <class T>
SnapshotDataset dataset(std::string name, std::string units, std::string description, std::vector<T> values,
                        std::size_t columns = 1) {
  return {std::move(name), std::move(units), std::move(description), std::move(values), columns};
}

SnapshotGroup contacts_group(const ContactList& c) {
  SnapshotGroup g{"contacts",
                  "touching disc pairs and disc-wall contacts with their forces: body a acts on body b with force f "
                  "(b feels f, a feels -f); pairs first, then wall contacts",
                  {},
                  {}};
  auto& ds = g.datasets;
  ds.push_back(dataset("is_wall", "-", "1 for a disc-wall contact (a is the wall), 0 for a disc pair", c.is_wall));
  ds.push_back(dataset("id_a", "-",
                       "stable id of disc a (the lower id of a pair); for a wall contact the wall's row in `walls`",
                       c.id_a));
  ds.push_back(dataset("id_b", "-", "stable id of disc b", c.id_b));
  ds.push_back(dataset("index_a", "-", "row of disc a in this output's per-disc arrays, -1 for a wall", c.index_a));
  ds.push_back(dataset("index_b", "-", "row of disc b in this output's per-disc arrays", c.index_b));
  ds.push_back(dataset("x", "d", "contact point: middle of the overlap, x", c.x));
  ds.push_back(dataset("y", "d", "contact point: middle of the overlap, y", c.y));
  ds.push_back(dataset("nx", "-", "unit normal from a to b, x", c.nx));
  ds.push_back(dataset("ny", "-", "unit normal from a to b, y", c.ny));
  ds.push_back(dataset("fn", "m g", "normal force on b, along n (>= 0: the law never pulls)", c.fn));
  ds.push_back(dataset("ft", "m g", "tangential force on b, along t = (-ny, nx)", c.ft));
  ds.push_back(dataset("fx", "m g", "force on b, x", c.fx));
  ds.push_back(dataset("fy", "m g", "force on b, y", c.fy));
  ds.push_back(dataset("overlap", "d", "overlap of the two bodies", c.overlap));
  ds.push_back(dataset("at_limit", "-", "1 where the tangential force sits on the Coulomb limit mu fn", c.at_limit));
  return g;
}

// ParaView lines: segment k from centre a (a wall contact: the contact point) to centre b.
void add_segments(SnapshotGroup& g, const ContactList& c, const Discs& d) {
  std::vector<double> points;
  std::vector<std::int64_t> cells;
  points.reserve(4 * c.size());
  cells.reserve(2 * c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto b = static_cast<std::size_t>(c.index_b[k]);
    if (c.is_wall[k]) {
      points.push_back(c.x[k]); points.push_back(c.y[k]);
    } else {
      const auto a = static_cast<std::size_t>(c.index_a[k]);
      points.push_back(d.x[a]); points.push_back(d.y[a]);
    }
    points.push_back(d.x[b]); points.push_back(d.y[b]);
    cells.push_back(static_cast<std::int64_t>(2 * k));
    cells.push_back(static_cast<std::int64_t>(2 * k + 1));
  }
  g.datasets.push_back(dataset("segment_points", "d",
                               "2 x contacts rows (x, y): rows 2k and 2k+1 are the ends of contact k's line, centre of "
                               "a (a wall contact: the contact point) and centre of b",
                               std::move(points), 2));
  g.datasets.push_back(dataset("segment_cells", "-",
                               "contacts rows of 2 point numbers into segment_points (2k, 2k+1): line cells "
                               "(XDMF Polyline, 2 nodes per element)",
                               std::move(cells), 2));
}

SnapshotGroup stress_group(const DiscStress& s) {
  const std::string what = "Love-Weber stress of the disc, (1/A) sum over its contacts of f_i l_j (f the force on "
                           "the disc, l the branch vector from its centre to the contact point, A = pi r^2); "
                           "tension positive, component ";
  SnapshotGroup g{"stress", "per-disc stress, rows as the per-disc arrays", {}, {}};
  g.datasets.push_back(dataset("xx", kStressUnits, what + "xx", s.xx));
  g.datasets.push_back(dataset("xy", kStressUnits, what + "xy (f_x l_y)", s.xy));
  g.datasets.push_back(dataset("yx", kStressUnits, what + "yx (f_y l_x)", s.yx));
  g.datasets.push_back(dataset("yy", kStressUnits, what + "yy", s.yy));
  g.datasets.push_back(dataset("area", "d^2", "area A = pi r^2 the disc's stress is divided by", s.area));
  return g;
}

SnapshotGroup grid_group(const StressGrid& s) {
  const std::string what = "coarse-grained stress: sum of sigma A over the discs whose centre lies in the cell, "
                           "divided by the cell's area (voids included); rows y, columns x; component ";
  SnapshotGroup g{"stress_grid",
                  "stress on a regular grid of square cells; cell (row j, column i) covers [x0 + i cell, x0 + (i+1) "
                  "cell) x [y0 + j cell, y0 + (j+1) cell); attributes x0, y0, cell in d",
                  {{"cell", s.cell}, {"x0", s.x0}, {"y0", s.y0}},
                  {}};
  g.datasets.push_back(dataset("xx", kStressUnits, what + "xx", s.xx, s.nx));
  g.datasets.push_back(dataset("xy", kStressUnits, what + "xy", s.xy, s.nx));
  g.datasets.push_back(dataset("yx", kStressUnits, what + "yx", s.yx, s.nx));
  g.datasets.push_back(dataset("yy", kStressUnits, what + "yy", s.yy, s.nx));
  return g;
}

SnapshotGroup clusters_group(const Clusters& c) {
  SnapshotGroup g{"clusters", "rigid cluster bodies: pose and velocity of each body's centre of mass", {}, {}};
  g.datasets.push_back(dataset("id", "-", "stable body id (the member discs' cluster_id)", c.id));
  g.datasets.push_back(dataset("x", "d", "centre of mass, x", c.x));
  g.datasets.push_back(dataset("y", "d", "centre of mass, y", c.y));
  g.datasets.push_back(dataset("theta", "rad", "body angle (anticlockwise)", c.theta));
  g.datasets.push_back(dataset("vx", "sqrt(g d)", "velocity of the centre of mass, x", c.vx));
  g.datasets.push_back(dataset("vy", "sqrt(g d)", "velocity of the centre of mass, y", c.vy));
  g.datasets.push_back(dataset("omega", "rad / sqrt(d/g)", "angular velocity (anticlockwise)", c.omega));
  return g;
}

}  // namespace

std::vector<SnapshotGroup> contact_output_groups(const World& world, const ContactOutputOptions& options) {
  std::vector<SnapshotGroup> groups;
  if (options.contacts || options.stress || options.stress_grid > 0) {
    const ContactList contacts = measure_contact_forces(world);
    if (options.contacts) {
      groups.push_back(contacts_group(contacts));
      add_segments(groups.back(), contacts, world.discs());
    }
    if (options.stress || options.stress_grid > 0) {
      const DiscStress stress = love_weber_stress(world.discs(), contacts);
      if (options.stress_grid > 0)
        groups.push_back(grid_group(coarse_grain_stress(world.discs(), stress, options.stress_grid)));
      if (options.stress) groups.push_back(stress_group(stress));
    }
  }
  if (world.clusters().size() > 0) groups.push_back(clusters_group(world.clusters()));
  return groups;
}

}  // namespace orogen
