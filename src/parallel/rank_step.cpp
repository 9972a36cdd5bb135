#include "parallel/rank_step.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "boundary/wall_forces.hpp"
#include "contact/pair_forces.hpp"
#include "integrate/integrator.hpp"
#include "parallel/owned_state.hpp"
#include "parallel/packed_pair.hpp"
#include "parallel/stripe_ranks.hpp"
#include "util/soa.hpp"

namespace orogen {
namespace {

constexpr std::size_t kBreakValues = 4;  // bond index, midpoint x and y, mode
constexpr std::size_t kChunkHeader = 5;  // a searched chunk's pairs that touch, apart, worst overlap and its discs

// A ghost: x, y, vx, vy, omega (what the force phases read); a sum: fx, fy, torque. In a world
// of materials both carry the disc's slip too (its friction in the step; a running sum).
std::size_t ghost_values(const Discs& d) { return d.has_materials ? 6 : 5; }
std::size_t sum_values(const Discs& d) { return d.has_materials ? 4 : 3; }

// Adds the seconds from its construction to its end to `total` (timing for the log only).
class Stopwatch {
 public:
  explicit Stopwatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

void check_steppable_over_ranks(const World& world) {
  if (!world.hooks().only_pins(Stage::AfterForces) || !world.hooks().empty(Stage::AfterIntegration) ||
      world.hooks().pins().size() > 1)
    throw std::invalid_argument(
        "a step over ranks does not run hooks inside the step (other than one pin: the constant-velocity "
        "base's) yet (docs/domain-decomposition.md)");
}

RankStep::RankStep(World& world, RankTransport& transport, RankCut cut)
    : access_(world), transport_(&transport), cut_(std::move(cut)), rank_(transport.rank()),
      ranks_(transport.ranks()) {
  check_steppable_over_ranks(access_.world);
  if (!cut_)
    cut_ = [](const NeighborList& L, const Discs& d, const Clusters& c, int ranks) {
      return split_threads(L, d, c, ranks);
    };
}

void RankStep::advance() {
  for (const Phase phase : kStepPhases) {
    post(phase);
    take(phase);
  }
}

void RankStep::post(Phase phase) {
  DiscForce* forces = access_.forces.data();
  switch (phase) {
    case Phase::Build:
      post_build();
      break;
    case Phase::Search:
      post_search();
      break;
    case Phase::Lists:
      post_lists();
      break;
    case Phase::Migration:
      if (migrate_ && !dropped(Exchange::Migration)) {
        send_migration();
        send_leaving_pairs();
      }
      break;
    case Phase::Ghosts:
      if (dropped(Exchange::Ghosts)) break;
      for (int q = 0; q < ranks_; ++q) {
        const auto& discs = plan_.ghosts(rank_, q);
        if (q == rank_ || discs.empty()) continue;
        const Discs& d = access_.discs;
        buffer_.clear();
        for (const auto i : discs) {
          buffer_.insert(buffer_.end(), {d.x[i], d.y[i], d.vx[i], d.vy[i], d.omega[i]});
          if (d.has_materials) buffer_.push_back(d.slip[i]);  // its friction in this step, its running slip
        }
        transport_->send(q, buffer_);
      }
      break;
    case Phase::EvenPairs:
    case Phase::OddPairs: {
      const int parity = phase == Phase::EvenPairs ? 0 : 1;
      if (parity == 0) {  // the discs this rank reads are current: their friction from their slip
        coefficients_ = {};
        wall_slip_ = {};
        access_.prepare_contact_coefficients(coefficients_, wall_slip_);
      }
      on_threads([&](const ThreadSplit& threads, std::size_t t) {
        pair_forces_parity(access_.neighbors, access_.contacts.pairs, access_.discs, access_.law, coefficients_,
                           access_.dt, forces, threads, t, parity);
      });
      if (parity == 0 && !dropped(Exchange::PartialSums)) send_sums(plan_.partial_sums);
      if (parity == 1 && !dropped(Exchange::PairSums)) send_sums(plan_.pair_sums);
      break;
    }
    case Phase::Walls:
      on_threads([&](const ThreadSplit& threads, std::size_t t) {
        wall_forces_share(access_.contacts.walls, access_.discs, access_.walls, access_.law, access_.dt, wall_slip_,
                          forces, threads, t);
      });
      if (!dropped(Exchange::WholeSums)) send_sums(plan_.whole_sums);
      if (has_pins()) find_pins();
      break;
    case Phase::Integration:
      integrate();
      break;
  }
}

void RankStep::take(Phase phase) {
  switch (phase) {
    case Phase::Build:
      take_build();
      break;
    case Phase::Search:
      take_search();
      break;
    case Phase::Lists:
      take_lists();
      break;
    case Phase::Migration:
      if (migrate_ && !dropped(Exchange::Migration)) {
        receive_migration();
        receive_arriving_pairs();
      }
      break;
    case Phase::Ghosts:
      if (dropped(Exchange::Ghosts)) break;
      for (int q = 0; q < ranks_; ++q) {
        const auto& discs = plan_.ghosts(q, rank_);
        if (q == rank_ || discs.empty()) continue;
        Discs& d = access_.discs;
        const std::size_t values = ghost_values(d);
        buffer_.resize(values * discs.size());
        transport_->receive(q, buffer_);
        const double* v = buffer_.data();
        for (const auto i : discs) {
          d.x[i] = v[0]; d.y[i] = v[1]; d.vx[i] = v[2]; d.vy[i] = v[3]; d.omega[i] = v[4];
          if (d.has_materials) d.slip[i] = v[5];
          v += values;
        }
      }
      break;
    case Phase::EvenPairs:
      if (!dropped(Exchange::PartialSums)) receive_sums(plan_.partial_sums);
      break;
    case Phase::OddPairs:
      if (!dropped(Exchange::PairSums)) receive_sums(plan_.pair_sums);
      break;
    case Phase::Walls:
      if (!dropped(Exchange::WholeSums)) receive_sums(plan_.whole_sums);
      step_bonds();  // on the whole sums, and before a pin holds a body (one process: bonds, then hooks)
      if (has_pins()) take_pin_flags();
      break;
    case Phase::Integration:
      take_displacements();
      break;
  }
}

void RankStep::post_build() {
  check_steppable_over_ranks(access_.world);
  // Every copy decides alike: the largest displacement was reduced over the ranks.
  build_ = access_.world.contacts_stale();
  // A copy made whole by a stage builds from its own state; otherwise the build reads every
  // rank's positions (and bonds), and the rest of the state migrates after it.
  migrate_ = build_ && !whole_;
  if (migrate_) {
    Stopwatch watch(serial_.gather_seconds);
    buffer_.clear();
    pack_build_state(access_, plan_, rank_, buffer_);
    send_gathered(true);
  }
}

void RankStep::take_build() {
  if (migrate_) {
    Stopwatch watch(serial_.gather_seconds);
    for (int q = 0; q < ranks_; ++q) {
      if (q == rank_) continue;
      buffer_.resize(build_state_size(access_, plan_, q));
      transport_->receive(q, buffer_);
      unpack_build_state(access_, plan_, q, buffer_);
    }
    keepers_ = record_keepers(access_, plan_);  // before the build re-orders what they name
    kept_pairs_ = record_kept_pairs(access_, rank_pairs(access_.neighbors, plan_.cut, rank_));
  }
  if (build_) {
    // Every copy bins and sorts as one process: what that reads (the positions, the radii) is
    // current in every copy. The search is cut by the discs in each chunk, alike in every copy.
    // Without the whole state a copy indexes only the histories of the pairs it kept.
    Stopwatch watch(serial_.build_seconds);
    access_.begin_list_build(pending_, migrate_ ? rank_pairs(access_.neighbors, plan_.cut, rank_) : PairRange{});
    search_ranges_ = chunk_ranges_by_discs(pending_.bins, ranks_);
  }
}

void RankStep::post_search() {
  if (!build_) return;
  {
    Stopwatch watch(serial_.build_seconds), search(serial_.search_seconds);
    const auto r = static_cast<std::size_t>(rank_);
    searched_ = search_pair_chunks(pending_.bins, access_.discs, access_.neighbors.skin, search_ranges_[r],
                                   search_ranges_[r + 1]);
    for (const ChunkPairs& c : searched_) serial_.searched_pairs += c.first.size() + c.apart_first.size();
  }
  if (ranks_ == 1 || searched_.empty()) return;
  // Every rank learns each chunk's counts and worst overlap; the pairs go only where the cut
  // after the search puts their chunk (the Lists phase).
  buffer_.clear();
  for (const ChunkPairs& c : searched_)
    buffer_.insert(buffer_.end(), {static_cast<double>(c.first.size()), static_cast<double>(c.apart_first.size()),
                                   c.stats.max_overlap_ratio, static_cast<double>(c.stats.worst_a),
                                   static_cast<double>(c.stats.worst_b)});
  for (int q = 0; q < ranks_; ++q)
    if (q != rank_) transport_->send(q, buffer_);
}

void RankStep::take_search() {
  if (!build_) return;
  Stopwatch watch(serial_.build_seconds);
  // The list of one process in its shape: this rank's chunks searched, the others' pairs
  // placeholders (disc 0 with itself, a pair no search lists) until the Lists phase brings the
  // ones this rank keeps. The cut follows from the shape alone.
  std::vector<ChunkPairs> all(static_cast<std::size_t>(search_ranges_.back()));
  for (int q = 0; q < ranks_; ++q) {
    const auto begin = static_cast<std::size_t>(search_ranges_[static_cast<std::size_t>(q)]);
    const auto end = static_cast<std::size_t>(search_ranges_[static_cast<std::size_t>(q) + 1]);
    if (q == rank_)
      std::move(searched_.begin(), searched_.end(), all.begin() + static_cast<std::ptrdiff_t>(begin));
    else if (begin < end)
      receive_search_counts(q, std::span(all).subspan(begin, end - begin));
  }
  searched_ = {};
  access_.join_list_build(pending_, all);
  build_cut_ = cut_(access_.neighbors, access_.discs, access_.clusters, ranks_);
  if (build_cut_.threads() != ranks_) throw std::logic_error("a rank cut with another number of shares than ranks");
}

void RankStep::receive_search_counts(int q, std::span<ChunkPairs> chunks) {
  buffer_.resize(kChunkHeader * chunks.size());
  transport_->receive(q, buffer_);
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const double* h = buffer_.data() + kChunkHeader * k;
    ChunkPairs& c = chunks[k];
    c.first.assign(static_cast<std::size_t>(h[0]), 0);
    c.second.assign(c.first.size(), 0);
    c.apart_first.assign(static_cast<std::size_t>(h[1]), 0);
    c.apart_second.assign(c.apart_first.size(), 0);
    c.stats.max_overlap_ratio = h[2];
    c.stats.worst_a = static_cast<std::uint32_t>(h[3]);
    c.stats.worst_b = static_cast<std::uint32_t>(h[4]);
  }
}

// The chunks of [begin, end) that rank `q` keeps under the cut made after the search.
std::pair<std::size_t, std::size_t> RankStep::kept_part(int q, std::int64_t begin, std::int64_t end) const {
  const auto r = static_cast<std::size_t>(q);
  const auto lo = std::max<std::int64_t>(begin, build_cut_.chunk[r]);
  const auto hi = std::min<std::int64_t>(end, build_cut_.chunk[r + 1]);
  return {static_cast<std::size_t>(lo), static_cast<std::size_t>(std::max(lo, hi))};
}

void RankStep::post_lists() {
  if (!build_ || ranks_ == 1) return;
  if (access_.discs.size() >= kPackedPairLimit) throw std::logic_error("too many discs to send a pair as one double");
  const NeighborList& L = access_.neighbors;
  const auto r = static_cast<std::size_t>(rank_);
  for (int q = 0; q < ranks_; ++q) {
    if (q == rank_) continue;
    const auto [k0, k1] = kept_part(q, search_ranges_[r], search_ranges_[r + 1]);
    if (k0 == k1 || L.chunk_start[k0] == L.chunk_start[k1]) continue;
    buffer_.clear();
    for (std::size_t p = L.chunk_start[k0]; p < L.chunk_start[k1]; ++p)
      buffer_.push_back(pack_pair(L.first[p], L.second[p]));
    transport_->send(q, buffer_);
    serial_.list_values += buffer_.size();
  }
}

void RankStep::take_lists() {
  if (build_) {
    Stopwatch watch(serial_.build_seconds);
    NeighborList& L = access_.list();
    for (int q = 0; q < ranks_; ++q) {
      if (q == rank_) continue;
      const auto [k0, k1] = kept_part(rank_, search_ranges_[static_cast<std::size_t>(q)],
                                      search_ranges_[static_cast<std::size_t>(q) + 1]);
      if (k0 == k1 || L.chunk_start[k0] == L.chunk_start[k1]) continue;
      buffer_.resize(L.chunk_start[k1] - L.chunk_start[k0]);
      transport_->receive(q, buffer_);
      std::size_t p = L.chunk_start[k0];
      for (const double packed : buffer_) { unpack_pair(packed, L.first[p], L.second[p]); ++p; }
    }
    // The histories: the old ones this rank kept (all, in a copy made whole by a stage) into
    // its chunks of the new list.
    access_.finish_list_build(pending_, rank_pairs(L, build_cut_, rank_));
    list_whole_ = ranks_ == 1;
    ++serial_.builds;
  }
  // The bonds re-ordered (after a build, or new bonds): their routes too.
  const bool bonds_moved = access_.prepare_bonds();
  if (plan_.ranks == 0 || plan_.build != access_.neighbors.builds || bonds_moved) make_plan();
  if (migrate_) {
    Stopwatch watch(serial_.gather_seconds);
    migration_ = find_migration(access_, keepers_, plan_);
    leaving_pairs_ = pack_leaving_pairs(kept_pairs_, pending_.bins.grid, plan_.cut, rank_);
    rolling_pairs_ = pending_.rolling;  // alike in every copy, as what the senders recorded
  }
  pending_ = {};
  keepers_ = {};
  kept_pairs_ = {};
  access_.forces.resize(access_.discs.size());  // zero between steps (take_displacements)
}

void RankStep::send_migration() {
  Stopwatch watch(serial_.gather_seconds);
  const auto out = pack_migration(access_, migration_, plan_, rank_);
  for (int q = 0; q < ranks_; ++q) {
    const auto& values = out[static_cast<std::size_t>(q)];
    if (q == rank_ || values.empty()) continue;
    transport_->send(q, values);
    serial_.migrated_values += values.size();
  }
}

void RankStep::receive_migration() {
  Stopwatch watch(serial_.gather_seconds);
  const auto sizes = migration_sizes(access_, migration_, plan_, rank_);
  std::vector<std::vector<double>> received(static_cast<std::size_t>(ranks_));
  for (int q = 0; q < ranks_; ++q) {
    auto& values = received[static_cast<std::size_t>(q)];
    values.resize(sizes[static_cast<std::size_t>(q)]);
    if (q != rank_ && !values.empty()) transport_->receive(q, values);
  }
  unpack_migration(access_, migration_, plan_, rank_, received);
}

void RankStep::send_leaving_pairs() {
  Stopwatch watch(serial_.gather_seconds);
  const std::size_t per = leaving_pair_values(rolling_pairs_);
  for (int q = 0; q < ranks_; ++q) {
    if (q == rank_) continue;
    const auto& values = leaving_pairs_[static_cast<std::size_t>(q)];
    const double count = static_cast<double>(values.size() / per);
    transport_->send(q, std::span(&count, 1));
    if (!values.empty()) transport_->send(q, values);
    serial_.migrated_values += 1 + values.size();
  }
  leaving_pairs_ = {};
}

void RankStep::receive_arriving_pairs() {
  Stopwatch watch(serial_.gather_seconds);
  PairContacts& pairs = access_.contacts.pairs;
  const bool rolling = rolling_pairs_;
  std::vector<std::vector<double>> received(static_cast<std::size_t>(ranks_));
  for (int q = 0; q < ranks_; ++q) {
    if (q == rank_) continue;
    double count = 0;
    transport_->receive(q, std::span(&count, 1));
    auto& values = received[static_cast<std::size_t>(q)];
    values.resize(static_cast<std::size_t>(count) * leaving_pair_values(rolling));
    if (!values.empty()) transport_->receive(q, values);
  }
  unpack_arriving_pairs(pairs, rank_pairs(access_.neighbors, plan_.cut, rank_), received, rolling);
}

void RankStep::make_whole() {
  if (whole_) return;
  Stopwatch watch(serial_.gather_seconds);
  send_owned_state();
  if (!list_whole_) send_list_pairs();
  receive_owned_states();
  if (!list_whole_) receive_list_pairs();
  list_whole_ = true;
  whole_ = true;
}

void RankStep::send_list_pairs() {
  buffer_.clear();
  pack_list_pairs(access_, plan_, rank_, buffer_);
  send_to_others();
}

void RankStep::receive_list_pairs() {
  receive_from_others(list_pairs_size, unpack_list_pairs);
  complete_gathered_list(access_);
}

void RankStep::gather_positions() {
  if (whole_) return;
  Stopwatch watch(serial_.gather_seconds);
  buffer_.clear();
  pack_owned_positions(access_, plan_, rank_, buffer_);
  send_gathered(true);
  receive_from_others(owned_positions_size, unpack_owned_positions);
}

void RankStep::send_owned_state() {
  buffer_.clear();
  pack_owned_state(access_, plan_, rank_, buffer_);
  send_gathered(false);
}

void RankStep::send_gathered(bool positions) {
  send_to_others();
  ++serial_.gathers;
  if (positions) ++serial_.position_gathers;
}

void RankStep::send_to_others() {
  for (int q = 0; q < ranks_; ++q)
    if (q != rank_) transport_->send(q, buffer_);
  serial_.gathered_values += buffer_.size() * static_cast<std::size_t>(ranks_ - 1);
}

void RankStep::receive_from_others(SizeOf size, Unpack unpack) {
  for (int q = 0; q < ranks_; ++q) {
    if (q == rank_) continue;
    buffer_.resize(size(access_, plan_, q));
    transport_->receive(q, buffer_);
    unpack(access_, plan_, q, buffer_);
  }
}

void RankStep::receive_owned_states() { receive_from_others(owned_state_size, unpack_owned_state); }

void RankStep::make_plan() {
  // After a build: its cut, and the chunks that can name each disc from its stripes (no rank
  // holds the whole list). A copy's first plan (whole: fresh, or resumed): from its list. Bonds
  // made between builds: the routes of the last build's cut and chunks.
  ThreadSplit cut;
  ChunkRanks chunk_ranks;
  if (build_) {
    cut = build_cut_;
    chunk_ranks = stripe_chunk_ranks(pending_.bins.grid, access_.discs, cut);
  } else if (plan_.ranks == 0) {
    cut = cut_(access_.neighbors, access_.discs, access_.clusters, ranks_);
    if (cut.threads() != ranks_) throw std::logic_error("a rank cut with another number of shares than ranks");
    chunk_ranks = list_chunk_ranks(access_.neighbors, cut, access_.discs.size());
  } else {
    cut = plan_.cut;
    chunk_ranks = {plan_.even_rank, plan_.odd_rank};
  }
  plan_ = make_exchange_plan(std::move(chunk_ranks), access_.neighbors.builds, access_.contacts.walls, access_.discs,
                             access_.clusters, cut, access_.bonds,
                             access_.bonds.id_a.empty() ? 0 : access_.bond_scratch.acting);
}

void RankStep::send_sums(const Routes& routes) {
  const DiscForce* forces = access_.forces.data();
  for (int q = 0; q < ranks_; ++q) {
    const auto& discs = routes(rank_, q);
    if (q == rank_ || discs.empty()) continue;
    const Discs& d = access_.discs;
    buffer_.clear();
    for (const auto i : discs) {
      buffer_.insert(buffer_.end(), {forces[i].fx, forces[i].fy, forces[i].torque});
      if (d.has_materials) buffer_.push_back(d.slip[i]);  // a running sum, as the force
    }
    transport_->send(q, buffer_);
  }
}

void RankStep::receive_sums(const Routes& routes) {
  DiscForce* forces = access_.forces.data();
  for (int q = 0; q < ranks_; ++q) {
    const auto& discs = routes(q, rank_);
    if (q == rank_ || discs.empty()) continue;
    Discs& d = access_.discs;
    const std::size_t values = sum_values(d);
    buffer_.resize(values * discs.size());
    transport_->receive(q, buffer_);
    const double* v = buffer_.data();
    // Set, not added: the sum arrives whole so far, in the order of one process.
    for (const auto i : discs) {
      forces[i] = {v[0], v[1], v[2]};
      if (d.has_materials) d.slip[i] = v[3];
      v += values;
    }
  }
}

// The rank's share of the cut, cut again between the threads a step of one process of its
// size would use (step_threads), remade when the plan or the thread count changes.
const ThreadSplit& RankStep::thread_cut() {
  const int threads = step_threads(access_.discs.size());
  if (threads_cut_.threads() != threads || threads_cut_build_ != plan_.build || threads_cut_ranks_ != plan_.ranks) {
    threads_cut_ = split_share(plan_.cut, static_cast<std::size_t>(rank_), threads, access_.neighbors);
    threads_cut_build_ = plan_.build;
    threads_cut_ranks_ = plan_.ranks;
  }
  return threads_cut_;
}

void RankStep::on_threads(const std::function<void(const ThreadSplit&, std::size_t)>& work) {
  const ThreadSplit& cut = thread_cut();
  const int threads = cut.threads();
  if (threads == 1) return work(cut, 0);
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int t = 0; t < threads; ++t) work(cut, static_cast<std::size_t>(t));
}

void RankStep::find_pins() {
  World& w = access_.world;
  pins_found_.clear();
  pins_held_.clear();
  auto at_rest = [&](std::size_t i) { return MotionEdit::body_has(access_.discs, access_.clusters, i, Motion::Kinematic); };
  for (const StageHooks::Pin* pin : w.hooks().pins()) {
    pin->prepare(w);
    for (const std::size_t wall : pin->walls())
      w.for_each_touching(wall, [&](std::size_t i) {
        // This rank's wall contacts are this step's; a disc held and recorded already is done.
        if (plan_.wall_rank[i] == rank_ && !(pin->recorded(w, i) && at_rest(i)))
          pins_found_.push_back(static_cast<std::uint32_t>(i));
      });
  }
  std::sort(pins_found_.begin(), pins_found_.end());
  pins_found_.erase(std::unique(pins_found_.begin(), pins_found_.end()), pins_found_.end());
  // A flag for each disc of the whole sums sent to its integrating rank: hold its body.
  for (int q = 0; q < ranks_; ++q) {
    const auto& discs = plan_.whole_sums(rank_, q);
    if (q == rank_ || discs.empty()) continue;
    buffer_.assign(discs.size(), 0.0);
    for (std::size_t k = 0; k < discs.size(); ++k)
      if (std::binary_search(pins_found_.begin(), pins_found_.end(), discs[k])) buffer_[k] = 1;
    transport_->send(q, buffer_);
  }
  for (const auto i : pins_found_)
    if (plan_.step_rank[i] == rank_) pins_held_.push_back(i);
}

void RankStep::take_pin_flags() {
  for (int q = 0; q < ranks_; ++q) {
    const auto& discs = plan_.whole_sums(q, rank_);
    if (q == rank_ || discs.empty()) continue;
    buffer_.resize(discs.size());
    transport_->receive(q, buffer_);
    for (std::size_t k = 0; k < discs.size(); ++k)
      if (buffer_[k] != 0) pins_held_.push_back(discs[k]);
  }
  hold(pins_held_, false);  // before integration, as the hook of one process
}

void RankStep::hold(const std::vector<std::uint32_t>& discs, bool record) {
  if (discs.empty()) return;
  World& w = access_.world;
  const auto pins = w.hooks().pins();
  w.edit_motion([&](MotionEdit& e) {
    for (const auto i : discs) {
      if (record) pins.front()->record(w, i);  // one pin at most (check_steppable_over_ranks)
      e.body_of(i, Motion::Kinematic);
    }
  });
}

void RankStep::integrate() {
  RankAccess& a = access_;
  double max2 = 0;
  std::int64_t not_finite = 0;
  const ThreadSplit& cut = thread_cut();
#pragma omp parallel for num_threads(cut.threads()) schedule(static, 1) reduction(max : max2) reduction(+ : not_finite)
  for (int t = 0; t < cut.threads(); ++t) {
    const Displacement moved = integrate_share(a.discs, a.clusters, a.forces.data(), a.body, a.dt,
                                               a.neighbors.x_ref.data(), a.neighbors.y_ref.data(), cut,
                                               static_cast<std::size_t>(t));
    max2 = std::max(max2, moved.max2);  // a max and a count: exact in any order
    not_finite += moved.not_finite;
  }
  max2_ = max2;
  not_finite_ = static_cast<double>(not_finite);
  buffer_ = {max2_, not_finite_};
  if (has_pins()) buffer_.push_back(static_cast<double>(pins_found_.size()));
  if (has_bonds_) buffer_.push_back(static_cast<double>(breaks_found_.size()));
  for (int q = 0; q < ranks_; ++q)
    if (q != rank_) transport_->send(q, buffer_);
  if (!pins_found_.empty()) {
    buffer_.assign(pins_found_.begin(), pins_found_.end());
    for (int q = 0; q < ranks_; ++q)
      if (q != rank_) transport_->send(q, buffer_);
  }
  if (!breaks_found_.empty()) {
    buffer_.clear();
    for (const auto& b : breaks_found_) buffer_.insert(buffer_.end(), {static_cast<double>(b.bond), b.x, b.y, b.mode});
    for (int q = 0; q < ranks_; ++q)
      if (q != rank_) transport_->send(q, buffer_);
  }
}

void RankStep::step_bonds() {
  breaks_found_.clear();
  has_bonds_ = !access_.bonds.id_a.empty();
  if (!has_bonds_) return;
  // The acting bonds with a disc this rank integrates, in bond order: those of a disc are added
  // to its sum in the order of one process (apply_bond_forces). A bond across the cut is stepped
  // alike by both ranks (its discs' motion came with the ghosts), so both know if it broke.
  Bonds& B = access_.bonds;
  const std::int32_t* step_rank = plan_.step_rank.data();
  my_bonds_.clear();
  for (std::size_t k = 0; k < access_.bond_scratch.acting; ++k)
    if (step_rank[B.a[k]] == rank_ || step_rank[B.b[k]] == rank_) my_bonds_.push_back(static_cast<std::uint32_t>(k));
  bond_forces_of(B, access_.discs, access_.dt, access_.bond_scratch, my_bonds_);
  const BondScratch& s = access_.bond_scratch;
  const Discs& d = access_.discs;
  DiscForce* force = access_.forces.data();
  for (const std::uint32_t k : my_bonds_) {
    const auto a = B.a[k], b = B.b[k];
    if (s.broken[k]) {
      breaks_found_.push_back({k, 0.5 * (d.x[a] + d.x[b]), 0.5 * (d.y[a] + d.y[b]), static_cast<double>(s.broken[k] - 1)});
      continue;
    }
    if (step_rank[a] == rank_) { force[a].fx -= s.fx[k]; force[a].fy -= s.fy[k]; force[a].torque += s.torque_a[k]; }
    if (step_rank[b] == rank_) { force[b].fx += s.fx[k]; force[b].fy += s.fy[k]; force[b].torque += s.torque_b[k]; }
  }
}

void RankStep::remove_broken_bonds() {
  // Every rank's breaks, each once (a bond across the cut was found by both), in bond order: the
  // log and the bonds of one process in every copy.
  auto& all = breaks_all_;
  std::sort(all.begin(), all.end(), [](const FoundBreak& p, const FoundBreak& q) { return p.bond < q.bond; });
  all.erase(std::unique(all.begin(), all.end(), [](const FoundBreak& p, const FoundBreak& q) { return p.bond == q.bond; }),
            all.end());
  if (all.empty()) return;
  Bonds& B = access_.bonds;
  World& w = access_.world;
  std::vector<std::uint8_t> keep(B.size(), 1);
  for (const auto& b : all) {
    B.breaks.push_back({w.step(), w.time(), B.id_a[b.bond], B.id_b[b.bond], b.x, b.y, static_cast<BondBreakMode>(b.mode)});
    keep[b.bond] = 0;
  }
  compact_arrays(B, keep);
  access_.bond_scratch.acting -= all.size();  // the acting bonds still first, in order
}

void RankStep::take_displacements() {
  const bool pins = has_pins();
  if (pins) pins_all_ = pins_found_;  // every rank's, this one's first
  breaks_all_ = breaks_found_;
  for (int q = 0; q < ranks_; ++q) {
    if (q == rank_) continue;
    buffer_.resize(2 + (pins ? 1 : 0) + (has_bonds_ ? 1 : 0));
    transport_->receive(q, buffer_);
    max2_ = std::max(max2_, buffer_[0]);  // a max is exact in any order
    not_finite_ += buffer_[1];
    const auto pinned = static_cast<std::size_t>(pins ? buffer_[2] : 0);
    const auto broken = static_cast<std::size_t>(has_bonds_ ? buffer_.back() : 0);
    if (pinned > 0) {
      buffer_.resize(pinned);
      transport_->receive(q, buffer_);
      for (const double i : buffer_) pins_all_.push_back(static_cast<std::uint32_t>(i));
    }
    if (broken > 0) {
      buffer_.resize(kBreakValues * broken);
      transport_->receive(q, buffer_);
      for (std::size_t k = 0; k < broken; ++k) {
        const double* v = buffer_.data() + kBreakValues * k;
        breaks_all_.push_back({static_cast<std::uint32_t>(v[0]), v[1], v[2], v[3]});
      }
    }
  }
  remove_broken_bonds();
  // Every copy holds and records what any rank pinned (the integrating rank held its own bodies
  // before it moved them), so that all copies keep the same motion flags and the same record.
  if (pins) hold(pins_all_, true);
  access_.moved = Displacement{max2_, static_cast<std::int64_t>(not_finite_)}.distance();
  // Integration zeroed the sums it used; those this rank summed for others stay: clear them,
  // as one process holds only zeros between steps.
  std::fill(access_.forces.begin(), access_.forces.end(), DiscForce{0.0, 0.0, 0.0});
  access_.finish_step();
  whole_ = ranks_ == 1;
}

}  // namespace orogen
