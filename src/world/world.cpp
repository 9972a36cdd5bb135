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
  if (w.dt > w.stable_dt())
    return fmt::format("time step dt = {:.3g} above the stability limit {:.3g} for k_n = {:.3g}", w.dt,
                       w.stable_dt(), w.law.kn);
  // Overlap under the weight of one disc, relative to its radius: a few percent at most.
  double m = 0, r = 0;
  for (std::size_t i = 0; i < w.discs.size(); ++i) { m += w.discs.mass[i]; r += w.discs.radius[i]; }
  const double sag = w.discs.size() ? (m / r) * std::hypot(w.body.gx, w.body.gy) / w.law.kn : 0.0;
  if (sag > 0.02)
    return fmt::format("k_n = {:.3g} is too soft for the load: one disc's own weight overlaps it by {:.1f}% of its "
                       "radius, a pile of them far more (raise contact.kn)",
                       w.law.kn, 100 * sag);
  // An overlap built up over many steps is a load the contact cannot hold, not a collision:
  // e.g. material driven into a corner of kinematic (pinned) discs.
  const auto& d = w.discs;
  const double dx = d.x[b] - d.x[a], dy = d.y[b] - d.y[a], dist = std::hypot(dx, dy);
  const double overlap = d.radius[a] + d.radius[b] - dist;
  const double closing = dist > 0 ? -((d.vx[b] - d.vx[a]) * dx + (d.vy[b] - d.vy[a]) * dy) / dist : 0.0;
  if (closing * 1000 * w.dt < overlap) {
    const double force = w.law.kn * overlap;
    const double weight = 0.5 * (d.mass[a] + d.mass[b]) * std::hypot(w.body.gx, w.body.gy);
    const std::string as_weight = weight > 0 ? fmt::format(" (the weight of {:.0f} discs)", force / weight) : "";
    return fmt::format("a load too large for k_n = {:.3g}: the contact carries k_n x overlap = {:.3g}{} and closes "
                       "at only {:.2g} per unit time, so the overlap grew over thousands of steps (raise contact.kn; "
                       "a stiffer contact lowers the largest wedge.speed of eq. 4.3)",
                       w.law.kn, force, as_weight, closing);
  }
  return fmt::format("an imposed velocity (moving wall, plate, kinematic discs) too fast for k_n = {:.3g} at "
                     "dt = {:.3g}, or a collision too violent for them",
                     w.law.kn, w.dt);
}

void check_build(const BuildStats& s, const World& w) {
  if (!s.finite)
    throw InstabilityError(fmt::format(
        "simulation became unstable at step {} (t = {:.6g}): disc positions are no longer finite. "
        "Likely cause: time step dt = {:.3g} too large for k_n = {:.3g} (stable limit {:.3g}), or an imposed "
        "velocity too fast for the contact stiffness",
        w.step, w.time, w.dt, w.law.kn, w.stable_dt()));
  if (s.max_overlap_ratio > 0.5)
    throw InstabilityError(fmt::format(
        "simulation became unstable at step {} (t = {:.6g}): discs {} and {} overlap by {:.0f}% of the smaller "
        "radius. Likely cause: {}",
        w.step, w.time, w.discs.id[s.worst_a], w.discs.id[s.worst_b], 100 * s.max_overlap_ratio,
        likely_cause(w, s.worst_a, s.worst_b)));
}

}  // namespace

void World::advance() {
  if (contacts_stale()) {
    const bool sort = sort_every > 0 && neighbors.builds % static_cast<std::uint64_t>(sort_every) == 0;
    check_build(rebuild_contacts(sort), *this);
  }
  step_stages();
  hooks.run(Stage::AfterIntegration, *this);
  for (auto& w : walls) {
    w.ax += w.vx * dt; w.bx += w.vx * dt;
    w.ay += w.vy * dt; w.by += w.vy * dt;
  }
  ++step;
  time = static_cast<double>(step) * dt;
}

