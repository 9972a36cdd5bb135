#pragma once
// Disc-disc contact forces over the Verlet list.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/thread_split.hpp"
#include "particles/disc_force.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Per-step scratch of the force stages: the force and torque summed on each disc (by disc
// index), which integration then uses and zeroes (all zero between steps, so a re-ordered,
// grown or compacted array needs no clearing), and the threads' cut of the step, made once
// per neighbour-list build (it depends on the list, the disc and body counts alone).
struct PairScratch {
  std::vector<DiscForce> forces;
  ThreadSplit split;
  std::uint64_t split_build = ~std::uint64_t{0};  // the list build the cut was made for
};

// The coefficients of this step in a world of named materials; nullptr: the law's for every
// pair. `friction`, by disc: a pair slides at the weaker of its two, and the slip of each contact
// on the Coulomb limit is added to both discs' Discs::slip. `rolling`, by material (`material`:
// each disc's): a pair resists rolling with the weaker of its two discs' materials (read only
// while the store keeps rolling histories, PairContacts::roll; with none, no contact resists
// rolling).
struct DiscCoefficients {
  const double* friction = nullptr;
  const std::uint8_t* material = nullptr;
  const double* rolling = nullptr;
};

// `disc`: see DiscCoefficients.
// Sets the forces to the sum of the discs' contact forces, chunk by chunk (see
// NeighborList::chunk_start), the chunks and discs cut between the threads of a team by `split`:
// bitwise the same result for any number of threads and any split. Every thread t of the team
// (World::step_stages) calls it, `forces` already sized to the discs and zero (integration
// leaves them so); it sums its even chunks, then its odd ones, with the team's barriers
// between (so the forces are whole when it returns).
void pair_forces_share(const NeighborList& list, PairContacts& contacts, Discs& discs, const ContactLaw& law,
                       const DiscCoefficients& disc, double dt, DiscForce* forces, const ThreadSplit& split,
                       std::size_t t);

// One parity of share t's chunks (0: the even ones, 1: the odd ones), added onto `forces`, with
// no barrier: for a step whose parities run apart, with an exchange between them (ranks that
// hold copies of the world, parallel/rank_step.hpp). Even then odd gives pair_forces_share's bits.
void pair_forces_parity(const NeighborList& list, PairContacts& contacts, Discs& discs, const ContactLaw& law,
                        const DiscCoefficients& disc, double dt, DiscForce* forces, const ThreadSplit& split,
                        std::size_t t, int parity);

}  // namespace orogen
