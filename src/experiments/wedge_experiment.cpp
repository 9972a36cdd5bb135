#include "experiments/wedge_experiment.hpp"
#include "util/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "analysis/wedge_geometry.hpp"
#include "exhumation/in_run_analysis.hpp"
#include "experiments/series_table.hpp"
#include "experiments/layer_units.hpp"
#include "experiments/settled_layer.hpp"
#include "experiments/surface_series.hpp"

namespace orogen {
namespace {

constexpr std::string_view kPinHook = "wedge.pin_retro_base";

}  // namespace

std::string WedgeExperiment::tile_problem(const Tile& tile, double h0) {
  const double needed = h0 + 2 * tile_margin_for(h0);
  if (std::fabs(tile.thickness - h0) > 1e-9 * h0)
    return fmt::format("a packing as thick as layer.thickness = {} (this one is {} thick: set layer.thickness = {})",
                       h0, tile.thickness, tile.thickness);
  if (tile.length < needed)
    return fmt::format("a packing at least {} d long for layer.thickness = {} (this one is {} d)", needed, h0,
                       tile.length);
  return {};
}

void WedgeExperiment::setup(World& w) {
  if (!spec_.packing_file.empty()) {
    const Tile whole = load_tile(spec_.packing_file);
    if (const std::string problem = tile_problem(whole, spec_.h0); !problem.empty())
      throw std::runtime_error(spec_.packing_file + ": wedge.packing_file must be " + problem);
    tile_ = cut_tile(whole, tile_margin(), whole.length - 2 * tile_margin());
  } else {
    // Settle the tile in a world of its own with the same engine settings.
    World box;
    box.set_contact_law(w.law());
    box.set_time_step(w.dt());
    box.set_neighbor_skin(w.neighbors().skin);
    box.set_sort_every(w.sort_every());
    PackingSpec p = spec_.packing;
    // A wider box, cut back to the tile length away from its walls (see cut_tile).
    p.length = spec_.tile_length * spec_.h0 + 2 * tile_margin();
    p.thickness = spec_.h0;
    PackingExperiment packing(p, spec_.settle);
    packing.setup(box);
    settle_with_tuning(box, packing, spec_.settle);
    tile_ = cut_tile(tile_from_world(box, p.length, p.thickness), tile_margin(), spec_.tile_length * spec_.h0);
  }
  build_layer(w);
}

void WedgeExperiment::build_layer(World& w) {
  const double L = tile_.length;
  x_end_ = spec_.retro_length * spec_.h0;
  Wall pro{.name = std::string(kProBase), .ax = -1e7, .ay = 0, .bx = 0, .by = 0, .surface_speed = spec_.v, .mu = spec_.mu_bp};
  // Only eq. 4.1's drag needs a traction wall: the Coulomb belt of the traction condition is
  // the rough wall of the constant-velocity one, the retro base's law, moving with the plate.
  const bool drag = spec_.basal == BasalCondition::Traction && spec_.traction_law == TractionLaw::Drag;
  pro.friction = drag ? WallFriction::Traction : WallFriction::Rough;
  pro.traction_gamma = spec_.gamma_b;
  Wall retro{.name = std::string(kRetroBase), .ax = 0, .ay = 0, .bx = x_end_ + 1, .by = 0,
             .friction = WallFriction::Rough, .mu = spec_.mu_br};
  Wall end{.name = std::string(kRetroEnd), .ax = x_end_, .ay = -1, .bx = x_end_, .by = 20 * spec_.h0};
  set_weakening(pro, spec_.base_weakening);
  set_weakening(retro, spec_.base_weakening);
  start_isostasy();
  w.set_walls(base_.active() ? segmented_base(pro, retro, end) : std::vector<Wall>{pro, retro, end});
  // Until a wedge exists, the layer in front of the S-point stalls on its base and must be
  // long enough to break at the S-point rather than against the rigid kinematic slab.
  window_pro_ = -std::max(spec_.window, spec_.initial_active) * spec_.h0;
  // The retro-side layer is dynamic as far as the pro side's initial stretch (MODEL allows the
  // far retro slab at rest until deformation approaches; nearer, held at rest it would be a
  // rigid backstop where the thesis's retro layer slides on its base), and then follows the
  // retro front like the pro window (update_windows).
  window_retro_ = std::min(x_end_ + 1.0, std::max(spec_.window, spec_.initial_active) * spec_.h0);
  double left = x_end_ - L;
  while (true) {
    const auto [first, last] = stamp_tile(w, tile_, left, x_end_);  // nothing overlapping the end wall
    apply_units(w, first, last, spec_.packing.seed);
    if (left <= window_pro_ - slab_reserve()) break;
    left -= L;
  }
  slab_left_ = left;
  if (base_.active()) base_.set_reference_load(layer_load(w));
  entered_ = static_cast<std::int64_t>(w.discs().size());
  start_surface();
  count_entered(w, 0, w.discs().size());
  t_start_ = w.time();
  update_windows(w);
  attach(w);
}

void WedgeExperiment::attach(World& w) {
  find_base_walls(w);
  if (spec_.basal == BasalCondition::ConstantVelocity)
    w.hooks().add_pin(std::string(kPinHook),
                      StageHooks::Pin{[this]() -> const std::vector<std::size_t>& { return retro_walls_; },
                                      [this](const World& world) { size_pins(world); },
                                      [this](const World& world, std::size_t i) { pin(world, i); },
                                      [this](const World& world, std::size_t i) { return pinned(world, i); }});
}

// Keeps kinematic slab beyond the pro window: stamps a new tile when less than
// slab_reserve() of it is left. (A window that jumps past the slab's end in one update is
// caught up within a step or two; the new tiles turn dynamic at the next window update, as
// all inflow does.)
void WedgeExperiment::feed_slab(World& w) {
  slab_left_ += spec_.v * w.dt();
  if (slab_left_ <= window_pro_ - slab_reserve()) return;
  slab_left_ -= tile_.length;
  w.make_whole();  // over ranks: every copy adds the tile to the whole state
  const std::size_t first_cluster = w.clusters().size();
  const auto [first, last] = stamp_tile(w, tile_, slab_left_, std::numeric_limits<double>::infinity(), on_base(w));
  apply_units(w, first, last, spec_.packing.seed);
  w.edit_motion([&](MotionEdit& e) {
    for (auto i = first; i < last; ++i)
      if (w.discs().cluster[i] < 0) e.disc(i, Motion::Kinematic, spec_.v, riding_speed(w, w.discs().x[i], spec_.v));
    for (std::size_t k = first_cluster; k < w.clusters().size(); ++k)
      e.cluster(k, Motion::Kinematic, spec_.v, riding_speed(w, w.clusters().x[k], spec_.v));
  });
  entered_ += static_cast<std::int64_t>(last - first);
  count_entered(w, first, last);
}

// The surface laws on the tile's columns (2.3 mean radii unless surface.column_width), deposits
// drawn from the tile's sizes.
void WedgeExperiment::start_surface() {
  SurfaceSpec s = spec_.surface;
  double r_mean = 0;
  for (double r : tile_.radius) r_mean += r;
  r_mean /= std::max<std::size_t>(1, tile_.size());
  if (s.column_width <= 0) s.column_width = spec_.column_width_factor * r_mean;
  surface_ = SurfaceProcesses(std::move(s), tile_.radius, spec_.packing.seed);
}

bool WedgeExperiment::set_surface_script(SurfaceScript script) {
  spec_.surface.script = script;
  surface_.set_script(std::move(script));
  return true;
}

void WedgeExperiment::count_entered(const World& w, std::size_t first, std::size_t last) {
  for (std::size_t i = first; i < last; ++i)
    surface_.ledger().entered += std::numbers::pi * w.discs().radius[i] * w.discs().radius[i];
}

// Active region: between the windows that follow the deformation fronts; kinematic slab
// outside (moving with the pro plate, or at rest on the retro side); pinned discs at rest.
void WedgeExperiment::update_windows(World& w) {
  auto& d = w.discs();
  const double front_y = spec_.h0 + spec_.packing.d_max;
  double dp = 0, dr = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d.y[i] <= front_y) continue;
    dp = std::min(dp, d.x[i]);
    dr = std::max(dr, d.x[i]);
  }
  window_pro_ = std::min(window_pro_, dp - spec_.window * spec_.h0);
  window_retro_ = std::min(x_end_ + 1.0, std::max(window_retro_, dr + spec_.window * spec_.h0));
  const auto ids = static_cast<std::size_t>(w.next_disc_id());
  if (pinned_.size() < ids) pinned_.resize(ids, 0);
  // Kinematic bodies ride on the base: vy keeps them on it until the next update (0: rigid base).
  auto wanted = [&](double x, bool pinned, double& vx, double& vy) {
    vx = 0;
    vy = 0;
    if (pinned || x > window_retro_) { vy = riding_speed(w, x, 0); return Motion::Kinematic; }
    if (x < window_pro_) { vx = spec_.v; vy = riding_speed(w, x, vx); return Motion::Kinematic; }
    return Motion::Dynamic;
  };
  const auto& c = w.clusters();
  w.edit_motion([&](MotionEdit& e) {
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (d.cluster[i] >= 0) continue;
      double vx, vy;
      const Motion m = wanted(d.x[i], pinned_[static_cast<std::size_t>(d.id[i])], vx, vy);
      e.disc(i, m, vx, vy);
    }
    for (std::size_t k = 0; k < c.size(); ++k) {
      bool pinned = false;
      for (auto i : c.members[k]) if (i >= 0 && pinned_[static_cast<std::size_t>(d.id[i])]) pinned = true;
      double vx, vy;
      const Motion m = wanted(c.x[k], pinned, vx, vy);
      e.cluster(k, m, vx, vy);
    }
  });
}

