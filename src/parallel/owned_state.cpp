#include "parallel/owned_state.hpp"

#include <stdexcept>
#include <type_traits>

#include "contact/contact_damping.hpp"
#include "contact/store_carry.hpp"
#include "parallel/packed_pair.hpp"
#include "parallel/pair_migration.hpp"

namespace orogen {
namespace {

// A bond's state is its first disc's integrating rank's (both sides step a bond across the cut alike).
template <class F>
void for_each_owned_bond_value(RankAccess& a, const ExchangePlan& plan, int owner, F&& f) {
  Bonds& B = a.bonds;
  const std::size_t acting = B.id_a.empty() ? 0 : a.bond_scratch.acting;
  for (std::size_t k = 0; k < acting; ++k) {
    if (plan.step_rank[B.a[k]] != owner) continue;
    f(B.fn[k]); f(B.fs[k]); f(B.moment[k]);
  }
}

// Calls f(value) for each value rank `owner` keeps current (doubles, and the wall contacts'
// flags), in one order for packing and unpacking.
template <class F>
void for_each_owned_value(RankAccess& a, const ExchangePlan& plan, int owner, F&& f) {
  Discs& d = a.discs;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (plan.step_rank[i] != owner) continue;
    f(d.x[i]); f(d.y[i]); f(d.vx[i]); f(d.vy[i]); f(d.omega[i]); f(d.theta[i]);
    if (d.has_materials) f(d.slip[i]);
  }
  Clusters& c = a.clusters;
  const auto r = static_cast<std::size_t>(owner);
  for (auto k = static_cast<std::size_t>(plan.cut.body[r]); k < static_cast<std::size_t>(plan.cut.body[r + 1]); ++k) {
    f(c.x[k]); f(c.y[k]); f(c.theta[k]); f(c.vx[k]); f(c.vy[k]); f(c.omega[k]);
    f(c.rot_c[k]); f(c.rot_s[k]); f(c.fx[k]); f(c.fy[k]); f(c.torque[k]);
  }
  {  // its chunks: a contiguous range of pairs
    auto& xi = a.contacts.pairs.xi;
    auto& roll = a.contacts.pairs.roll;  // empty unless some contact resists rolling
    const PairRange own = rank_pairs(a.neighbors, plan.cut, owner);
    for (std::size_t p = own.begin; p < own.end; ++p) {
      f(xi[p]);
      if (!roll.empty()) f(roll[p]);
    }
  }
  for_each_owned_bond_value(a, plan, owner, f);
  WallContacts& wc = a.contacts.walls;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    if (plan.wall_rank[wc.disc[k]] != owner) continue;
    f(wc.xi[k]); f(wc.touching[k]); f(wc.at_limit[k]);
  }
}

// Calls f(value) for each position rank `owner` keeps current: its discs' and bodies' x and y.
template <class F>
void for_each_owned_position(RankAccess& a, const ExchangePlan& plan, int owner, F&& f) {
  Discs& d = a.discs;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (plan.step_rank[i] == owner) { f(d.x[i]); f(d.y[i]); }
  Clusters& c = a.clusters;
  const auto r = static_cast<std::size_t>(owner);
  for (auto k = static_cast<std::size_t>(plan.cut.body[r]); k < static_cast<std::size_t>(plan.cut.body[r + 1]); ++k) {
    f(c.x[k]); f(c.y[k]);
  }
}

// What a list build without the whole state reads of rank `owner`'s: its positions, and its
// bonds' state (the bonds are re-ordered after a build; gathered whole, they need no migration).
template <class F>
void for_each_build_value(RankAccess& a, const ExchangePlan& plan, int owner, F&& f) {
  for_each_owned_position(a, plan, owner, f);
  for_each_owned_bond_value(a, plan, owner, f);
}

template <class Each>
void pack(RankAccess& a, const ExchangePlan& plan, int owner, std::vector<double>& out, Each each) {
  each(a, plan, owner, [&](auto& v) { out.push_back(static_cast<double>(v)); });
}

