#pragma once
// One rank's time step in a run cut between ranks that each hold a copy of the World and talk
// only through a RankTransport (docs/domain-decomposition.md). The step is World::advance's,
// cut into phases at the places where a thread of one process would read what another wrote;
// each phase first computes and sends (post), then receives (take). Every floating-point
// operation then has the operands, and the order, of one process: the same bits.
//   Build        a stale list: every rank's positions (and bonds' state) to every rank (where the
//                copy was whole already, a stage gathered it, no exchange); each copy bins and
//                sorts the discs as one process
//   Search       each rank searches its range of the list's chunks (cut by the discs in them)
//                and sends every rank each chunk's counts; every copy makes the list's shape
//                (the other ranks' pairs placeholders) and from it the new cut
//   Lists        the pairs a rank searched in chunks the cut gives another rank, to that rank;
//                each copy then holds its own chunks' pairs (make_whole gathers the rest),
//                finishes the build over them (histories carried into its own chunks alone) and
//                makes the plan from the stripes (stripe_ranks.hpp, exchange_plan.hpp)
//   Migration    after a build from positions: the motion, body state and contact histories each
//                rank kept current, to the rank that keeps them under the new plan (migration.hpp;
//                the pairs' histories from their old keeper alone, with a count: pair_migration.hpp)
//   Ghosts       the motion of the discs this rank reads but another moved
//   EvenPairs    the even chunks; their running sums to the odd chunk's rank
//   OddPairs     the odd chunks; whole pair sums to the wall owner of a disc on a wall
//   Walls        the wall forces of the disc range; whole sums to the integrating rank, which
//                then steps the bonds of the discs it integrates (a bond across the cut on both
//                sides, alike) and adds them in bond order; with a pin hook (StageHooks::Pin),
//                the bodies its discs pin, flagged to their integrating rank, which holds them
//                before it integrates
//   Integration  the free discs of the disc range and the bodies of the body range; the largest
//                displacement (and the discs pinned, the bonds broken) to every rank; the broken
//                bonds logged and removed in every copy; walls moved, the clock on
// Named materials: a disc's slip travels with its motion (ghosts) and, as a running sum, with
// its forces. Each phase runs on the OpenMP threads one process of the rank's size would use,
// cutting the rank's share again (split_share): the same bits for any thread count.
// Not yet: hooks inside the step other than pins (std::invalid_argument).
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "boundary/wall_forces.hpp"
#include "contact/pair_forces.hpp"
#include "parallel/exchange_plan.hpp"
#include "world/contact_rebuild.hpp"
#include "parallel/migration.hpp"
#include "parallel/pair_migration.hpp"
#include "parallel/rank_access.hpp"
#include "parallel/rank_transport.hpp"

namespace orogen {

enum class Phase : std::uint8_t { Build, Search, Lists, Migration, Ghosts, EvenPairs, OddPairs, Walls, Integration };
inline constexpr std::array<Phase, 9> kStepPhases = {Phase::Build,     Phase::Search,   Phase::Lists,
                                                     Phase::Migration, Phase::Ghosts,   Phase::EvenPairs,
                                                     Phase::OddPairs,  Phase::Walls,    Phase::Integration};

// std::invalid_argument naming what a step over ranks does not run yet (hooks inside the step
// other than a pin). Check the world given, not a copy: a copy drops its hooks.
void check_steppable_over_ranks(const World& world);

// The exchanges a test may drop, to show that the results then differ.
enum class Exchange : std::uint8_t { Ghosts, PartialSums, PairSums, WholeSums, Migration };

// How the step is cut into ranks after a build: split_threads with one share per rank unless
// given (tests give lopsided cuts).
using RankCut = std::function<ThreadSplit(const NeighborList&, const Discs&, const Clusters&, int ranks)>;

class RankStep {
 public:
  // `world` must be the same in every rank (a copy); std::invalid_argument if it has what a
  // step over ranks does not run yet.
  RankStep(World& world, RankTransport& transport, RankCut cut = {});

  void post(Phase phase);
  void take(Phase phase);
  // All phases in turn: a rank of its own (a transport whose sends do not wait).
  void advance();
  // Every rank's owned state into this copy (collective; nothing if it is whole already), so
  // that a stage between steps reads, and may change, the state of one process in each copy.
  void make_whole();
  // Every rank's disc and body positions into this copy (collective; nothing if it is whole),
  // which stays not whole: for a stage that reads positions only (World::gather_positions).
  void gather_positions();

  // What a run over ranks costs beyond its slab's work, for the log: the gathers of every
  // rank's state (its positions before list builds, the whole in make_whole), the doubles this
  // rank sent in them, the doubles it sent in migrations after builds, and the seconds it spent
  // in gathers and migrations and in the builds (the part every copy runs whole, its share of
  // the search), and the doubles it sent of its share of the list (pair indices) to the others.
  struct SerialWork {
    std::uint64_t gathers = 0, gathered_values = 0, builds = 0, migrated_values = 0;
    std::uint64_t position_gathers = 0;  // of them, gathers of the positions (and bonds) alone
    std::uint64_t list_values = 0;  // pairs this rank searched and another keeps (one value each)
    std::uint64_t searched_pairs = 0;  // pairs found in this rank's share of the searches
    double gather_seconds = 0, build_seconds = 0;
    double search_seconds = 0;  // of build_seconds, in this rank's share of the pair search
  };
  const SerialWork& serial_work() const { return serial_; }

