#include "contact/neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/parallel.hpp"

namespace orogen {
namespace {

// Cells are numbered stripe by stripe across the longer side of the domain: (u, v) with u
// along the long axis (the stripe) and v across it, index u * nv + v. Discs sorted by cell
// then lie in memory in the order the pairs are built, and stripes make the chunks of the
// force loop (see NeighborList::chunk_start).
struct Grid {
  double x_lo = 0, y_lo = 0, cell = 1;
  std::int64_t nx = 1, ny = 1;
  bool x_long = true;  // u runs along x
  std::int64_t nu() const { return x_long ? nx : ny; }
  std::int64_t nv() const { return x_long ? ny : nx; }
  std::int64_t cell_of(double x, double y) const {
    auto cx = static_cast<std::int64_t>((x - x_lo) / cell);
    auto cy = static_cast<std::int64_t>((y - y_lo) / cell);
    cx = std::clamp<std::int64_t>(cx, 0, nx - 1);
    cy = std::clamp<std::int64_t>(cy, 0, ny - 1);
    return x_long ? cx * ny + cy : cy * nx + cx;
  }
};

Grid make_grid(const Discs& d, double cell) {
  Grid g;
  double xl = std::numeric_limits<double>::max(), yl = xl, xh = -xl, yh = -xl;
  for (std::size_t i = 0; i < d.size(); ++i) {
    xl = std::min(xl, d.x[i]); xh = std::max(xh, d.x[i]);
    yl = std::min(yl, d.y[i]); yh = std::max(yh, d.y[i]);
  }
  if (d.size() == 0) { xl = yl = 0; xh = yh = 1; }
  // A few stray discs far away must not blow up the grid: grow cells past ~4 per disc.
  const double max_cells = 4.0 * static_cast<double>(d.size()) + 64.0;
  while (((xh - xl) / cell + 1) * ((yh - yl) / cell + 1) > max_cells) cell *= 1.5;
  g.x_lo = xl; g.y_lo = yl; g.cell = cell;
  g.nx = static_cast<std::int64_t>((xh - xl) / cell) + 1;
  g.ny = static_cast<std::int64_t>((yh - yl) / cell) + 1;
  g.x_long = g.nx >= g.ny;
  return g;
}

// Mass that resists a contact on disc i: its body's mass, infinite for kinematic discs.
double resisting_mass(const Discs& d, const Clusters& c, std::uint32_t i) {
  if (!d.is_dynamic(i)) return std::numeric_limits<double>::infinity();
  return d.cluster[i] >= 0 ? c.mass[static_cast<std::size_t>(d.cluster[i])] : d.mass[i];
}

double pair_mass(double ma, double mb) {
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
}

// Fills the damping table for every pair and wall mass this world can produce, so that the
// parallel pair search only reads it.
void prepare_damping(const ContactLaw& law, const Discs& d, const Clusters& c, double dt) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double m = resisting_mass(d, c, static_cast<std::uint32_t>(i));
    if (std::isinf(m)) continue;
    lo = std::min(lo, m);
    hi = std::max(hi, m);
  }
  if (hi == 0) return;
  law.prepare_damping(0.5 * lo, hi, dt);
}

// Sorts discs into cells (counting sort); returns disc indices in cell order and cell starts.
void bin_discs(const Discs& d, const Grid& g, std::vector<std::uint32_t>& order,
               std::vector<std::uint32_t>& cell_start) {
  const std::size_t n = d.size();
  const auto ncell = static_cast<std::size_t>(g.nx * g.ny);  // numbered by Grid::cell_of
  std::vector<std::uint32_t> cell_of(n);
  cell_start.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = static_cast<std::uint32_t>(g.cell_of(d.x[i], d.y[i]));
    ++cell_start[cell_of[i] + 1];
  }
  for (std::size_t k = 0; k < ncell; ++k) cell_start[k + 1] += cell_start[k];
  order.resize(n);
  std::vector<std::uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
}

// A chunk whose pairs touch this often at a build is dense (NeighborList::chunk_dense). The
// benchmark pile (skin 0.1 d, 74% of the pairs touching) runs faster with every pair through
// the kernel, 1.06x at 5k discs and 1.5x at 80k; a wedge (skin 0.3 d, half of them) 1.14x
// slower (measured with both kernels at several shares, docs/performance.md).
constexpr double kDenseShare = 0.65;

}  // namespace

