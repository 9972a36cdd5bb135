#include "contact/contact_damping.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "util/parallel.hpp"

namespace orogen {
namespace {

double pair_mass(double ma, double mb) {
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
}

}  // namespace

double resisting_mass(const Discs& d, const Clusters& c, std::uint32_t i) {
  if (!d.is_dynamic(i)) return std::numeric_limits<double>::infinity();
  return d.cluster[i] >= 0 ? c.mass[static_cast<std::size_t>(d.cluster[i])] : d.mass[i];
}

void prepare_damping(const ContactLaw& law, const Discs& d, const Clusters& c, double dt) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double m = resisting_mass(d, c, static_cast<std::uint32_t>(i));
    if (std::isinf(m)) continue;
    lo = std::min(lo, m);
    hi = std::max(hi, m);
  }
  if (hi == 0) return;
  law.prepare_damping(0.5 * lo, hi, dt);
}

void set_pair_damping(PairContacts& pairs, const NeighborList& L, const Discs& d, const Clusters& c,
                      const ContactLaw& law, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(L.size());
  pairs.gamma_n.resize(L.size());
#pragma omp parallel for schedule(static) if (static_cast<std::ptrdiff_t>(d.size()) > min_parallel_items())
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    const double m = pair_mass(resisting_mass(d, c, L.first[p]), resisting_mass(d, c, L.second[p]));
    pairs.gamma_n[p] = law.gamma_n(m, dt);
  }
}

void set_wall_damping(WallContacts& wc, const Discs& d, const Clusters& c, const ContactLaw& law, double dt) {
  wc.gamma_n.resize(wc.size());
  for (std::size_t k = 0; k < wc.size(); ++k) wc.gamma_n[k] = law.gamma_n(resisting_mass(d, c, wc.disc[k]), dt);
}

}  // namespace orogen
