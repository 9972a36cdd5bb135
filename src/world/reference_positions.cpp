#include "world/reference_positions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace orogen {

void record_reference_positions(NeighborList& L, const Discs& d, const std::vector<Wall>& walls) {
  L.x_ref = d.x;
  L.y_ref = d.y;
  L.wall_ax_ref.clear(); L.wall_ay_ref.clear(); L.wall_bx_ref.clear(); L.wall_by_ref.clear();
  for (const auto& w : walls) {
    L.wall_ax_ref.push_back(w.ax); L.wall_ay_ref.push_back(w.ay);
    L.wall_bx_ref.push_back(w.bx); L.wall_by_ref.push_back(w.by);
  }
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