// Constant-velocity condition: a disc that touches the retro-side base is held at rest (no
// slip) from the step it first touches: a pin hook after the forces of every step
// (StageHooks::Pin), so it does not move in that step's integration (docs/model.md, "Constant
// velocity"). The experiment keeps a flag for every disc id so far, set once a disc touched.
void WedgeExperiment::size_pins(const World& w) {
  const auto ids = static_cast<std::size_t>(w.next_disc_id());
  if (pinned_.size() < ids) pinned_.resize(ids, 0);
}

void WedgeExperiment::pin(const World& w, std::size_t disc) { pinned_[static_cast<std::size_t>(w.discs().id[disc])] = 1; }

bool WedgeExperiment::pinned(const World& w, std::size_t disc) const {
  const auto id = static_cast<std::size_t>(w.discs().id[disc]);
  return id < pinned_.size() && pinned_[id] != 0;
}

// Erosion (thesis 6.3): every disc, or whole cluster by its mean elevation, above the
// threshold is removed and logged.
void WedgeExperiment::erode(World& w, std::span<const std::uint8_t> above) {
  const bool count = surface_.active();  // the ledger is an output of surface runs only
  const double before = count ? disc_area(w) : 0.0;
  if (w.remove(above, RemovalReason::Eroded) > 0 && count) surface_.ledger().eroded_threshold += before - disc_area(w);
}