BuildStats build_neighbor_list(NeighborList& L, Discs& d, Clusters& c, const std::vector<Wall>& walls,
                               const ContactLaw& law, double dt, bool sort) {
  BuildStats stats;
  const std::size_t n = d.size();
  std::int64_t max_id = 0;
  double r_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    max_id = std::max(max_id, d.id[i]);
    r_max = std::max(r_max, d.radius[i]);
    if (!std::isfinite(d.x[i]) || !std::isfinite(d.y[i])) stats.finite = false;
  }
  if (!stats.finite) return stats;
  for (auto id : L.id_first) max_id = std::max(max_id, id);
  for (auto id : L.wall_disc_id) max_id = std::max(max_id, id);

  // Index the old history by stable ids before indices change.
  HistoryCarry pair_history, wall_history;
  pair_history.index(L.id_first, L.id_second, L.xi, max_id);
  {
    std::vector<std::int64_t> wall_key(L.walls.wall.begin(), L.walls.wall.end());
    wall_history.index(L.wall_disc_id, wall_key, L.walls.xi, max_id);
  }

  const Grid g = make_grid(d, 2.0 * r_max + L.skin);
  std::vector<std::uint32_t> order, cell_start;
  bin_discs(d, g, order, cell_start);
  if (sort) {
    d.permute(order);
    order_clusters_by_discs(c, d);
    relink_clusters(c, d);
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
  }

  // Pairs: each cell against itself and its four forward neighbours in traversal order:
  // (u, v+1) in its own stripe and (u+1, v-1), (u+1, v), (u+1, v+1) in the next. Chunks of
  // whole stripes, at most kMaxChunks of them: a number fixed by the geometry alone, so that
  // the order of the force sums never depends on the thread count. Chunks are searched in
  // parallel into lists of their own, joined in chunk order.
  constexpr std::int64_t kMaxChunks = 64;
  const std::int64_t stripes_per_chunk = (g.nu() + kMaxChunks - 1) / kMaxChunks;
  const std::int64_t chunks = (g.nu() + stripes_per_chunk - 1) / stripes_per_chunk;
  prepare_damping(law, d, c, dt);  // the damping table is filled serially, read in parallel
  struct ChunkPairs {
    std::vector<std::uint32_t> first, second;
    std::vector<std::int64_t> id_first, id_second;
    std::vector<double> xi, gamma_n;
    BuildStats stats;
    std::size_t touching = 0;
  };
  std::vector<ChunkPairs> found(static_cast<std::size_t>(chunks));
  const std::int64_t neighbours[4][2] = {{0, 1}, {1, -1}, {1, 0}, {1, 1}};  // (du, dv)