  const ExchangePlan& plan() const { return plan_; }
  World& world() { return access_.world; }
  const World& world() const { return access_.world; }
  RankAccess& access() { return access_; }
  void drop_for_testing(Exchange e) { dropped_[static_cast<std::size_t>(e)] = true; }

 private:
  bool dropped(Exchange e) const { return dropped_[static_cast<std::size_t>(e)]; }
  void post_build();
  void take_build();
  // This rank's chunks of the list searched, their counts sent; every rank's counts joined into
  // the list's shape, the new cut made from it.
  void post_search();
  void take_search();
  void receive_search_counts(int from, std::span<ChunkPairs> chunks);  // as post_search sent them
  // The pairs this rank searched and another keeps under the new cut, sent; those it keeps and
  // another searched, received; the build finished, the plan made.
  void post_lists();
  void take_lists();
  std::pair<std::size_t, std::size_t> kept_part(int rank, std::int64_t begin, std::int64_t end) const;
  void make_plan();
  void send_migration();
  void receive_migration();
  // The pairs' histories that change keeper, sent and received.
  void send_leaving_pairs();
  void receive_arriving_pairs();
  // This rank's owned state to every other rank; theirs into this copy.
  void send_owned_state();
  void receive_owned_states();
  // This rank's chunks of the list to every other rank; theirs into this copy (make_whole).
  void send_list_pairs();
  void receive_list_pairs();
  // buffer_ to every other rank, counted as a gather (of the positions, or of the whole state).
  void send_gathered(bool positions);
  // buffer_ to every other rank, its values counted as gathered; from every other rank, a
  // buffer of `size` values given to `unpack` (the walks of owned_state.hpp).
  void send_to_others();
  using SizeOf = std::size_t (*)(RankAccess&, const ExchangePlan&, int);
  using Unpack = void (*)(RankAccess&, const ExchangePlan&, int, std::span<const double>);
  void receive_from_others(SizeOf size, Unpack unpack);
  // The discs' force sums along `routes`, out of this rank, or into it (set, not added).
  void send_sums(const Routes& routes);
  void receive_sums(const Routes& routes);
  // This rank's bonds stepped and added; the breaks every rank found applied in every copy.
  void step_bonds();
  void remove_broken_bonds();
  void integrate();
  void take_displacements();
  // Pin hooks: the discs of this rank's disc range that touch a pin's walls and are not yet
  // held, flagged to the ranks that integrate them; the flags received; all of them applied in
  // every copy after integration.
  bool has_pins() const { return access_.world.hooks().has_pins(); }
  void find_pins();
  void take_pin_flags();
  void hold(const std::vector<std::uint32_t>& discs, bool record);
  // The rank's share cut between its OpenMP threads, and a phase's work run on each of them.
  const ThreadSplit& thread_cut();
  void on_threads(const std::function<void(const ThreadSplit&, std::size_t)>& work);

  RankAccess access_;
  RankTransport* transport_;
  RankCut cut_;
  int rank_, ranks_;
  ExchangePlan plan_;
  bool whole_ = true;  // this copy holds every rank's current state (a fresh copy, gathered by a stage, or built from it)
  bool list_whole_ = true;  // its list holds every chunk's pairs (after a build over ranks: only this rank's)
  bool build_ = false;  // this step rebuilds the list
  bool migrate_ = false;  // ... from the positions alone: the state then migrates (migration.hpp)
  Migration migration_;
  PreviousKeepers keepers_;
  KeptPairs kept_pairs_;
  std::vector<std::vector<double>> leaving_pairs_;  // by rank
  bool rolling_pairs_ = false;  // the pairs' histories include rolling ones
  PendingBuild pending_;
  std::vector<std::int64_t> search_ranges_;  // each rank's chunks of the search: ranks + 1 bounds
  std::vector<ChunkPairs> searched_;
  ThreadSplit build_cut_;  // the cut made at this step's build
  double max2_ = 0;
  double not_finite_ = 0;
  ThreadSplit threads_cut_;
  std::uint64_t threads_cut_build_ = 0;
  int threads_cut_ranks_ = 0;
  std::vector<double> buffer_;
  // This step's pinned discs: found as wall owner, held as integrator, and those of every rank.
  std::vector<std::uint32_t> pins_found_, pins_held_, pins_all_;
  // This step's contact coefficients (World::prepare_contact_coefficients), bonds and breaks.
  DiscCoefficients coefficients_;
  WallSlip wall_slip_;
  bool has_bonds_ = false;
  std::vector<std::uint32_t> my_bonds_;
  struct FoundBreak {
    std::uint32_t bond;
    double x, y, mode;
  };
  std::vector<FoundBreak> breaks_found_, breaks_all_;
  std::array<bool, 5> dropped_{};
  SerialWork serial_;
};

}  // namespace orogen
