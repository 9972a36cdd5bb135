#pragma once
// How one step's work is cut between the threads of a team. Thread t sums the forces of
// chunks [chunk[t], chunk[t+1]) (those of each parity in turn), and updates discs
// [disc[t], disc[t+1]) and bodies [body[t], body[t+1]): contiguous stretches of the domain,
// so that a thread integrates mostly the discs whose forces it has just summed and whose
// positions it will read next, and they stay in its own core's cache. (With the chunks
// handed out first come, first served and the discs cut in equal halves, two threads at 20k
// discs spent four times as long per disc in the integration as one thread, moving forces
// and positions between the cores.) Any split gives the same results: it only decides who
// does what.
#include <cstddef>
#include <vector>

#include "contact/neighbor_list.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

struct ThreadSplit {
  std::vector<std::ptrdiff_t> chunk, disc, body;  // threads + 1 boundaries each
  int threads() const { return static_cast<int>(chunk.size()) - 1; }
};

// Chunks cut by their number of pairs (equal shares of the force loop); discs where the chunks
// are cut (NeighborList::chunk_disc), or in equal shares without that hint; bodies where
// their discs are cut.
ThreadSplit split_threads(const NeighborList& list, const Discs& discs, const Clusters& clusters, int threads);

// Share `r` of `cut` cut again into `threads` shares (the threads of one rank of a run over
// ranks): its chunks by their pairs, its discs and bodies in equal parts. The sums keep their
// order for any cut (chunks two apart share no disc), so the bits are those of `cut`.
ThreadSplit split_share(const ThreadSplit& cut, std::size_t r, int threads, const NeighborList& list);

// The threads a step's loops use: all of them from kMinParallelItems discs on, else one.
int step_threads(std::size_t discs);

}  // namespace orogen