std::vector<std::uint8_t> WedgeExperiment::stray_flags(const World& w) const {
  const auto& d = w.discs();
  std::vector<std::uint8_t> flags(d.size(), 0);
  for (std::size_t i = 0; i < d.size(); ++i)
    flags[i] = d.y[i] < base_height(w, d.x[i]) - 2.0 || d.x[i] > x_end_ + 2.0 || d.y[i] > 50 * spec_.h0;
  return flags;
}

void WedgeExperiment::remove_strays(World& w, std::span<const std::uint8_t> strays) {
  const double before = disc_area(w);
  w.remove(strays, RemovalReason::LeftDomain);
  surface_.ledger().left += before - disc_area(w);
}

bool WedgeExperiment::advance(World& w) {
  if (convergence(w) >= spec_.s_end) return false;
  w.advance();
  feed_slab(w);
  // Each stage below reads or changes the discs: over ranks, every copy first gets the whole
  // state, or the positions alone where they tell that nothing is to change.
  if (spec_.erosion_height > 0 && w.step() % static_cast<std::uint64_t>(spec_.erosion_every) == 0) {
    w.gather_positions();
    if (const auto above = w.flags_above(spec_.erosion_height * spec_.h0); any_flagged(above)) {
      w.make_whole();
      erode(w, above);
    }
  }
  if (surface_.updates_at(w)) {
    w.make_whole();
    surface_.update(w, window_pro_ - spec_.h0, x_end_, spec_.surface.every * w.dt(), on_base(w));
  }
  if (base_.active()) {
    if (w.step() % static_cast<std::uint64_t>(spec_.isostasy.every) == 0) {
      w.gather_positions();  // the load reads the discs' positions and sizes alone
      base_.solve(w.discs(), slab_left_, x_end_, w.step());
      check_base_depth(w);
    }
    place_base(w);
  }
  if (w.step() % kHousekeepingEvery == 0) {
    // Both read positions only; the windows' motion edits are the same in every copy. Removing
    // strays (rare) changes the discs: the whole state first.
    w.gather_positions();
    if (const auto strays = stray_flags(w); any_flagged(strays)) {
      w.make_whole();
      remove_strays(w, strays);
    }
    update_windows(w);
  }
  return true;
}

