#pragma once
// The sub-particle carry of issue 40 (docs/surface.md): a surface law lowers a column by less
// than a particle in most updates; rounding each update to whole particles would erode nothing
// (or a particle every time). Each column keeps the area the law has removed and no particle has
// paid for yet, and a column's top particle is removed once its due reaches the particle's area,
// so that the eroded area follows the law over time. Bookkeeping is exact: the area accrued
// equals the area removed plus what is still due, summed over the columns.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace orogen {

struct ErosionCarry {
  std::vector<double> due;  // per column: area the law removed and no particle paid yet [d^2]
};

// Adds max(before - after, 0) x width to each column's due (a column whose surface rose owes
// nothing: that is deposition's). Grows `due` to the profile's length.
void accrue_erosion(ErosionCarry& carry, const std::vector<double>& before, const std::vector<double>& after,
                    double width);

// A column's top particle: what removing it pays (its area; a cluster's whole area, paid by the
// column of its top disc) and who it is.
struct TopParticle {
  std::size_t column = 0;
  double area = 0;
  std::int64_t id = -1;
};

// The particles to remove now, at most each column's top one: those whose column's due reaches
// their area; each removed particle's area is taken from its column's due.
std::vector<std::int64_t> pay_erosion(ErosionCarry& carry, const std::vector<TopParticle>& tops);

}  // namespace orogen
