#pragma once
// A base that deflects under the load on it (issue 40, docs/isostasy.md): segment walls whose
// end points are nodes segment_length apart. Every `every` steps the load of the discs over each
// node's column, beyond the reference layer's, is solved for the deflection (plate_flexure.hpp),
// and over the next `every` steps the nodes move linearly from where they are to it, so that
// no disc is kicked by a jump of the base. The plate reaches beyond the nodes: the solve has
// margin nodes with the reference load on each side, four flexural parameters wide, and past
// the nodes the base stays at the end nodes' heights.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "boundary/wall.hpp"
#include "isostasy/isostasy_spec.hpp"
#include "particles/discs.hpp"

namespace orogen {

class World;

class IsostaticBase {
 public:
  IsostaticBase() = default;
  // Nodes from at most x_lo to at least x_hi, one of them at x = 0 (the S-point, where the
  // pro-side and retro-side bases meet); reference_load: the reference layer's weight per length.
  IsostaticBase(const IsostasySpec& spec, double x_lo, double x_hi, double reference_load);

  bool active() const { return spec_.active(); }
  // The reference layer's weight per length, measured on the layer as built.
  void set_reference_load(double load) { reference_load_ = load; }
  const std::vector<double>& nodes() const { return x_; }

  // The segment walls: a copy of `pro` between each pair of nodes left of 0, named
  // "<pro.name>_<k>", and of `retro` right of it, named likewise; the last retro segment
  // reaches to retro_end.
  std::vector<Wall> segments(const Wall& pro, const Wall& retro, double retro_end) const;
  // Solves for the deflection under the load of the discs whose centres lie in columns wholly
  // within [covered_lo, covered_hi] (beyond it: the reference load) and starts the base's move
  // to it at `step`.
  void solve(const Discs& discs, double covered_lo, double covered_hi, std::uint64_t step);
  // Height of the base at x at `step` (on its move), the end nodes' beyond them.
  double height(double x, std::uint64_t step) const;
  // The step at which the base reaches the last solution.
  std::uint64_t move_end() const { return move_start_ + static_cast<std::uint64_t>(spec_.every); }
  // The node heights at `step`.
  std::vector<double> heights(std::uint64_t step) const;

  // Deflection measures at `step`, in d: the deepest node and where it is, the highest
  // node on each side of it (the forebulges).
  struct Shape {
    double deepest, x_deepest, bulge_pro, bulge_retro;
  };
  Shape shape(std::uint64_t step) const;

  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("isostasy.nodes", self.x_);  // fixed for the run's life: an extended run (a larger s_end) keeps them
    f("isostasy.from", self.from_);
    f("isostasy.to", self.to_);
    f("isostasy.move_start", self.move_start_);
    f("isostasy.reference_load", self.reference_load_);
  }

 private:
  double at_node(std::size_t k, std::uint64_t step) const;

  IsostasySpec spec_;
  double reference_load_ = 0;
  std::vector<double> x_;      // the nodes, ascending
  std::size_t margin_ = 0;     // solve nodes beyond each end
  std::vector<double> from_, to_;  // node heights where the move began and where it ends
  std::uint64_t move_start_ = 0;
};

}  // namespace orogen
