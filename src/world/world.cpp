#include "world/world.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>

#include "boundary/wall_forces.hpp"
#include "world/contact_rebuild.hpp"

namespace orogen {
namespace {

// The most likely reason for a blow-up, from the time step, the stiffness, the weights and the
// worst pair (discs a and b).
std::string likely_cause(const World& w, std::size_t a, std::size_t b) {
  if (w.dt() > w.stable_dt())
    return fmt::format("time step dt = {:.3g} above the stability limit {:.3g} for k_n = {:.3g}", w.dt(),
                       w.stable_dt(), w.law().kn);
  // Overlap under the weight of one disc, relative to its radius: a few percent at most.
  double m = 0, r = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) { m += w.discs().mass[i]; r += w.discs().radius[i]; }
  const double sag = w.discs().size() ? (m / r) * std::hypot(w.body().gx, w.body().gy) / w.law().kn : 0.0;
  if (sag > 0.02)
    return fmt::format("k_n = {:.3g} is too soft for the load: one disc's own weight overlaps it by {:.1f}% of its "
                       "radius, a pile of them far more (raise contact.kn)",
                       w.law().kn, 100 * sag);
  // An overlap built up over many steps is a load the contact cannot hold, not a collision:
  // e.g. material driven into a corner of kinematic (pinned) discs.
  const auto& d = w.discs();
  const double dx = d.x[b] - d.x[a], dy = d.y[b] - d.y[a], dist = std::hypot(dx, dy);
  const double overlap = d.radius[a] + d.radius[b] - dist;
  const double closing = dist > 0 ? -((d.vx[b] - d.vx[a]) * dx + (d.vy[b] - d.vy[a]) * dy) / dist : 0.0;
  if (closing * 1000 * w.dt() < overlap) {
    const double force = w.law().kn * overlap;
    const double weight = 0.5 * (d.mass[a] + d.mass[b]) * std::hypot(w.body().gx, w.body().gy);
    const std::string as_weight = weight > 0 ? fmt::format(" (the weight of {:.0f} discs)", force / weight) : "";
    return fmt::format("a load too large for k_n = {:.3g}: the contact carries k_n x overlap = {:.3g}{} and closes "
                       "at only {:.2g} per unit time, so the overlap grew over thousands of steps (raise contact.kn; "
                       "a stiffer contact lowers the largest wedge.speed of eq. 4.3)",
                       w.law().kn, force, as_weight, closing);
  }
  return fmt::format("an imposed velocity (moving wall, plate, kinematic discs) too fast for k_n = {:.3g} at "
                     "dt = {:.3g}, or a collision too violent for them",
                     w.law().kn, w.dt());
}

void check_build(const BuildStats& s, const World& w) {
  if (!s.finite)
    throw InstabilityError(fmt::format(
        "simulation became unstable at step {} (t = {:.6g}): disc positions are no longer finite. "
        "Likely cause: time step dt = {:.3g} too large for k_n = {:.3g} (stable limit {:.3g}), or an imposed "
        "velocity too fast for the contact stiffness",
        w.step(), w.time(), w.dt(), w.law().kn, w.stable_dt()));
  if (s.max_overlap_ratio > 0.5)
    throw InstabilityError(fmt::format(
        "simulation became unstable at step {} (t = {:.6g}): discs {} and {} overlap by {:.0f}% of the smaller "
        "radius. Likely cause: {}",
        w.step(), w.time(), w.discs().id[s.worst_a], w.discs().id[s.worst_b], 100 * s.max_overlap_ratio,
        likely_cause(w, s.worst_a, s.worst_b)));
}

}  // namespace

void World::advance() {
  if (rank_.rank) {
    rank_.rank->advance();
    return;
  }
  rebuild_if_stale();
  step_stages();
  hooks_.run(Stage::AfterIntegration, *this);
  finish_step();
}

void World::rebuild_if_stale() {
  if (!contacts_stale()) return;
  check_build(rebuild_contacts(sort_at_next_build()), *this);
}

bool World::sort_at_next_build() const {
  return sort_every_ > 0 && neighbors_.builds % static_cast<std::uint64_t>(sort_every_) == 0;
}

