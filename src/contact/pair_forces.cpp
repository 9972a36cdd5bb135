#include "contact/pair_forces.hpp"

#include <algorithm>
#include <type_traits>

#include "contact/contact_block.hpp"
#include "contact/materials.hpp"
#include "contact/normal_laws.hpp"

namespace orogen {
namespace {

// The disc arrays the contact loop reads.
struct DiscView {
  const double *x, *y, *vx, *vy, *omega, *radius;
};

// The pair arrays the contact loop reads and writes, as plain pointers: through the vectors,
// every double stored (a history, a block entry, a force) would make the compiler reload every
// array's address, since as far as it knows the store might change a vector's own pointer.
struct PairView {
  const std::uint32_t* __restrict first;
  const std::uint32_t* __restrict second;
  const double* __restrict gamma_n;
  double* __restrict xi;
  double* __restrict roll;  // nullptr: no contact resists rolling
};

// Where a pair's friction comes from. The thesis's one material: contact.mu for every pair,
// and no slip is kept (the loops are those of before materials, bit for bit). Named materials:
// the weaker of the two discs' frictions of this step (World::step_stages fills them from each
// disc's material and slip), and the slip of each contact on the Coulomb limit added to both
// discs (chunks of one parity share no disc: no race, and the same order for any thread count).
struct UniformFriction {
  static constexpr bool kTracksSlip = false;
  double mu;
  double pair(std::uint32_t, std::uint32_t) const { return mu; }
  void add_slip(std::uint32_t, std::uint32_t, double) const {}
};
struct MaterialFriction {
  static constexpr bool kTracksSlip = true;
  const double* __restrict mu_disc;
  double* __restrict slip;
  double pair(std::uint32_t i, std::uint32_t j) const { return pair_friction(mu_disc[i], mu_disc[j]); }
  void add_slip(std::uint32_t i, std::uint32_t j, double s) const { slip[i] += s; slip[j] += s; }
};

// Where a pair's rolling resistance comes from, as its friction does. None (the thesis's law):
// no rolling history is kept and the loops are those of before rolling resistance, bit for bit.
// Resisting: contact.rolling_friction for every pair (with UniformFriction), or in a world of
// materials the weaker of the two discs' coefficients (with MaterialFriction).
struct NoRolling {
  static constexpr bool kOn = false;  // the loops read nothing else of it
};
struct UniformRolling {
  static constexpr bool kOn = true;
  double kr_per_r2;  // k_r / r_eff^2
  double mu_r;
  double pair(std::uint32_t, std::uint32_t) const { return mu_r; }
};
struct MaterialRolling {
  static constexpr bool kOn = true;
  double kr_per_r2;
  const std::uint8_t* __restrict material;  // each disc's
  const double* __restrict mur;             // each material's
  double pair(std::uint32_t i, std::uint32_t j) const {
    return pair_rolling_friction(mur[material[i]], mur[material[j]]);
  }
};

// Gathers the touching pairs among [p0, p0 + count) into the block (their pair numbers in
// `pair`), zeroes the history of the others, and runs the block kernel on the touching ones.
template <class Normal, class Friction, class Rolling>
int compute_block(const PairView& L, const DiscView& d, const ContactLaw& law, const Friction& friction,
                  const Rolling& rolling, double dt, std::size_t p0, int count, ContactBlock& b, std::uint32_t* pair) {
  int m = 0;
  const double damping_ratio = law.tangential_damping_ratio;
  for (int k = 0; k < count; ++k) {
    const std::size_t p = p0 + k;
    const auto i = L.first[p], j = L.second[p];
    const double dx = d.x[j] - d.x[i], dy = d.y[j] - d.y[i], rsum = d.radius[i] + d.radius[j];
    if (dx * dx + dy * dy >= rsum * rsum) {
      L.xi[p] = 0;
      if constexpr (Rolling::kOn) L.roll[p] = 0;
      continue;
    }
    b.dx[m] = dx; b.dy[m] = dy; b.ri[m] = d.radius[i]; b.rj[m] = d.radius[j];
    b.dvx[m] = d.vx[j] - d.vx[i]; b.dvy[m] = d.vy[j] - d.vy[i]; b.wi[m] = d.omega[i]; b.wj[m] = d.omega[j];
    b.gn[m] = L.gamma_n[p];
    b.gs[m] = damping_ratio * b.gn[m];
    b.xi[m] = L.xi[p];
    if constexpr (Friction::kTracksSlip || Rolling::kOn) b.mu[m] = friction.pair(i, j);
    if constexpr (Rolling::kOn) { b.mur[m] = rolling.pair(i, j); b.roll[m] = L.roll[p]; }
    pair[m++] = static_cast<std::uint32_t>(p);
  }
  if constexpr (Rolling::kOn)
    contact_forces_block_rolling<Normal>(b, m, law.kn, law.ks, rolling.kr_per_r2, dt);
  else if constexpr (Friction::kTracksSlip)
    contact_forces_block_materials<Normal>(b, m, law.kn, law.ks, dt);
  else
    contact_forces_block<Normal>(b, m, law.kn, law.ks, law.mu, dt);
  for (int k = 0; k < m; ++k) L.xi[pair[k]] = b.xi[k];
  if constexpr (Rolling::kOn)
    for (int k = 0; k < m; ++k) L.roll[pair[k]] = b.roll[k];
  return m;
}

// Pairs [begin, end) in pair order, added onto the discs' forces, only the touching ones
// through the kernel: for the pairs that were apart at the list build, most still apart (so
// the test mostly goes one way and its branch is predicted).
template <class Normal, class Friction, class Rolling>
void touching_pair_forces(const PairView& L, const DiscView& d, const ContactLaw& law, const Friction& friction,
                          const Rolling& rolling, double dt, std::size_t begin, std::size_t end,
                          DiscForce* __restrict force) {
  ContactBlock b;
  std::uint32_t pair[kContactBlock];
  for (std::size_t p0 = begin; p0 < end; p0 += kContactBlock) {
    const int count = static_cast<int>(std::min<std::size_t>(kContactBlock, end - p0));
    const int m = compute_block<Normal>(L, d, law, friction, rolling, dt, p0, count, b, pair);
    for (int k = 0; k < m; ++k) {
      const auto i = L.first[pair[k]], j = L.second[pair[k]];
      force[i].fx -= b.fx[k]; force[i].fy -= b.fy[k]; force[i].torque += -b.ri[k] * b.ft[k];
      force[j].fx += b.fx[k]; force[j].fy += b.fy[k]; force[j].torque += -b.rj[k] * b.ft[k];
      if constexpr (Rolling::kOn) { force[i].torque -= b.moment[k]; force[j].torque += b.moment[k]; }
      if constexpr (Friction::kTracksSlip) friction.add_slip(i, j, b.slip[k]);
    }
  }
}

// The same sums with every pair through the kernel, which reads the discs itself: for the
// pairs that touched at the list build, most still touching. Testing pairs that touch or not
// at random costs a mispredicted branch per pair that goes the other way, and with the discs
// out of cache (a wedge of 30k discs, a pile of 80k) each one waits for the positions it
// tested: on N(I), one thread, testing every pair ran 1.5x slower (docs/performance.md). A
// pair apart gets what the test would have given it: zero history, and a zero force and
// torque that change no sum (the sums start at +0.0, and a sum that starts at +0.0 never
// becomes -0.0 when rounding to nearest, so adding +0.0 or -0.0 leaves it as it is): the sums
// are bitwise those of touching_pair_forces.
template <class Normal, class Friction, class Rolling>
void all_pair_forces(const PairView& L, const DiscView& d, const ContactLaw& law, const Friction& friction,
                     const Rolling& rolling, double dt, std::size_t begin, std::size_t end,
                     DiscForce* __restrict force) {
  alignas(64) double fx[kContactBlock], fy[kContactBlock], ft[kContactBlock], slip[kContactBlock];
  alignas(64) double moment[kContactBlock];
  const double damping_ratio = law.tangential_damping_ratio;
  const double kn = law.kn, ks = law.ks;
  for (std::size_t p0 = begin; p0 < end; p0 += kContactBlock) {
    const int count = static_cast<int>(std::min<std::size_t>(kContactBlock, end - p0));
    const std::uint32_t* __restrict first = L.first + p0;
    const std::uint32_t* __restrict second = L.second + p0;
    const double* __restrict gamma_n = L.gamma_n + p0;
    double* __restrict xi = L.xi + p0;
    double* __restrict roll = Rolling::kOn ? L.roll + p0 : nullptr;
#pragma omp simd
    for (int k = 0; k < count; ++k) {
      const auto i = first[k], j = second[k];
      const ContactLane c =
          contact_lane<Normal>(d.x[j] - d.x[i], d.y[j] - d.y[i], d.radius[i], d.radius[j], d.vx[j] - d.vx[i],
                               d.vy[j] - d.vy[i], d.omega[i], d.omega[j], gamma_n[k], damping_ratio * gamma_n[k],
                               xi[k], kn, ks, friction.pair(i, j), dt);
      fx[k] = c.fx; fy[k] = c.fy; ft[k] = c.ft; xi[k] = c.xi;
      if constexpr (Friction::kTracksSlip) slip[k] = c.slip;
      if constexpr (Rolling::kOn) {
        const RollingLane r = rolling_lane(c.touching, d.radius[i], d.radius[j], d.omega[i], d.omega[j], roll[k],
                                           Normal::load(c.fn), rolling.kr_per_r2, rolling.pair(i, j), dt);
        roll[k] = r.roll; moment[k] = r.moment;
      }
    }
    for (int k = 0; k < count; ++k) {
      const auto i = first[k], j = second[k];
      force[i].fx -= fx[k]; force[i].fy -= fy[k]; force[i].torque += -d.radius[i] * ft[k];
      force[j].fx += fx[k]; force[j].fy += fy[k]; force[j].torque += -d.radius[j] * ft[k];
      if constexpr (Rolling::kOn) { force[i].torque -= moment[k]; force[j].torque += moment[k]; }
      if constexpr (Friction::kTracksSlip) friction.add_slip(i, j, slip[k]);
    }
  }
}

// The share of touching pairs above which a whole chunk goes through the kernel untested.
constexpr double kDenseShare = 0.65;

// Thread t's chunks of one parity, with the normal law Normal (one instance of the loops per
// registered law, chosen once per step).
template <class Normal, class Friction, class Rolling>
void parity_forces(const NeighborList& L, const PairView& pairs, const DiscView& d, const ContactLaw& law,
                   const Friction& friction, const Rolling& rolling, double dt, DiscForce* force,
                   const ThreadSplit& split, std::size_t t, std::ptrdiff_t parity) {
  const std::ptrdiff_t begin = split.chunk[t], end = split.chunk[t + 1];
  for (std::ptrdiff_t k = begin + ((begin & 1) != parity); k < end; k += 2) {
    const auto kk = static_cast<std::size_t>(k);
    // The pairs that touched at the build untested, then the rest tested. Either way gives
    // the same bits; the hint is missing right after a resume.
    const std::size_t begin_pair = L.chunk_start[kk], end_pair = L.chunk_start[kk + 1];
    std::size_t untested_end =
        kk < L.chunk_touching.size() ? std::min(begin_pair + L.chunk_touching[kk], end_pair) : begin_pair;
    // A chunk that is mostly touching (the settled pile: 74%) goes untested whole: testing
    // its few apart pairs from memory cost the 80k pile 6-9% (docs/performance.md).
    const double pairs_in_chunk = static_cast<double>(end_pair - begin_pair);
    if (static_cast<double>(untested_end - begin_pair) >= kDenseShare * pairs_in_chunk) untested_end = end_pair;
    all_pair_forces<Normal>(pairs, d, law, friction, rolling, dt, begin_pair, untested_end, force);
    touching_pair_forces<Normal>(pairs, d, law, friction, rolling, dt, untested_end, end_pair, force);
  }
}

// Thread t's even chunks, then its odd ones. Chunks of one parity share no disc, so they run in
// parallel without races, and every disc sums its pairs in the same order for any number of
// threads.
template <class Normal, class Friction, class Rolling>
void chunk_forces(const NeighborList& L, const PairView& pairs, const DiscView& d, const ContactLaw& law,
                  const Friction& friction, const Rolling& rolling, double dt, DiscForce* force,
                  const ThreadSplit& split, std::size_t t) {
  for (std::ptrdiff_t parity = 0; parity < 2; ++parity) {
    parity_forces<Normal>(L, pairs, d, law, friction, rolling, dt, force, split, t, parity);
#pragma omp barrier
  }
}

// Calls run(normal law, friction, rolling) with the step's law, friction and rolling resistance
// (resisting whenever the store keeps rolling histories).
template <class Run>
void with_law_and_friction(const ContactLaw& law, const DiscCoefficients& disc, bool rolling, Discs& discs,
                           Run&& run) {
  with_normal_law(law.normal_force, [&](auto normal) {
    const double kr_per_r2 = law.rolling_stiffness * law.ks;
    const auto with_rolling = [&](const auto& friction) {
      if (!rolling)
        run(normal, friction, NoRolling{});
      else if constexpr (std::decay_t<decltype(friction)>::kTracksSlip)
        run(normal, friction, MaterialRolling{kr_per_r2, disc.material, disc.rolling});
      else
        run(normal, friction, UniformRolling{kr_per_r2, law.rolling_friction});
    };
    if (disc.friction == nullptr)
      with_rolling(UniformFriction{law.mu});
    else
      with_rolling(MaterialFriction{disc.friction, discs.slip.data()});
  });
}

}  // namespace

void pair_forces_share(const NeighborList& L, PairContacts& contacts, Discs& discs, const ContactLaw& law,
                       const DiscCoefficients& disc, double dt, DiscForce* force, const ThreadSplit& split,
                       std::size_t t) {
  const DiscView d{discs.x.data(), discs.y.data(), discs.vx.data(), discs.vy.data(), discs.omega.data(),
                   discs.radius.data()};
  const bool rolling = !contacts.roll.empty();
  const PairView pairs{L.first.data(), L.second.data(), contacts.gamma_n.data(), contacts.xi.data(),
                       rolling ? contacts.roll.data() : nullptr};
  with_law_and_friction(law, disc, rolling, discs, [&](auto normal, const auto& friction, const auto& roll) {
    chunk_forces<decltype(normal)>(L, pairs, d, law, friction, roll, dt, force, split, t);
  });
}

void pair_forces_parity(const NeighborList& L, PairContacts& contacts, Discs& discs, const ContactLaw& law,
                        const DiscCoefficients& disc, double dt, DiscForce* force, const ThreadSplit& split,
                        std::size_t t, int parity) {
  const DiscView d{discs.x.data(), discs.y.data(), discs.vx.data(), discs.vy.data(), discs.omega.data(),
                   discs.radius.data()};
  const bool rolling = !contacts.roll.empty();
  const PairView pairs{L.first.data(), L.second.data(), contacts.gamma_n.data(), contacts.xi.data(),
                       rolling ? contacts.roll.data() : nullptr};
  with_law_and_friction(law, disc, rolling, discs, [&](auto normal, const auto& friction, const auto& roll) {
    parity_forces<decltype(normal)>(L, pairs, d, law, friction, roll, dt, force, split, t, parity);
  });
}

}  // namespace orogen
