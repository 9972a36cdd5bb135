#include "parallel/migration.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

namespace orogen {
namespace {

// Calls f(r, begin, end) for each rank's range of `bounds` (ThreadSplit's, one per rank).
template <class F>
void for_each_range(const std::vector<std::ptrdiff_t>& bounds, F&& f) {
  for (std::size_t r = 0; r + 1 < bounds.size(); ++r)
    f(static_cast<std::int32_t>(r), static_cast<std::size_t>(bounds[r]), static_cast<std::size_t>(bounds[r + 1]));
}

// By stable id, the rank `rank_of` gives the item of each index.
template <class Ids, class RankOf>
std::vector<std::int32_t> by_id(const Ids& ids, RankOf&& rank_of) {
  const auto largest = ids.empty() ? std::int64_t{-1} : *std::max_element(ids.begin(), ids.end());
  std::vector<std::int32_t> out(static_cast<std::size_t>(largest + 1), kNoRank);
  for (std::size_t i = 0; i < ids.size(); ++i) out[static_cast<std::size_t>(ids[i])] = rank_of(i);
  return out;
}

// The old keeper if it differs from the new one, else kNoRank.
std::int32_t moved_from(std::int32_t before, std::int32_t after) { return before == after ? kNoRank : before; }

// Calls f(from, to, value) for each value whose keeper changed, in one order for packing,
// counting and unpacking: the discs' motion, the bodies' state, the wall contacts' histories
// (the positions and bonds came before the build; the pairs' histories go their own way,
// pair_migration.hpp).
template <class F>
void for_each_moving_value(RankAccess& a, const Migration& m, const ExchangePlan& plan, F&& f) {
  Discs& d = a.discs;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const std::int32_t from = m.disc[i], to = plan.step_rank[i];
    if (from == kNoRank) continue;
    f(from, to, d.vx[i]); f(from, to, d.vy[i]); f(from, to, d.omega[i]); f(from, to, d.theta[i]);
    if (d.has_materials) f(from, to, d.slip[i]);
  }
  Clusters& c = a.clusters;
  for_each_range(plan.cut.body, [&](std::int32_t to, std::size_t k0, std::size_t k1) {
    for (std::size_t k = k0; k < k1; ++k) {
      const std::int32_t from = m.body[k];
      if (from == kNoRank) continue;
      for (auto* v : {&c.theta[k], &c.vx[k], &c.vy[k], &c.omega[k], &c.rot_c[k], &c.rot_s[k], &c.fx[k], &c.fy[k],
                      &c.torque[k]})
        f(from, to, *v);
    }
  });
  WallContacts& wc = a.contacts.walls;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    const std::int32_t from = m.wall[k], to = plan.wall_rank[wc.disc[k]];
    if (from == kNoRank) continue;
    f(from, to, wc.xi[k]); f(from, to, wc.touching[k]); f(from, to, wc.at_limit[k]);
  }
}

}  // namespace

PreviousKeepers record_keepers(RankAccess& a, const ExchangePlan& plan) {
  PreviousKeepers k;
  k.disc_step = by_id(a.discs.id, [&](std::size_t i) { return plan.step_rank[i]; });
  k.disc_wall = by_id(a.discs.id, [&](std::size_t i) { return plan.wall_rank[i]; });
  const std::vector<std::int32_t> body_rank = rank_of_ranges(plan.cut.body, a.clusters.size());
  k.body = by_id(a.clusters.id, [&](std::size_t b) { return body_rank[b]; });
  return k;
}

Migration find_migration(RankAccess& a, const PreviousKeepers& before, const ExchangePlan& plan) {
  Migration m;
  const Discs& d = a.discs;
  m.disc.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i)
    m.disc[i] = moved_from(before.disc_step[static_cast<std::size_t>(d.id[i])], plan.step_rank[i]);
  const std::vector<std::int32_t> body_rank = rank_of_ranges(plan.cut.body, a.clusters.size());
  m.body.resize(a.clusters.size());
  for (std::size_t k = 0; k < a.clusters.size(); ++k)
    m.body[k] = moved_from(before.body[static_cast<std::size_t>(a.clusters.id[k])], body_rank[k]);
  const WallContacts& wc = a.contacts.walls;
  m.wall.resize(wc.size());
  for (std::size_t k = 0; k < wc.size(); ++k)
    m.wall[k] = moved_from(before.disc_wall[static_cast<std::size_t>(wc.disc_id[k])], plan.wall_rank[wc.disc[k]]);
  return m;
}

std::vector<std::vector<double>> pack_migration(RankAccess& a, const Migration& m, const ExchangePlan& plan, int from) {
  std::vector<std::vector<double>> out(static_cast<std::size_t>(plan.ranks));
  for_each_moving_value(a, m, plan, [&](std::int32_t f, std::int32_t to, auto& v) {
    if (f == from) out[static_cast<std::size_t>(to)].push_back(static_cast<double>(v));
  });
  return out;
}

std::vector<std::size_t> migration_sizes(RankAccess& a, const Migration& m, const ExchangePlan& plan, int to) {
  std::vector<std::size_t> sizes(static_cast<std::size_t>(plan.ranks), 0);
  for_each_moving_value(a, m, plan, [&](std::int32_t from, std::int32_t t, auto&) {
    if (t == to) ++sizes[static_cast<std::size_t>(from)];
  });
  return sizes;
}

void unpack_migration(RankAccess& a, const Migration& m, const ExchangePlan& plan, int to,
                      std::span<const std::vector<double>> received) {
  std::vector<std::size_t> next(received.size(), 0);
  for_each_moving_value(a, m, plan, [&](std::int32_t from, std::int32_t t, auto& v) {
    if (t != to) return;
    const auto q = static_cast<std::size_t>(from);
    if (next[q] == received[q].size()) throw std::logic_error("a migration of another size than its plan's");
    v = static_cast<std::remove_reference_t<decltype(v)>>(received[q][next[q]++]);
  });
  for (std::size_t q = 0; q < received.size(); ++q)
    if (next[q] != received[q].size()) throw std::logic_error("a migration of another size than its plan's");
}

}  // namespace orogen
