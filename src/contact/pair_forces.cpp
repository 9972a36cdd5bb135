#include "contact/pair_forces.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/contact_block.hpp"
#include "util/parallel.hpp"

namespace orogen {
namespace {

// Gathers the touching pairs among [p0, p0 + count) into the block (their pair numbers in
// `pair`), zeroes the history of the others, and runs the block kernel on the touching ones.
int compute_block(NeighborList& L, const ContactDisc* c, const ContactLaw& law, double dt, std::size_t p0,
                  int count, ContactBlock& b, std::uint32_t* pair) {
  int m = 0;
  for (int k = 0; k < count; ++k) {
    const std::size_t p = p0 + k;
    const ContactDisc& a = c[L.first[p]];
    const ContactDisc& o = c[L.second[p]];
    const double dx = o.x - a.x, dy = o.y - a.y, rsum = a.radius + o.radius;
    if (dx * dx + dy * dy >= rsum * rsum) { L.xi[p] = 0; continue; }
    b.dx[m] = dx; b.dy[m] = dy; b.ri[m] = a.radius; b.rj[m] = o.radius;
    b.dvx[m] = o.vx - a.vx; b.dvy[m] = o.vy - a.vy; b.wi[m] = a.omega; b.wj[m] = o.omega;
    b.gn[m] = L.gamma_n[p];
    b.gs[m] = law.tangential_damping_ratio * b.gn[m];
    b.xi[m] = L.xi[p];
    pair[m++] = static_cast<std::uint32_t>(p);
  }
  contact_forces_block(b, m, law.kn, law.ks, law.mu, dt);
  for (int k = 0; k < m; ++k) L.xi[pair[k]] = b.xi[k];
  return m;
}

// All pairs of one chunk, in pair order, added onto the discs' forces.
void chunk_forces(NeighborList& L, const ContactDisc* c, const ContactLaw& law, double dt, std::size_t begin,
                  std::size_t end, DiscForce* force) {
  ContactBlock b;
  std::uint32_t pair[kContactBlock];
  for (std::size_t p0 = begin; p0 < end; p0 += kContactBlock) {
    const int count = static_cast<int>(std::min<std::size_t>(kContactBlock, end - p0));
    const int m = compute_block(L, c, law, dt, p0, count, b, pair);
    for (int k = 0; k < m; ++k) {
      const auto i = L.first[pair[k]], j = L.second[pair[k]];
      force[i].fx -= b.fx[k]; force[i].fy -= b.fy[k]; force[i].torque += -c[i].radius * b.ft[k];
      force[j].fx += b.fx[k]; force[j].fy += b.fy[k]; force[j].torque += -c[j].radius * b.ft[k];
    }
  }
}

}  // namespace

double pack_discs(const Discs& d, const NeighborList& L, PairScratch& s) {
  const auto n = static_cast<std::ptrdiff_t>(d.size());
  s.discs.resize(d.size());
  s.forces.resize(d.size());
  ContactDisc* c = s.discs.data();
  const bool matches = L.valid && L.x_ref.size() == d.size();
  const double* xr = matches ? L.x_ref.data() : d.x.data();
  const double* yr = matches ? L.y_ref.data() : d.y.data();
  double max2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max2) if (n > kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    c[i] = {d.x[i], d.y[i], d.vx[i], d.vy[i], d.omega[i], d.radius[i]};
    const double dx = d.x[i] - xr[i], dy = d.y[i] - yr[i];
    const double m2 = dx * dx + dy * dy;
    // Written so that NaN counts as infinitely far: it forces a rebuild, where it is caught.
    max2 = (m2 <= max2) ? max2 : (m2 == m2 ? m2 : std::numeric_limits<double>::infinity());
  }
  return matches ? std::sqrt(max2) : std::numeric_limits<double>::infinity();
}

void compute_pair_forces(NeighborList& L, const ContactLaw& law, double dt, PairScratch& s) {
  const ContactDisc* c = s.discs.data();
  DiscForce* force = s.forces.data();
  const auto n = static_cast<std::ptrdiff_t>(s.forces.size());
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  const bool parallel = static_cast<std::ptrdiff_t>(L.size()) >= kMinParallelItems && omp_get_max_threads() > 1;
  // One thread team for the stage: clear, even chunks, odd chunks.
#pragma omp parallel if (parallel)
  {
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) force[i] = {0.0, 0.0, 0.0};
    // Even chunks, then odd chunks: chunks of one parity share no disc, so they run in
    // parallel without races, and every disc sums its pairs in the same order for any number
    // of threads.
    for (std::ptrdiff_t parity = 0; parity < 2; ++parity) {
#pragma omp for schedule(dynamic, 1)
      for (std::ptrdiff_t k = parity; k < chunks; k += 2)
        chunk_forces(L, c, law, dt, L.chunk_start[k], L.chunk_start[k + 1], force);
    }
  }
}

}  // namespace orogen
