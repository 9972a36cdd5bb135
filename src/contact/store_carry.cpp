#include "contact/store_carry.hpp"

#include <algorithm>
#include <cstddef>

#include "util/parallel.hpp"

namespace orogen {

std::int64_t max_stored_id(const ContactStore& s) {
  std::int64_t max_id = 0;
  for (auto id : s.pairs.id_first) max_id = std::max(max_id, id);
  for (auto id : s.walls.disc_id) max_id = std::max(max_id, id);
  return max_id;
}

HistoryCarry index_pair_history(const PairContacts& pairs, std::span<const double> history, std::int64_t max_id,
                                PairRange indexed) {
  const std::size_t end = indexed.end_in(history.size());
  const std::size_t begin = std::min(indexed.begin, end);
  HistoryCarry h;
  h.index(std::span(pairs.id_first).subspan(begin, end - begin), std::span(pairs.id_second).subspan(begin, end - begin),
          history.subspan(begin, end - begin), max_id);
  return h;
}

HistoryCarry index_wall_history(const WallContacts& walls, std::int64_t max_id) {
  HistoryCarry h;
  const std::vector<std::int64_t> wall_key(walls.wall.begin(), walls.wall.end());
  h.index(walls.disc_id, wall_key, walls.xi, max_id);
  return h;
}

void set_pair_ids(PairContacts& pairs, const NeighborList& L, const Discs& d) {
  const auto n = static_cast<std::ptrdiff_t>(L.size());
  pairs.id_first.resize(L.size());
  pairs.id_second.resize(L.size());
#pragma omp parallel for schedule(static) if (static_cast<std::ptrdiff_t>(d.size()) > min_parallel_items())
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    pairs.id_first[p] = d.id[L.first[p]];
    pairs.id_second[p] = d.id[L.second[p]];
  }
}

namespace {
// history[p] for the pairs of `carried`: what `old` holds under the pair's ids.
void carry_range(const PairContacts& pairs, std::vector<double>& history, const HistoryCarry& old, PairRange carried) {
  const auto end = static_cast<std::ptrdiff_t>(carried.end_in(history.size()));
  const auto begin = std::min(static_cast<std::ptrdiff_t>(carried.begin), end);
#pragma omp parallel for schedule(static) if (end - begin > min_parallel_items())
  for (std::ptrdiff_t p = begin; p < end; ++p) history[p] = old.find(pairs.id_first[p], pairs.id_second[p]);
}
}  // namespace

void carry_pair_history(PairContacts& pairs, const HistoryCarry& old, PairRange carried) {
  pairs.xi.assign(pairs.id_first.size(), 0.0);  // the list's size: its ids are set
  carry_range(pairs, pairs.xi, old, carried);
}

void carry_rolling_history(PairContacts& pairs, const HistoryCarry& old, PairRange carried) {
  pairs.roll.assign(pairs.id_first.size(), 0.0);
  carry_range(pairs, pairs.roll, old, carried);
}

void carry_wall_history(WallContacts& wc, const HistoryCarry& old) {
  wc.xi.resize(wc.size());
  for (std::size_t k = 0; k < wc.size(); ++k) wc.xi[k] = old.find(wc.disc_id[k], static_cast<std::int64_t>(wc.wall[k]));
}

}  // namespace orogen