Surface WedgeExperiment::surface(const Discs& discs) const {
  double r_mean = 0;
  for (double r : tile_.radius) r_mean += r;
  r_mean /= std::max<std::size_t>(1, tile_.size());
  return measure_surface(discs, window_pro_ - spec_.h0, x_end_, spec_.column_width_factor * r_mean);
}

// The discs of the crust: all but the sediment laid by the surface laws, so that the wedge's
// shape and fronts are the orogen's (a basin's fill would count as raised, deformed surface),
// and on a deflecting base each at its height above the base, so that they are the wedge's
// thickening rather than its sinking (docs/isostasy.md). Null where neither applies: measure
// the world's discs.
std::unique_ptr<Discs> WedgeExperiment::crust(const World& w) const {
  return crust_discs(surface_, spec_.surface.deposition, w, on_base(w));
}

namespace {

using Entry = SeriesEntry<WedgeSample>;
constexpr std::array kWedgeSeries = {
    Entry{"step", "-", "model time step", &WedgeSample::step},
    Entry{"time", "sqrt(d/g)", "model time", &WedgeSample::time},
    Entry{"S", "-", "normalised convergence: plate displacement / h0", &WedgeSample::S},
    Entry{"H", "h0", "wedge height: highest elevation minus h0", &WedgeSample::H},
    Entry{"Dp", "h0", "pro-side deformation front (wedge.fronts: raised surface or discs), from the S-point",
          &WedgeSample::Dp},
    Entry{"Mp", "h0", "pro-side marker front: smallest x of discs above the marker height", &WedgeSample::Mp},
    Entry{"Dr", "h0", "retro-side deformation front (wedge.fronts: raised surface or discs)", &WedgeSample::Dr},
    Entry{"Mr", "h0", "retro-side marker front: largest x of discs above the marker height", &WedgeSample::Mr},
    Entry{"T", "h0", "x of the highest disc (peak), from the S-point", &WedgeSample::T},
    Entry{"alpha", "deg", "mean pro-wedge taper: slope from Dp up to the peak", &WedgeSample::alpha},
    Entry{"beta", "deg", "mean retro-wedge taper: slope from the peak down to Dr", &WedgeSample::beta},
    Entry{"alpha_fit", "deg", "least-squares slope of the surface between Dp and the peak", &WedgeSample::alpha_fit},
    Entry{"beta_fit", "deg", "least-squares slope of the surface between the peak and Dr, sign flipped",
          &WedgeSample::beta_fit},
    Entry{"slip_pro", "-", "fraction of touching pro-side basal contacts at the Coulomb limit", &WedgeSample::slip_pro},
    Entry{"slip_retro", "-", "fraction of touching retro-side basal contacts at the Coulomb limit",
          &WedgeSample::slip_retro},
    Entry{"n_active", "-", "discs in the force computation that move by forces (dynamic)", &WedgeSample::n_active},
    Entry{"n_discs", "-", "discs in the model (active and kinematic slab)", &WedgeSample::n_discs},
    Entry{"n_eroded", "-", "discs removed by erosion so far", &WedgeSample::n_eroded},
    Entry{"n_left", "-", "discs that left the model space so far", &WedgeSample::n_left},
    Entry{"n_entered", "-", "discs ever added (initial layer and inflow); n_entered = n_discs + n_eroded + n_left",
          &WedgeSample::n_entered},
    Entry{"window_pro", "h0", "pro-side edge of the active region, from the S-point", &WedgeSample::window_pro},
    Entry{"window_retro", "h0", "retro-side edge of the active region, from the S-point", &WedgeSample::window_retro},
};

}  // namespace