void World::begin_list_build(PendingBuild& build, PairRange indexed) {
  build = begin_rebuild(neighbors_, contacts_, discs_, clusters_, sort_at_next_build(), indexed);
  if (!build.finite) {
    BuildStats stats;
    stats.finite = false;
    check_build(stats, *this);
  }
}

void World::join_list_build(PendingBuild& build, const std::vector<ChunkPairs>& chunks) {
  take_found_pairs(build, join_pair_chunks(neighbors_, chunks, pair_chunks(build.bins.grid).stripes_per_chunk),
                   neighbors_);
}

void World::finish_list_build(PendingBuild& build, PairRange carried) {
  const BuildStats stats = finish_rebuild(build, neighbors_, contacts_, discs_, clusters_, walls_, law_, dt_, carried);
  after_list_build();
  check_build(stats, *this);
}

void World::finish_step() {
  for (auto& w : walls_) {
    w.ax += w.vx * dt_; w.bx += w.vx * dt_;
    w.ay += w.vy * dt_; w.by += w.vy * dt_;
  }
  ++step_;
  time_ = static_cast<double>(step_) * dt_;
}

void World::step_stages(const ThreadSplit* given) {
  scratch_.forces.resize(discs_.size());  // zero between steps (integration leaves them so)
  DiscForce* forces = scratch_.forces.data();
  const int threads = given ? given->threads() : step_threads(discs_.size());
  const ThreadSplit& cut = given ? *given : thread_cut(threads);
  double max2 = 0;
  std::int64_t not_finite = 0;
  // Hooks after the forces run on one thread between the force stages and integration; with
  // none, the team does not wait there for it.
  const bool after_forces = !hooks_.empty(Stage::AfterForces);
  std::exception_ptr hook_error;
  ThreadSplit fallback;
  DiscCoefficients disc_coefficients;
  WallSlip wall_slip;
  prepare_contact_coefficients(disc_coefficients, wall_slip);
  if (!bonds_.id_a.empty()) prepare_bond_scratch(bonds_, discs_, neighbors_.builds, bond_scratch_);
  const std::size_t bond_count = bonds_.id_a.empty() ? 0 : bond_scratch_.acting;
  // One thread team for all three stages (a team per stage cost a fork and a join each), each
  // thread on its own stretch of the domain.
#pragma omp parallel num_threads(threads) reduction(max : max2) reduction(+ : not_finite) if (threads > 1)
  {
    // OMP_DYNAMIC may give fewer threads than asked for: then cut for the team actually given.
    const bool whole_team = cut.threads() == omp_get_num_threads();
    if (!whole_team) {
#pragma omp single
      fallback = split_threads(neighbors_, discs_, clusters_, omp_get_num_threads());
    }
    const ThreadSplit& split = whole_team ? cut : fallback;
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    pair_forces_share(neighbors_, contacts_.pairs, discs_, law_, disc_coefficients, dt_, forces, split, t);
    wall_forces_share(contacts_.walls, discs_, walls_, law_, dt_, wall_slip, forces, split, t);
    // A body's members may lie in the next thread's stretch: their forces must be whole before
    // it gathers them, and their wall contacts read before it moves them.
#pragma omp barrier
    if (bond_count > 0) {
      // Each thread its stretch of bonds, then one thread adds them in bond order.
      const auto team = static_cast<std::size_t>(omp_get_num_threads());
      bond_forces_range(bonds_, discs_, dt_, bond_scratch_, bond_count * t / team, bond_count * (t + 1) / team);
#pragma omp barrier
#pragma omp single
      apply_bond_forces(bonds_, discs_, bond_scratch_, forces, step_, time_);
    }
    if (after_forces) {
#pragma omp single
      {
        try {
          hooks_.run(Stage::AfterForces, *this);
        } catch (...) {
          hook_error = std::current_exception();  // an exception may not leave the team
        }
      }
    }
    const Displacement r =
        integrate_share(discs_, clusters_, forces, body_, dt_, neighbors_.x_ref.data(), neighbors_.y_ref.data(), split, t);
    max2 = r.max2;
    not_finite = r.not_finite;
  }
  if (hook_error) std::rethrow_exception(hook_error);
  moved_ = Displacement{max2, not_finite}.distance();
}

