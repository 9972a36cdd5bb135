// One run's step over real MPI ranks (parallel/mpi_rank.hpp, docs/domain-decomposition.md step 2),
// every bit as the step of one process. Run under mpiexec -n K (K = 1, 2, 3; CMakeLists.txt
// registers each): every rank builds the same world as tests/test_emulated_ranks.cpp's, steps its
// copy over MPI (cut by split_threads, and for 2 and 3 ranks also by the emulation test's
// lopsided cut), and at every 25th step rank 0 gathers the whole state and compares it, memcmp,
// with the same world stepped by one process in rank 0 (discs' motion and order, clusters, pair
// and wall contact histories, walls, clock, list builds). Then the transport itself: a buffer of
// another size than expected is refused with a message, and buffers arrive in the order sent.
// A plain program: exit 0 on every rank if all holds, else 1 (mpiexec then fails).
#include <mpi.h>

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "parallel/mpi_rank.hpp"
#include "ranks_world.hpp"

namespace orogen {
namespace {

int failures = 0;

void fail(int rank, const std::string& what) {
  std::fprintf(stderr, "rank %d: FAILED: %s\n", rank, what.c_str());
  ++failures;
}

// The step over MPI against one process, `steps` steps compared every `every`.
void same_run_as_one_process(int steps, int every, RankCut cut = {}, const char* how = "split_threads") {
  const World start = testing::mixed_heap();
  MpiRank mine(start, std::move(cut));
  const int rank = mine.rank();
  std::optional<World> one;
  if (rank == 0) one.emplace(start);
  const std::uint64_t builds = start.neighbors().builds;
  int compared = 0;
  bool differs = false;  // every rank goes on to the end: a rank that left would leave the others waiting
  for (int s = 1; s <= steps; ++s) {
    mine.advance();
    if (one) one->advance();
    if (s % every != 0) continue;
    std::optional<World> whole = mine.gathered();  // every rank takes part
    if (rank != 0 || differs) continue;
    ++compared;
    if (!whole || !testing::same_bits(testing::state_of(*whole), testing::state_of(*one))) {
      fail(rank, "the gathered state differs from one process's at step " + std::to_string(s));
      differs = true;
    }
  }
  if (rank == 0) {
    const std::uint64_t rebuilt = one->neighbors().builds - builds;
    if (rebuilt < 4) fail(rank, "the run rebuilt its list only " + std::to_string(rebuilt) + " times");
    if (!differs)
      std::printf("%d ranks cut by %s: %d steps, %llu list builds (a sort every second), the gathered state "
                  "equal to one process's at each of %d comparisons\n",
                  mine.ranks(), how, steps, static_cast<unsigned long long>(rebuilt), compared);
  }
}

// The transport alone: order kept, another size refused (the buffer then read at its size).
void transport_keeps_order_and_sizes() {
  MpiTransport t;
  if (t.ranks() < 2) return;
  const int rank = t.rank();
  if (rank == 1) {
    for (int k = 0; k < 50; ++k) t.send(0, std::vector<double>(static_cast<std::size_t>(k % 7), k));
    t.send(0, std::vector<double>{1.0, 2.0, 3.0});
    t.flush();
  } else if (rank == 0) {
    for (int k = 0; k < 50; ++k) {
      std::vector<double> v(static_cast<std::size_t>(k % 7));
      t.receive(1, v);
      for (const double x : v)
        if (x != k) fail(rank, "buffer " + std::to_string(k) + " arrived out of order");
    }
    std::vector<double> two(2), three(3);
    try {
      t.receive(1, two);
      fail(rank, "a buffer of 3 values was taken into 2");
    } catch (const std::logic_error& e) {
      const std::string msg = e.what();
      if (msg.find("expects 2 values from rank 1, which sent 3") == std::string::npos)
        fail(rank, "unclear message: " + msg);
    }
    t.receive(1, three);  // still there, unread
    if (three != std::vector<double>{1.0, 2.0, 3.0}) fail(rank, "the refused buffer was lost or changed");
  }
}

}  // namespace
}  // namespace orogen

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  try {
    orogen::same_run_as_one_process(300, 25);
    // Cuts far from split_threads', so that every exchange carries something (2 and 3 ranks).
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (ranks == 2 || ranks == 3) orogen::same_run_as_one_process(300, 25, orogen::testing::lopsided_cut, "lopsided_cut");
    orogen::transport_keeps_order_and_sizes();
  } catch (const std::exception& e) {
    orogen::fail(rank, std::string("exception: ") + e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);  // the other ranks may wait for this one forever
  }
  int mine = orogen::failures, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Finalize();
  if (rank == 0) std::printf(all == 0 ? "PASSED\n" : "FAILED (%d)\n", all);
  return all == 0 ? 0 : 1;
}