std::vector<SeriesColumn> WedgeExperiment::columns() const {
  auto out = series_columns(kWedgeSeries);
  if (surface_.active()) {
    const auto ledger = ledger_columns(surface_);
    out.insert(out.end(), ledger.begin(), ledger.end());
  }
  if (base_.active()) out.insert(out.end(), isostasy_columns().begin(), isostasy_columns().end());
  return out;
}

std::vector<double> WedgeExperiment::measure(const World& w) const {
  const WedgeSample m = sample(w);
  auto out = series_values(kWedgeSeries, m);
  if (surface_.active())
    for (double v : ledger_values(surface_, w)) out.push_back(v);
  if (base_.active())
    for (double v : isostasy_values(w, m.Dp, m.Dr)) out.push_back(v);
  return out;
}

WedgeSample WedgeExperiment::sample(const World& w) const {
  const std::unique_ptr<Discs> without_sediment = crust(w);
  const Discs& measured = without_sediment ? *without_sediment : w.discs();
  const Surface s = surface(measured);
  // A raised stretch of surface counts as deformation from h0/2 wide, gaps up to h0/4 bridged
  // (wedge.fronts = surface).
  WedgeGeometryInput in{measured.x, measured.y, measured.radius, spec_.h0, spec_.packing.d_max, spec_.marker_height,
                        0.0, spec_.fronts, 0.5 * spec_.h0, 0.25 * spec_.h0};
  const WedgeGeometry g = measure_wedge(in, s);
  const WallContactStats pro = base_stats(w, pro_walls_);
  const WallContactStats retro = base_stats(w, retro_walls_);
  std::size_t active = 0, eroded = 0, left = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) active += w.discs().is_dynamic(i);
  for (const auto& r : w.removals()) {
    eroded += is_erosion(r.reason);
    left += r.reason == RemovalReason::LeftDomain;
  }
  const double h0 = spec_.h0;
  return {.step = static_cast<double>(w.step()), .time = w.time(), .S = convergence(w), .H = g.h / h0, .Dp = g.dp / h0,
          .Mp = g.mp / h0, .Dr = g.dr / h0, .Mr = g.mr / h0, .T = g.x_peak / h0, .alpha = g.alpha * kDegPerRad,
          .beta = g.beta * kDegPerRad, .alpha_fit = g.alpha_fit * kDegPerRad, .beta_fit = g.beta_fit * kDegPerRad,
          .slip_pro = pro.slip_fraction(), .slip_retro = retro.slip_fraction(),
          .n_active = static_cast<double>(active), .n_discs = static_cast<double>(w.discs().size()),
          .n_eroded = static_cast<double>(eroded), .n_left = static_cast<double>(left),
          .n_entered = static_cast<double>(entered_), .window_pro = window_pro_ / h0,
          .window_retro = window_retro_ / h0};
}

