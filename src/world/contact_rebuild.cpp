#include "world/contact_rebuild.hpp"

#include <algorithm>

#include "boundary/traction_mass.hpp"
#include "boundary/wall_contact_search.hpp"
#include "contact/cell_grid.hpp"
#include "contact/chunk_hints.hpp"
#include "contact/contact_damping.hpp"
#include "contact/disc_scan.hpp"
#include "contact/store_carry.hpp"
#include "world/reference_positions.hpp"

namespace orogen {

PendingBuild begin_rebuild(const NeighborList& L, const ContactStore& store, Discs& d, Clusters& c, bool sort,
                           PairRange indexed) {
  PendingBuild build;
  const DiscScan scan = scan_discs(d);
  if (!scan.finite) {
    build.finite = false;
    return build;
  }
  // Index the old histories by stable ids before indices change.
  const std::int64_t max_id = std::max(scan.max_id, max_stored_id(store));
  build.pair_history = index_pair_history(store.pairs, store.pairs.xi, max_id, indexed);
  build.wall_history = index_wall_history(store.walls, max_id);
  build.rolling = !store.pairs.roll.empty();  // kept only while some contact resists rolling
  if (build.rolling) build.rolling_history = index_pair_history(store.pairs, store.pairs.roll, max_id, indexed);

  build.bins = bin_discs(d, make_grid(d, 2.0 * scan.r_max + L.skin));
  build.sort = sort;
  if (sort) sort_discs_by_cell(build.bins, d, c);
  return build;
}

void take_found_pairs(PendingBuild& build, const PairSearchResult& search, NeighborList& L) {
  build.search = search;
  set_chunk_hints(L, search, build.bins);
}

BuildStats finish_rebuild(PendingBuild& build, NeighborList& L, ContactStore& store, Discs& d, Clusters& c,
                          const std::vector<Wall>& walls, const ContactLaw& law, double dt, PairRange carried) {
  set_pair_ids(store.pairs, L, d);
  carry_pair_history(store.pairs, build.pair_history, carried);
  if (build.rolling) carry_rolling_history(store.pairs, build.rolling_history, carried);
  prepare_damping(law, d, c, dt);  // the damping table is filled serially, read in parallel
  set_pair_damping(store.pairs, L, d, c, law, dt);

  search_wall_contacts(store.walls, d, walls, L.skin);
  carry_wall_history(store.walls, build.wall_history);
  set_wall_damping(store.walls, d, c, law, dt);
  set_traction_mass(store.walls, d, c, walls);

  record_reference_positions(L, d, walls);
  ++L.builds;
  L.valid = true;
  return build.search.stats;
}

BuildStats rebuild_contacts(NeighborList& L, ContactStore& store, Discs& d, Clusters& c,
                            const std::vector<Wall>& walls, const ContactLaw& law, double dt, bool sort) {
  PendingBuild build = begin_rebuild(L, store, d, c, sort);
  if (!build.finite) {
    BuildStats stats;
    stats.finite = false;
    return stats;
  }
  take_found_pairs(build, search_pairs(L, build.bins, d), L);
  return finish_rebuild(build, L, store, d, c, walls, law, dt);
}

bool contacts_stale(const NeighborList& L, const Discs& d, const std::vector<Wall>& walls, double moved) {
  const bool list_matches = L.valid && L.x_ref.size() == d.size();
  return !list_matches || moved + wall_displacement(L, walls) > 0.5 * L.skin;
}

}  // namespace orogen
