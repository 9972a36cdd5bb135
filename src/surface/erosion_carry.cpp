#include "surface/erosion_carry.hpp"

#include <algorithm>

namespace orogen {

void accrue_change(ErosionCarry& carry, std::size_t first, const std::vector<double>& before,
                   const std::vector<double>& after, double width,
                   const std::array<std::vector<double>, kSurfaceLaws>& lowered_by_law) {
  const std::size_t n = before.size();
  if (carry.due.size() < first + n) carry.due.resize(first + n, 0.0);
  for (auto& share : carry.by_law)
    if (share.size() < first + n) share.resize(first + n, 0.0);
  for (std::size_t j = 0; j < n; ++j) carry.due[first + j] += (before[j] - after[j]) * width;
  for (std::size_t law = 0; law < kSurfaceLaws; ++law)
    for (std::size_t j = 0; j < std::min(n, lowered_by_law[law].size()); ++j)
      carry.by_law[law][first + j] += lowered_by_law[law][j] * width;
}

std::vector<DueRemoval> pay_erosion(ErosionCarry& carry, const std::vector<TopParticle>& tops) {
  std::vector<DueRemoval> removed;
  for (const TopParticle& t : tops) {
    if (t.column >= carry.due.size() || t.id < 0 || carry.due[t.column] < t.area) continue;
    const double owed = carry.due[t.column];
    carry.due[t.column] -= t.area;
    std::size_t law = 0;
    for (std::size_t l = 1; l < kSurfaceLaws; ++l)
      if (t.column < carry.by_law[l].size() && carry.by_law[l][t.column] > carry.by_law[law][t.column]) law = l;
    // What is still owed keeps the laws' proportions: a column that pays several particles in
    // one update (the removal passes) names each after the same law.
    const double kept = carry.due[t.column] / owed;
    for (auto& share : carry.by_law)
      if (t.column < share.size()) share[t.column] *= kept;
    removed.push_back({t.id, static_cast<SurfaceLaw>(law)});
  }
  return removed;
}

}  // namespace orogen