void World::prepare_contact_coefficients(DiscCoefficients& disc, WallSlip& wall_slip) {
  // Named materials: each disc's friction from its material and its slip (contact/materials.hpp).
  if (discs_.has_materials) {
    disc_friction_.resize(discs_.size());
    for (std::size_t i = 0; i < discs_.size(); ++i)
      disc_friction_[i] = materials_.list[discs_.material[i]].friction_at(discs_.slip[i]);
    disc.friction = disc_friction_.data();
  }
  prepare_rolling(disc);
  // Weakening walls: each disc's coefficient from its slip as the step began (the pair stage adds
  // to it before the wall stage runs).
  if (discs_.has_materials && std::any_of(walls_.begin(), walls_.end(), [](const Wall& w) { return w.weakens; })) {
    slip_at_step_start_.assign(discs_.slip.begin(), discs_.slip.end());
    wall_slip = {slip_at_step_start_.data(), discs_.slip.data()};
  }
}

bool World::resists_rolling() const {
  return discs_.has_materials ? materials_.any_rolling() : law_.rolling_friction > 0;
}

void World::prepare_rolling(DiscCoefficients& disc) {
  // The store keeps rolling histories exactly while some contact resists rolling: without, the
  // pair loops are those of the thesis's law, bit for bit.
  auto& roll = contacts_.pairs.roll;
  if (!resists_rolling()) {
    roll.clear();
    return;
  }
  if (roll.empty()) roll.assign(contacts_.pairs.size(), 0.0);  // resisting from this step on
  if (!discs_.has_materials) return;
  // A material's coefficient does not change with slip: the loops read it through each disc's
  // material, from this table of a few entries.
  material_rolling_.resize(materials_.size());
  for (std::size_t m = 0; m < materials_.size(); ++m) material_rolling_[m] = materials_.list[m].rolling_friction;
  disc.material = discs_.material.data();
  disc.rolling = material_rolling_.data();
}

const ThreadSplit& World::thread_cut(int threads) {
  // The cut depends on the list and on the disc and body counts alone: made again only when
  // one of them changed, not every step (it cost a `single`, a barrier and three allocations).
  ThreadSplit& s = scratch_.split;
  const auto chunks = static_cast<std::ptrdiff_t>(neighbors_.chunk_start.empty() ? 0 : neighbors_.chunk_start.size() - 1);
  const bool current = scratch_.split_build == neighbors_.builds && s.threads() == threads && s.chunk.back() == chunks &&
                       s.disc.back() == static_cast<std::ptrdiff_t>(discs_.size()) &&
                       s.body.back() == static_cast<std::ptrdiff_t>(clusters_.size());
  if (!current) {
    s = split_threads(neighbors_, discs_, clusters_, threads);
    scratch_.split_build = neighbors_.builds;
  }
  return s;
}

bool World::contacts_stale() const { return orogen::contacts_stale(neighbors_, discs_, walls_, moved_); }

BuildStats World::rebuild_contacts(bool sort) {
  const BuildStats stats = orogen::rebuild_contacts(neighbors_, contacts_, discs_, clusters_, walls_, law_, dt_, sort);
  after_list_build();
  return stats;
}

void World::after_list_build() {
  moved_ = 0;  // no disc has moved since this build
  if (!bonds_.id_a.empty()) {  // the build may have re-ordered the discs, a removal compacted them
    std::vector<std::int64_t> index_of_id(static_cast<std::size_t>(next_disc_id_), -1);
    for (std::size_t i = 0; i < discs_.size(); ++i) index_of_id[static_cast<std::size_t>(discs_.id[i])] = static_cast<std::int64_t>(i);
    remap_bonds(bonds_, index_of_id);
  }
}