void World::step_stages(const ThreadSplit* given) {
  scratch.forces.resize(discs.size());  // zero between steps (integration leaves them so)
  DiscForce* forces = scratch.forces.data();
  const int threads = given ? given->threads() : step_threads(discs.size());
  const ThreadSplit& cut = given ? *given : thread_cut(threads);
  double max2 = 0;
  std::int64_t not_finite = 0;
  // Hooks after the forces run on one thread between the force stages and integration; with
  // none, the team does not wait there for it.
  const bool after_forces = !hooks.empty(Stage::AfterForces);
  std::exception_ptr hook_error;
  ThreadSplit fallback;
  // Named materials: each disc's friction from its material and its slip (contact/materials.hpp).
  const double* mu_disc = nullptr;
  if (discs.has_materials) {
    disc_friction.resize(discs.size());
    for (std::size_t i = 0; i < discs.size(); ++i)
      disc_friction[i] = materials.list[discs.material[i]].friction_at(discs.slip[i]);
    mu_disc = disc_friction.data();
  }
  // Weakening walls: each disc's coefficient from its slip as the step began (the pair stage adds
  // to it before the wall stage runs).
  WallSlip wall_slip;
  if (discs.has_materials && std::any_of(walls.begin(), walls.end(), [](const Wall& w) { return w.weakens; })) {
    slip_at_step_start.assign(discs.slip.begin(), discs.slip.end());
    wall_slip = {slip_at_step_start.data(), discs.slip.data()};
  }
  if (!bonds.id_a.empty()) prepare_bond_scratch(bonds, discs, neighbors.builds, bond_scratch);
  const std::size_t bond_count = bonds.id_a.empty() ? 0 : bond_scratch.acting;
  // One thread team for all three stages (a team per stage cost a fork and a join each), each
  // thread on its own stretch of the domain.
#pragma omp parallel num_threads(threads) reduction(max : max2) reduction(+ : not_finite) if (threads > 1)
  {
    // OMP_DYNAMIC may give fewer threads than asked for: then cut for the team actually given.
    const bool whole_team = cut.threads() == omp_get_num_threads();
    if (!whole_team) {
#pragma omp single
      fallback = split_threads(neighbors, discs, clusters, omp_get_num_threads());
    }
    const ThreadSplit& split = whole_team ? cut : fallback;
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    pair_forces_share(neighbors, contacts.pairs, discs, law, mu_disc, dt, forces, split, t);
    wall_forces_share(contacts.walls, discs, walls, law, dt, wall_slip, forces, split, t);
    // A body's members may lie in the next thread's stretch: their forces must be whole before
    // it gathers them, and their wall contacts read before it moves them.
#pragma omp barrier
    if (bond_count > 0) {
      // Each thread its stretch of bonds, then one thread adds them in bond order.
      const auto team = static_cast<std::size_t>(omp_get_num_threads());
      bond_forces_range(bonds, discs, dt, bond_scratch, bond_count * t / team, bond_count * (t + 1) / team);
#pragma omp barrier
#pragma omp single
      apply_bond_forces(bonds, discs, bond_scratch, forces, step, time);
    }
    if (after_forces) {
#pragma omp single
      {
        try {
          hooks.run(Stage::AfterForces, *this);
        } catch (...) {
          hook_error = std::current_exception();  // an exception may not leave the team
        }
      }
    }
    const Displacement r =
        integrate_share(discs, clusters, forces, body, dt, neighbors.x_ref.data(), neighbors.y_ref.data(), split, t);
    max2 = r.max2;
    not_finite = r.not_finite;
  }
  if (hook_error) std::rethrow_exception(hook_error);
  moved = Displacement{max2, not_finite}.distance();
}

const ThreadSplit& World::thread_cut(int threads) {
  // The cut depends on the list and on the disc and body counts alone: made again only when
  // one of them changed, not every step (it cost a `single`, a barrier and three allocations).
  ThreadSplit& s = scratch.split;
  const auto chunks = static_cast<std::ptrdiff_t>(neighbors.chunk_start.empty() ? 0 : neighbors.chunk_start.size() - 1);
  const bool current = scratch.split_build == neighbors.builds && s.threads() == threads && s.chunk.back() == chunks &&
                       s.disc.back() == static_cast<std::ptrdiff_t>(discs.size()) &&
                       s.body.back() == static_cast<std::ptrdiff_t>(clusters.size());
  if (!current) {
    s = split_threads(neighbors, discs, clusters, threads);
    scratch.split_build = neighbors.builds;
  }
  return s;
}

bool World::contacts_stale() const { return orogen::contacts_stale(neighbors, discs, walls, moved); }

