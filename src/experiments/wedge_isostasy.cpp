// The wedge's deflecting base (issue 40, docs/isostasy.md): its walls, their moves, the
// kinematic slab riding on it, and what series.csv records of it.
#include <fmt/format.h>

#include <limits>
#include <numbers>

#include "experiments/wedge_experiment.hpp"
#include "packing/tile.hpp"

namespace orogen {
namespace {

constexpr double kDeepestBase = 10;        // [h0]: a base deeper than this stops the run (exit 3)

// The weight per length (g = 1, grains of density 1) of the discs centred in [lo, hi).
double load_between(const Discs& d, double lo, double hi) {
  double area = 0;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d.x[i] >= lo && d.x[i] < hi) area += std::numbers::pi * d.radius[i] * d.radius[i];
  return area / (hi - lo);
}

bool names_base(const std::string& wall, std::string_view base) {
  return wall == base || (wall.size() > base.size() && wall.starts_with(base) && wall[base.size()] == '_');
}

}  // namespace

void WedgeExperiment::start_isostasy() {
  // Nodes over every x the pro-side window can reach in the run, and the retro layer (a resumed
  // run then loads the nodes it started with: an extended run keeps them).
  const double x_lo = -(spec_.initial_active + spec_.window + spec_.tile_length + spec_.s_end) * spec_.h0;
  base_ = IsostaticBase(spec_.isostasy, x_lo, x_end_ + 1, 0.0);  // the load: build_layer, or the checkpoint
}

// The far pro-side plate ends at the first node; segments from there (src/isostasy), then the
// retro end wall.
std::vector<Wall> WedgeExperiment::segmented_base(const Wall& pro, const Wall& retro, const Wall& end) const {
  Wall far = pro;
  far.bx = base_.nodes().front();
  std::vector<Wall> walls{far};
  for (Wall& s : base_.segments(pro, retro, x_end_ + 1)) walls.push_back(std::move(s));
  walls.push_back(end);
  return walls;
}

void WedgeExperiment::start_isostasy_in_branch(World& w) {
  w.set_walls(segmented_base(w.wall(kProBase), w.wall(kRetroBase), w.wall(kRetroEnd)));
  find_base_walls(w);
  // The layer as built is gone under the wedge: its load per length is that of a tile stamped
  // as build_layer stamps them, right to left, each dropping the discs that overlap the one to
  // its right (a scratch world of three: the middle one has its seam).
  World scratch;
  const double L = tile_.length;
  for (double left : {2 * L, L, 0.0}) stamp_tile(scratch, tile_, left, std::numeric_limits<double>::infinity());
  base_.set_reference_load(load_between(scratch.discs(), L, 2 * L));
}

// The built layer's weight per length (g = 1, grains of density 1): its discs' area over its
// length, seams and all, away from the retro end wall and the slab's far end.
double WedgeExperiment::layer_load(const World& w) const {
  return load_between(w.discs(), slab_left_ + spec_.h0, x_end_ - spec_.h0);
}

void WedgeExperiment::find_base_walls(const World& w) {
  pro_walls_.clear();
  retro_walls_.clear();
  for (std::size_t k = 0; k < w.walls().size(); ++k) {
    if (names_base(w.walls()[k].name, kProBase)) pro_walls_.push_back(k);
    if (names_base(w.walls()[k].name, kRetroBase)) retro_walls_.push_back(k);
  }
}

void WedgeExperiment::place_base(World& w) const {
  if (w.step() > base_.move_end()) return;  // where the last move left it
  const std::vector<double> h = base_.heights(w.step());
  const std::vector<double>& x = base_.nodes();
  const Wall& far = w.walls()[pro_walls_.front()];
  w.set_wall_ends(pro_walls_.front(), far.ax, h.front(), x.front(), h.front());
  // The segments follow the far plate in wall order, pro side then retro side.
  std::size_t k = 0;
  for (const auto* walls : {&pro_walls_, &retro_walls_})
    for (std::size_t j = walls == &pro_walls_ ? 1 : 0; j < walls->size(); ++j, ++k) {
      const Wall& s = w.walls()[(*walls)[j]];
      w.set_wall_ends((*walls)[j], s.ax, h[k], s.bx, h[k + 1]);
    }
  const std::size_t end = w.walls().size() - 1;  // the retro end, after the segments
  const Wall& e = w.walls()[end];
  w.set_wall_ends(end, e.ax, base_.height(x_end_, w.step()) - 1.0, e.bx, e.by);
}

double WedgeExperiment::base_height(const World& w, double x) const {
  return base_.active() ? base_.height(x, w.step()) : 0.0;
}

BaseHeight WedgeExperiment::on_base(const World& w) const {
  if (!base_.active()) return {};
  return [this, &w](double x) { return base_.height(x, w.step()); };
}

double WedgeExperiment::riding_speed(const World& w, double x, double vx) const {
  if (!base_.active()) return 0.0;
  const double dt = static_cast<double>(kHousekeepingEvery) * w.dt();
  return (base_.height(x + vx * dt, w.step() + kHousekeepingEvery) - base_.height(x, w.step())) / dt;
}

WallContactStats WedgeExperiment::base_stats(const World& w, const std::vector<std::size_t>& walls) const {
  WallContactStats sum;
  for (const std::size_t k : walls) {
    const WallContactStats s = w.wall_contact_stats(k);
    sum.touching += s.touching;
    sum.at_limit += s.at_limit;
  }
  return sum;
}

void WedgeExperiment::check_base_depth(const World& w) const {
  const IsostaticBase::Shape s = base_.shape(base_.move_end());
  if (s.deepest <= kDeepestBase * spec_.h0) return;
  throw InstabilityError(fmt::format(
      "the base would sink {:.3g} h0 at x = {:.3g} h0 under the load on it (step {}), deeper than {} h0: the "
      "mantle under it is too light for this wedge (isostasy.mantle_density = {})",
      s.deepest / spec_.h0, s.x_deepest / spec_.h0, w.step(), kDeepestBase, spec_.isostasy.mantle_density));
}

const std::vector<SeriesColumn>& WedgeExperiment::isostasy_columns() {
  static const std::vector<SeriesColumn> columns = {
      {"base_s_point", "height of the base at the S-point (x = 0); negative: below where it started [h0]"},
      {"deflection_max", "largest downward deflection of the base [h0]"},
      {"x_deflection_max", "x of the largest deflection, from the S-point [h0]"},
      {"forebulge_pro", "highest point of the base on the pro side of the largest deflection [h0]"},
      {"forebulge_retro", "highest point of the base on the retro side of the largest deflection [h0]"},
      {"basin_pro", "depth of the base under the pro-side deformation front Dp: the foredeep's room [h0]"},
      {"basin_retro", "depth of the base under the retro-side deformation front Dr [h0]"},
  };
  return columns;
}

std::vector<double> WedgeExperiment::isostasy_values(const World& w, double dp, double dr) const {
  const double h0 = spec_.h0;
  const IsostaticBase::Shape s = base_.shape(w.step());
  return {base_.height(0.0, w.step()) / h0, s.deepest / h0, s.x_deepest / h0, s.bulge_pro / h0, s.bulge_retro / h0,
          -base_.height(dp * h0, w.step()) / h0, -base_.height(dr * h0, w.step()) / h0};
}

}  // namespace orogen
