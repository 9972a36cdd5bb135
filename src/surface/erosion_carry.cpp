#include "surface/erosion_carry.hpp"

#include <algorithm>

namespace orogen {

void accrue_erosion(ErosionCarry& carry, const std::vector<double>& before, const std::vector<double>& after,
                    double width) {
  if (carry.due.size() < before.size()) carry.due.resize(before.size(), 0.0);
  for (std::size_t j = 0; j < before.size(); ++j) carry.due[j] += std::max(before[j] - after[j], 0.0) * width;
}

std::vector<std::int64_t> pay_erosion(ErosionCarry& carry, const std::vector<TopParticle>& tops) {
  std::vector<std::int64_t> removed;
  for (const TopParticle& t : tops) {
    if (t.column >= carry.due.size() || t.id < 0 || carry.due[t.column] < t.area) continue;
    carry.due[t.column] -= t.area;
    removed.push_back(t.id);
  }
  return removed;
}

}  // namespace orogen