std::vector<SnapshotField> WedgeExperiment::fields(const World& w) const {
  auto out = displacements_.fields(w);
  if (spec_.surface.deposition) out.push_back(deposition_field(surface_, w));
  return out;
}

std::vector<std::pair<std::string, double>> WedgeExperiment::scalars(const World& w) const {
  return {{"S", convergence(w)}, {"view_x_min", view_box(w)[0]}, {"view_x_max", view_box(w)[1]},
          {"view_y_min", view_box(w)[2]}, {"view_y_max", view_box(w)[3]}};
}

void WedgeExperiment::after_output(const World& w) {
  displacements_.remember(w);
  const WedgeSample m = sample(w);
  history_.record({m.S, m.H, m.Dp, m.Mp, m.Dr, m.Mr, m.T, m.alpha, m.beta});
}

std::vector<OutputObserver> WedgeExperiment::output_observers(const std::filesystem::path& run_dir) const {
  if (!spec_.analysis_in_run) return {};
  return {in_run_analysis(run_dir, spec_.analysis_every)};
}

std::vector<SummaryValue> WedgeExperiment::summary(const World&) const { return history_.summary(0.25 * spec_.s_end); }

void WedgeExperiment::save(ArchiveWriter& out) const {
  save_tile(out, tile_);
  state_fields(*this, ArchiveSaver(out));
  displacements_.save(out, "wedge");
  history_.save(out, "wedge");
  if (surface_.active()) SurfaceProcesses::state_fields(surface_, ArchiveSaver(out));
  if (base_.active()) IsostaticBase::state_fields(base_, ArchiveSaver(out));
}

void WedgeExperiment::load(const ArchiveReader& in) {
  tile_ = read_tile(in);
  state_fields(*this, ArchiveLoader(in));
  displacements_.load(in, "wedge");
  history_.load(in, "wedge");
  start_surface();
  if (surface_.active()) surface_.load_state(in);
  start_isostasy();
  base_loaded_ = base_.active() && in.has("isostasy.nodes");
  if (base_loaded_) IsostaticBase::state_fields(base_, ArchiveLoader(in));
}

void WedgeExperiment::adopt_branch_config(World& w) {
  for (const auto& [walls, mu] : {std::pair{&pro_walls_, spec_.mu_bp}, std::pair{&retro_walls_, spec_.mu_br}})
    for (const std::size_t k : *walls) {
      const std::string name = w.walls()[k].name;
      w.set_wall_friction(name, w.walls()[k].friction, mu);
      w.set_wall_weakening(name, spec_.base_weakening);
    }
  if (surface_.active()) surface_.start_in_branch(w);
  if (base_.active() && !base_loaded_) start_isostasy_in_branch(w);
}

std::string WedgeExperiment::status(const World& w) const {
  std::size_t active = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) active += w.discs().is_dynamic(i);
  return fmt::format("S {:.2f}/{:.1f}, {} active discs", convergence(w), spec_.s_end, active);
}

std::array<double, 4> WedgeExperiment::view_box(const World& w) const {
  const double deepest = base_.active() ? std::max(0.0, base_.shape(w.step()).deepest) : 0.0;
  return {window_pro_ + spec_.window * spec_.h0 - 2 * spec_.h0, x_end_ + 0.5, -0.5 - deepest, 4.0 * spec_.h0};
}

}  // namespace orogen