std::size_t World::remove(std::span<const std::uint8_t> flags, RemovalReason reason) {
  std::vector<std::uint8_t> gone_cluster(clusters_.size(), 0);
  for (std::size_t i = 0; i < discs_.size(); ++i)
    if (flags[i] && discs_.cluster[i] >= 0) gone_cluster[static_cast<std::size_t>(discs_.cluster[i])] = 1;
  std::vector<std::uint8_t> keep(discs_.size(), 1);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < discs_.size(); ++i) {
    const bool gone = flags[i] || (discs_.cluster[i] >= 0 && gone_cluster[static_cast<std::size_t>(discs_.cluster[i])]);
    if (!gone) continue;
    keep[i] = 0;
    ++removed;
    removals_.push_back({step_, time_, discs_.id[i], discs_.cluster_id[i], discs_.x[i], discs_.y[i], reason});
  }
  if (removed == 0) return 0;
  discs_.compact(keep);
  for (auto& g : gone_cluster) g = !g;
  clusters_.compact(gone_cluster);
  relink_clusters(clusters_, discs_);
  neighbors_.valid = false;
  return removed;
}

std::size_t World::remove_above(double height, RemovalReason reason) { return remove(flags_above(height), reason); }

std::vector<std::uint8_t> World::flags_above(double height) const {
  std::vector<double> cluster_y(clusters_.size(), 0.0);
  for (std::size_t k = 0; k < clusters_.size(); ++k) {
    int n = 0;
    for (auto i : clusters_.members[k])
      if (i >= 0) { cluster_y[k] += discs_.y[static_cast<std::size_t>(i)]; ++n; }
    cluster_y[k] /= n;
  }
  std::vector<std::uint8_t> flags(discs_.size(), 0);
  for (std::size_t i = 0; i < discs_.size(); ++i) {
    const double y = discs_.cluster[i] >= 0 ? cluster_y[static_cast<std::size_t>(discs_.cluster[i])] : discs_.y[i];
    flags[i] = y > height;
  }
  return flags;
}

std::size_t World::add_disc(double x, double y, double r) {
  neighbors_.valid = false;
  return discs_.add(next_disc_id_++, x, y, r);
}

std::size_t World::add_cluster(std::span<const std::size_t> idx) {
  neighbors_.valid = false;
  return make_cluster(clusters_, discs_, idx, next_cluster_id_++);
}

double World::min_pair_mass() const {
  double m_min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < discs_.size(); ++i) m_min = std::min(m_min, discs_.mass[i]);
  return 0.5 * m_min;  // infinite without discs: no contact, no limit (a configuration's own
                       // limit, for discs yet to come, is experiments/time_step_config.cpp's)
}

double stable_time_step(double kn, double min_pair_mass) {
  return 0.1 * 2.0 * std::numbers::pi * std::sqrt(min_pair_mass / kn);
}

double World::stable_dt() const {
  double k_bond = 0;  // a bond acts beside the contact: their stiffnesses add
  for (std::size_t k = 0; k < bonds_.size(); ++k) k_bond = std::max(k_bond, bonds_.kn[k] * 2 * bonds_.radius[k]);
  return stable_time_step(law_.kn + k_bond, min_pair_mass());
}

double World::kinetic_energy() const {
  double e = 0;
  for (std::size_t i = 0; i < discs_.size(); ++i) {
    if (discs_.cluster[i] >= 0 || !discs_.is_dynamic(i)) continue;
    const double m = discs_.mass[i];
    e += 0.5 * m * (discs_.vx[i] * discs_.vx[i] + discs_.vy[i] * discs_.vy[i]) +
         0.5 * discs_.omega[i] * discs_.omega[i] / discs_.inv_inertia[i];
  }
  for (std::size_t k = 0; k < clusters_.size(); ++k) {
    if (clusters_.motion[k] != static_cast<std::uint8_t>(Motion::Dynamic)) continue;
    e += 0.5 * clusters_.mass[k] * (clusters_.vx[k] * clusters_.vx[k] + clusters_.vy[k] * clusters_.vy[k]) +
         0.5 * clusters_.omega[k] * clusters_.omega[k] / clusters_.inv_inertia[k];
  }
  return e;
}

}  // namespace orogen
