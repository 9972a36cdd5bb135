#pragma once
// The state of the contacts, kept apart from the neighbour search: per candidate pair and per
// disc-wall contact, the tangential spring history, the normal dashpot, and for walls the
// touching and at-limit flags of the last force pass. The force stages read and write it; the
// list build (world/contact_rebuild.cpp) sizes it to the new candidates and carries the
// histories over by stable ids. Experiments and analyses read it through the small API at
// the end (World forwards it), never by its arrays.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/neighbor_list.hpp"

namespace orogen {

// Entry p belongs to the list's candidate pair p (NeighborList::first/second).
struct PairContacts {
  std::vector<std::int64_t> id_first, id_second;  // stable ids: the key the history is carried by
  std::vector<double> xi;                         // tangential spring history
  std::vector<double> gamma_n;                    // normal dashpot coefficient
  // Rolling spring history (relative rotation) while some contact resists rolling
  // (ContactLaw::rolling_friction, Material::rolling_friction); empty otherwise.
  std::vector<double> roll;
  std::size_t size() const { return xi.size(); }
};

// Discs within the skin of an enabled wall, in wall then disc order.
struct WallContacts {
  std::vector<std::uint32_t> wall, disc;
  std::vector<std::int64_t> disc_id;   // stable id of the disc: the history's key with the wall
  std::vector<double> xi;
  std::vector<double> gamma_n;         // normal dashpot coefficient of the contact
  std::vector<double> traction_mass;   // what a traction wall's drag steps against (boundary/traction_mass.hpp)
  std::vector<std::uint8_t> touching;  // whether the disc touched the wall in the last force pass
  std::vector<std::uint8_t> at_limit;  // whether the tangential force sat on the Coulomb limit
  void clear() {
    wall.clear(); disc.clear(); disc_id.clear(); xi.clear(); gamma_n.clear(); traction_mass.clear();
    touching.clear(); at_limit.clear();
  }
  std::size_t size() const { return disc.size(); }
};

struct ContactStore {
  PairContacts pairs;
  WallContacts walls;
};

// --- The read API ---

// One candidate pair as the force stage sees it (indices of the pass, the discs' stable ids:
// after a removal the indices may name other discs until the next build, history, dashpot).
struct PairContactView {
  std::uint32_t first, second;
  std::int64_t id_first, id_second;
  double xi, gamma_n;
};

// One disc-wall contact of the last force pass.
struct WallContactView {
  std::uint32_t wall, disc;
  double xi, gamma_n, traction_mass;
  bool touching, at_limit;
};

// Touching contacts of one wall in the last force pass, and how many of them slid (at the
// Coulomb limit).
struct WallContactStats {
  std::size_t touching = 0, at_limit = 0;
  double slip_fraction() const { return touching ? static_cast<double>(at_limit) / static_cast<double>(touching) : 0.0; }
};

// Calls f(PairContactView) for each candidate pair, in list order.
template <class F>
void for_each_pair_contact(const NeighborList& list, const ContactStore& store, F&& f) {
  for (std::size_t p = 0; p < list.size(); ++p)
    f(PairContactView{list.first[p], list.second[p], store.pairs.id_first[p], store.pairs.id_second[p],
                      store.pairs.xi[p], store.pairs.gamma_n[p]});
}

// Calls f(WallContactView) for each disc-wall contact, in wall then disc order.
template <class F>
void for_each_wall_contact(const ContactStore& store, F&& f) {
  const auto& wc = store.walls;
  for (std::size_t k = 0; k < wc.size(); ++k)
    f(WallContactView{wc.wall[k], wc.disc[k], wc.xi[k], wc.gamma_n[k], wc.traction_mass[k], wc.touching[k] != 0,
                      wc.at_limit[k] != 0});
}

WallContactStats wall_contact_stats(const ContactStore& store, std::size_t wall);

}  // namespace orogen
