#include "contact/cell_grid.hpp"

#include <algorithm>
#include <limits>

namespace orogen {

std::int64_t CellGrid::cell_of(double x, double y) const {
  auto cx = static_cast<std::int64_t>((x - x_lo) / cell);
  auto cy = static_cast<std::int64_t>((y - y_lo) / cell);
  cx = std::clamp<std::int64_t>(cx, 0, nx - 1);
  cy = std::clamp<std::int64_t>(cy, 0, ny - 1);
  return x_long ? cx * ny + cy : cy * nx + cx;
}

CellGrid make_grid(const Discs& d, double cell) {
  CellGrid g;
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

CellBins bin_discs(const Discs& d, const CellGrid& g) {
  CellBins b;
  b.grid = g;
  const std::size_t n = d.size();
  const auto ncell = static_cast<std::size_t>(g.nx * g.ny);  // numbered by CellGrid::cell_of
  std::vector<std::uint32_t> cell_of(n);
  b.cell_start.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = static_cast<std::uint32_t>(g.cell_of(d.x[i], d.y[i]));
    ++b.cell_start[cell_of[i] + 1];
  }
  for (std::size_t k = 0; k < ncell; ++k) b.cell_start[k + 1] += b.cell_start[k];
  b.order.resize(n);
  std::vector<std::uint32_t> fill(b.cell_start.begin(), b.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) b.order[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  return b;
}

void sort_discs_by_cell(CellBins& b, Discs& d, Clusters& c) {
  d.permute(b.order);
  order_clusters_by_discs(c, d);
  relink_clusters(c, d);
  for (std::size_t k = 0; k < b.order.size(); ++k) b.order[k] = static_cast<std::uint32_t>(k);
}

}  // namespace orogen