#pragma omp parallel for schedule(dynamic, 1) if (static_cast<std::ptrdiff_t>(n) > min_parallel_items())
  for (std::int64_t k = 0; k < chunks; ++k) {
    ChunkPairs& out = found[static_cast<std::size_t>(k)];
    auto consider = [&](std::uint32_t a, std::uint32_t b) {
      if (d.cluster_id[a] >= 0 && d.cluster_id[a] == d.cluster_id[b]) return;
      if (!d.is_dynamic(a) && !d.is_dynamic(b)) return;
      const double dx = d.x[b] - d.x[a], dy = d.y[b] - d.y[a];
      const double reach = d.radius[a] + d.radius[b] + L.skin;
      const double dist2 = dx * dx + dy * dy;
      if (dist2 >= reach * reach) return;
      const double overlap = d.radius[a] + d.radius[b] - std::sqrt(dist2);
      out.touching += overlap > 0;
      const double ratio = overlap / std::min(d.radius[a], d.radius[b]);
      if (ratio > out.stats.max_overlap_ratio) {
        out.stats.max_overlap_ratio = ratio; out.stats.worst_a = a; out.stats.worst_b = b;
      }
      if (d.id[a] > d.id[b]) std::swap(a, b);
      const double m = pair_mass(resisting_mass(d, c, a), resisting_mass(d, c, b));
      out.first.push_back(a);
      out.second.push_back(b);
      out.id_first.push_back(d.id[a]);
      out.id_second.push_back(d.id[b]);
      out.xi.push_back(pair_history.find(d.id[a], d.id[b]));
      out.gamma_n.push_back(law.gamma_n(m, dt));
    };
    const std::int64_t u_end = std::min(g.nu(), (k + 1) * stripes_per_chunk);
    for (std::int64_t u = k * stripes_per_chunk; u < u_end; ++u) {
      for (std::int64_t v = 0; v < g.nv(); ++v) {
        const auto cell = static_cast<std::size_t>(u * g.nv() + v);
        for (auto s = cell_start[cell]; s < cell_start[cell + 1]; ++s) {
          const auto a = order[s];
          for (auto t = s + 1; t < cell_start[cell + 1]; ++t) consider(a, order[t]);
          for (const auto& nb : neighbours) {
            const std::int64_t ou = u + nb[0], ov = v + nb[1];
            if (ov < 0 || ov >= g.nv() || ou >= g.nu()) continue;
            const auto other = static_cast<std::size_t>(ou * g.nv() + ov);
            for (auto t = cell_start[other]; t < cell_start[other + 1]; ++t) consider(a, order[t]);
          }
        }
      }
    }
  }
  L.first.clear(); L.second.clear(); L.xi.clear(); L.gamma_n.clear();
  L.id_first.clear(); L.id_second.clear();
  L.chunk_start.clear();
  L.chunk_dense.clear();
  for (const auto& f : found) {
    L.chunk_start.push_back(static_cast<std::uint32_t>(L.first.size()));
    L.chunk_dense.push_back(static_cast<double>(f.touching) >= kDenseShare * static_cast<double>(f.first.size()));
    L.first.insert(L.first.end(), f.first.begin(), f.first.end());
    L.second.insert(L.second.end(), f.second.begin(), f.second.end());
    L.id_first.insert(L.id_first.end(), f.id_first.begin(), f.id_first.end());
    L.id_second.insert(L.id_second.end(), f.id_second.begin(), f.id_second.end());
    L.xi.insert(L.xi.end(), f.xi.begin(), f.xi.end());
    L.gamma_n.insert(L.gamma_n.end(), f.gamma_n.begin(), f.gamma_n.end());
    if (f.stats.max_overlap_ratio > stats.max_overlap_ratio) {
      stats.max_overlap_ratio = f.stats.max_overlap_ratio;
      stats.worst_a = f.stats.worst_a;
      stats.worst_b = f.stats.worst_b;
    }
  }
  L.chunk_start.push_back(static_cast<std::uint32_t>(L.first.size()));
  if (sort) {  // discs are in cell order: chunk k's stripes hold discs from its first cell on
    L.chunk_disc.resize(static_cast<std::size_t>(chunks) + 1);
    for (std::int64_t k = 0; k < chunks; ++k)
      L.chunk_disc[static_cast<std::size_t>(k)] = cell_start[static_cast<std::size_t>(k * stripes_per_chunk * g.nv())];
    L.chunk_disc.back() = static_cast<std::uint32_t>(n);
  } else if (L.chunk_disc.size() != static_cast<std::size_t>(chunks) + 1) {
    L.chunk_disc.clear();  // the grid changed since the last sort: no hint until the next
  }

  // Wall contacts: every disc within reach of each enabled wall, in wall then disc order
  // (the distance test in parallel, the list in order).
  L.walls.clear();
  L.wall_disc_id.clear();
  std::vector<std::uint8_t> near(n);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (!walls[w].enabled) continue;
    const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count > min_parallel_items())
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      double cx, cy;
      const double dist2 = closest_point_on_segment(walls[w], d.x[i], d.y[i], cx, cy);
      const double reach = d.radius[i] + L.skin;
      near[i] = d.is_dynamic(i) && dist2 < reach * reach;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!near[i]) continue;
      L.walls.wall.push_back(static_cast<std::uint32_t>(w));
      L.walls.disc.push_back(static_cast<std::uint32_t>(i));
      L.walls.xi.push_back(wall_history.find(d.id[i], static_cast<std::int64_t>(w)));
      const double m = resisting_mass(d, c, static_cast<std::uint32_t>(i));
      L.walls.gamma_n.push_back(law.gamma_n(m, dt));
      L.walls.mass.push_back(m);
      L.walls.touching.push_back(0);
      L.walls.at_limit.push_back(0);
      L.wall_disc_id.push_back(d.id[i]);
    }
  }

  L.x_ref = d.x;
  L.y_ref = d.y;
  L.wall_ax_ref.clear(); L.wall_ay_ref.clear(); L.wall_bx_ref.clear(); L.wall_by_ref.clear();
  for (const auto& w : walls) {
    L.wall_ax_ref.push_back(w.ax); L.wall_ay_ref.push_back(w.ay);
    L.wall_bx_ref.push_back(w.bx); L.wall_by_ref.push_back(w.by);
  }
  ++L.builds;
  L.valid = true;
  return stats;
}

double wall_displacement(const NeighborList& L, const std::vector<Wall>& walls) {
  if (L.wall_ax_ref.size() != walls.size()) return std::numeric_limits<double>::infinity();
  double moved = 0;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const double a = std::hypot(walls[w].ax - L.wall_ax_ref[w], walls[w].ay - L.wall_ay_ref[w]);
    const double b = std::hypot(walls[w].bx - L.wall_bx_ref[w], walls[w].by - L.wall_by_ref[w]);
    moved = std::max(moved, std::max(a, b));
  }
  return moved;
}

}  // namespace orogen