BuildStats World::rebuild_contacts(bool sort) {
  const BuildStats stats = orogen::rebuild_contacts(neighbors, contacts, discs, clusters, walls, law, dt, sort);
  if (!bonds.id_a.empty()) {  // the build may have re-ordered the discs, a removal compacted them
    std::vector<std::int64_t> index_of_id(static_cast<std::size_t>(next_disc_id), -1);
    for (std::size_t i = 0; i < discs.size(); ++i) index_of_id[static_cast<std::size_t>(discs.id[i])] = static_cast<std::int64_t>(i);
    remap_bonds(bonds, index_of_id);
  }
  return stats;
}

std::size_t World::remove(std::span<const std::uint8_t> flags, RemovalReason reason) {
  std::vector<std::uint8_t> gone_cluster(clusters.size(), 0);
  for (std::size_t i = 0; i < discs.size(); ++i)
    if (flags[i] && discs.cluster[i] >= 0) gone_cluster[static_cast<std::size_t>(discs.cluster[i])] = 1;
  std::vector<std::uint8_t> keep(discs.size(), 1);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < discs.size(); ++i) {
    const bool gone = flags[i] || (discs.cluster[i] >= 0 && gone_cluster[static_cast<std::size_t>(discs.cluster[i])]);
    if (!gone) continue;
    keep[i] = 0;
    ++removed;
    removals.push_back({step, time, discs.id[i], discs.cluster_id[i], discs.x[i], discs.y[i], reason});
  }
  if (removed == 0) return 0;
  discs.compact(keep);
  for (auto& g : gone_cluster) g = !g;
  clusters.compact(gone_cluster);
  relink_clusters(clusters, discs);
  neighbors.valid = false;
  return removed;
}

std::size_t World::remove_above(double height, RemovalReason reason) {
  std::vector<double> cluster_y(clusters.size(), 0.0);
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    int n = 0;
    for (auto i : clusters.members[k])
      if (i >= 0) { cluster_y[k] += discs.y[static_cast<std::size_t>(i)]; ++n; }
    cluster_y[k] /= n;
  }
  std::vector<std::uint8_t> flags(discs.size(), 0);
  for (std::size_t i = 0; i < discs.size(); ++i) {
    const double y = discs.cluster[i] >= 0 ? cluster_y[static_cast<std::size_t>(discs.cluster[i])] : discs.y[i];
    flags[i] = y > height;
  }
  return remove(flags, reason);
}

std::size_t World::add_disc(double x, double y, double r) {
  neighbors.valid = false;
  return discs.add(next_disc_id++, x, y, r);
}

std::size_t World::add_cluster(std::span<const std::size_t> idx) {
  neighbors.valid = false;
  return make_cluster(clusters, discs, idx, next_cluster_id++);
}

double World::min_pair_mass() const {
  double m_min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < discs.size(); ++i) m_min = std::min(m_min, discs.mass[i]);
  return 0.5 * m_min;  // infinite without discs: no contact, no limit (a configuration's own
                       // limit, for discs yet to come, is experiments/time_step_config.cpp's)
}

double stable_time_step(double kn, double min_pair_mass) {
  return 0.1 * 2.0 * std::numbers::pi * std::sqrt(min_pair_mass / kn);
}

double World::stable_dt() const {
  double k_bond = 0;  // a bond acts beside the contact: their stiffnesses add
  for (std::size_t k = 0; k < bonds.size(); ++k) k_bond = std::max(k_bond, bonds.kn[k] * 2 * bonds.radius[k]);
  return stable_time_step(law.kn + k_bond, min_pair_mass());
}

double World::kinetic_energy() const {
  double e = 0;
  for (std::size_t i = 0; i < discs.size(); ++i) {
    if (discs.cluster[i] >= 0 || !discs.is_dynamic(i)) continue;
    const double m = discs.mass[i];
    e += 0.5 * m * (discs.vx[i] * discs.vx[i] + discs.vy[i] * discs.vy[i]) +
         0.5 * discs.omega[i] * discs.omega[i] / discs.inv_inertia[i];
  }
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    if (clusters.motion[k] != static_cast<std::uint8_t>(Motion::Dynamic)) continue;
    e += 0.5 * clusters.mass[k] * (clusters.vx[k] * clusters.vx[k] + clusters.vy[k] * clusters.vy[k]) +
         0.5 * clusters.omega[k] * clusters.omega[k] / clusters.inv_inertia[k];
  }
  return e;
}

}  // namespace orogen
