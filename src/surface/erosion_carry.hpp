#pragma once
// The sub-particle carry of issue 40 (docs/surface.md): a surface law lowers or raises a column
// by less than a particle in most updates; rounding each update to whole particles would move
// nothing (or a particle every time). Each column keeps, signed, the area the laws have moved
// and no particle has paid for yet: positive, eroded and still to be removed; negative,
// deposited and still to be filled. A column's top particle is removed once its due reaches
// the particle's area, and a new particle is laid on it once minus its due reaches the new
// particle's area, so that the moved area follows the laws over time. Bookkeeping is exact:
// the area accrued equals the area paid plus what is still due, summed over the columns.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace orogen {

// The laws a removal is logged with (removals.csv's reason, RemovalReason).
enum class SurfaceLaw : std::uint8_t { Hillslope = 0, Fluvial = 1, Script = 2 };
constexpr std::size_t kSurfaceLaws = 3;

struct ErosionCarry {
  std::vector<double> due;  // per column, signed: eroded (> 0) or deposited (< 0) and not yet paid [d^2]
  // Per law and column: the erosion each law accrued and the column has not paid yet (a payment
  // takes from each law in proportion), to name the law of a removal (the one that accrued most).
  std::array<std::vector<double>, kSurfaceLaws> by_law;
};

// Adds (before[k] - after[k]) x width to the due of column `first + k`, and each law's lowering
// x width to its share (lowered_by_law[law][k] >= 0). Grows the vectors to cover the profile.
void accrue_change(ErosionCarry& carry, std::size_t first, const std::vector<double>& before,
                   const std::vector<double>& after, double width,
                   const std::array<std::vector<double>, kSurfaceLaws>& lowered_by_law);

// A column's top particle: what removing it pays (its area; a cluster's whole area, paid by the
// column of its top disc) and who it is (the caller's name for it: a disc index, an id).
struct TopParticle {
  std::size_t column = 0;
  double area = 0;
  std::int64_t id = -1;
};

struct DueRemoval {
  std::int64_t id = -1;
  SurfaceLaw law = SurfaceLaw::Hillslope;
};

// The particles to remove now, at most each column's top one: those whose column's due reaches
// their area, each with the law that accrued most of its column's erosion; each removed
// particle's area is taken from its column's due, and from each law's share in proportion.
std::vector<DueRemoval> pay_erosion(ErosionCarry& carry, const std::vector<TopParticle>& tops);

}  // namespace orogen