template <class Each>
void unpack(RankAccess& a, const ExchangePlan& plan, int owner, std::span<const double> in, Each each) {
  std::size_t k = 0;
  each(a, plan, owner, [&](auto& v) {
    if (k == in.size()) throw std::logic_error("owned state of another size than its plan's");
    v = static_cast<std::remove_reference_t<decltype(v)>>(in[k++]);
  });
  if (k != in.size()) throw std::logic_error("owned state of another size than its plan's");
}

template <class Each>
std::size_t count(RankAccess& a, const ExchangePlan& plan, int owner, Each each) {
  std::size_t n = 0;
  each(a, plan, owner, [&](auto&) { ++n; });
  return n;
}

// The two walks as values (a function template cannot be passed as one).
constexpr auto kState = [](RankAccess& a, const ExchangePlan& p, int owner, auto&& f) { for_each_owned_value(a, p, owner, f); };
constexpr auto kPositions = [](RankAccess& a, const ExchangePlan& p, int owner, auto&& f) {
  for_each_owned_position(a, p, owner, f);
};
constexpr auto kBuild = [](RankAccess& a, const ExchangePlan& p, int owner, auto&& f) { for_each_build_value(a, p, owner, f); };

}  // namespace

void pack_owned_state(RankAccess& a, const ExchangePlan& plan, int owner, std::vector<double>& out) {
  pack(a, plan, owner, out, kState);
}

void unpack_owned_state(RankAccess& a, const ExchangePlan& plan, int owner, std::span<const double> in) {
  unpack(a, plan, owner, in, kState);
}

std::size_t owned_state_size(RankAccess& a, const ExchangePlan& plan, int owner) { return count(a, plan, owner, kState); }

void pack_owned_positions(RankAccess& a, const ExchangePlan& plan, int owner, std::vector<double>& out) {
  pack(a, plan, owner, out, kPositions);
}

void unpack_owned_positions(RankAccess& a, const ExchangePlan& plan, int owner, std::span<const double> in) {
  unpack(a, plan, owner, in, kPositions);
}

std::size_t owned_positions_size(RankAccess& a, const ExchangePlan& plan, int owner) {
  return count(a, plan, owner, kPositions);
}

void pack_build_state(RankAccess& a, const ExchangePlan& plan, int owner, std::vector<double>& out) {
  pack(a, plan, owner, out, kBuild);
}

void unpack_build_state(RankAccess& a, const ExchangePlan& plan, int owner, std::span<const double> in) {
  unpack(a, plan, owner, in, kBuild);
}

std::size_t build_state_size(RankAccess& a, const ExchangePlan& plan, int owner) { return count(a, plan, owner, kBuild); }

void pack_list_pairs(RankAccess& a, const ExchangePlan& plan, int owner, std::vector<double>& out) {
  const NeighborList& L = a.neighbors;
  const PairRange own = rank_pairs(L, plan.cut, owner);
  for (std::size_t p = own.begin; p < own.end; ++p) out.push_back(pack_pair(L.first[p], L.second[p]));
}

void unpack_list_pairs(RankAccess& a, const ExchangePlan& plan, int owner, std::span<const double> in) {
  NeighborList& L = a.list();
  const PairRange theirs = rank_pairs(L, plan.cut, owner);
  if (in.size() != theirs.end - theirs.begin)
    throw std::logic_error("a rank's pairs of another number than its chunks'");
  std::size_t p = theirs.begin;
  for (const double packed : in) {
    unpack_pair(packed, L.first[p], L.second[p]);
    ++p;
  }
}

std::size_t list_pairs_size(RankAccess& a, const ExchangePlan& plan, int owner) {
  const PairRange theirs = rank_pairs(a.neighbors, plan.cut, owner);
  return theirs.end - theirs.begin;
}

void complete_gathered_list(RankAccess& a) {
  set_pair_ids(a.contacts.pairs, a.neighbors, a.discs);
  prepare_damping(a.law, a.discs, a.clusters, a.dt);
  set_pair_damping(a.contacts.pairs, a.neighbors, a.discs, a.clusters, a.law, a.dt);
}

}  // namespace orogen
