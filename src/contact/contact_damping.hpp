#pragma once
// The normal dashpot of each contact, set at the list build from the masses that resist it
// (ContactLaw::gamma_n). One job: damping coefficients of the contact store.
#include <cstdint>

#include "contact/contact_law.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Mass that resists a contact on disc i: its body's mass, infinite for kinematic discs.
double resisting_mass(const Discs& discs, const Clusters& clusters, std::uint32_t i);

// Fills the law's damping table for every pair and wall mass these discs can produce, so that
// the parallel passes below only read it. Call before them.
void prepare_damping(const ContactLaw& law, const Discs& discs, const Clusters& clusters, double dt);

// gamma_n of every candidate pair of the list, from the pair's effective mass.
void set_pair_damping(PairContacts& pairs, const NeighborList& list, const Discs& discs, const Clusters& clusters,
                      const ContactLaw& law, double dt);

// gamma_n of every wall contact, from the mass of the disc's body.
void set_wall_damping(WallContacts& walls, const Discs& discs, const Clusters& clusters, const ContactLaw& law,
                      double dt);

}  // namespace orogen
