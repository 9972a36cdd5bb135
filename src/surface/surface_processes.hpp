#pragma once
// The surface laws driven in a run (issue 40, docs/surface.md): every `every` steps the model's
// surface is measured on fixed columns, the carry's unpaid area is laid on it (the continuum
// surface the laws left last time), the laws advance it, and particles pay the difference:
// top particles (whole clusters) are removed where a column owes a particle's area, each logged
// with the law that eroded most of it, and sediment discs are laid where a column is owed one.
// The area ledger (in, eroded, deposited, out) is a series of the run's.
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "analysis/surface.hpp"
#include "surface/erosion_carry.hpp"
#include "surface/surface_spec.hpp"
#include "world/world.hpp"

namespace orogen {

// Areas [d^2] that entered and left the model's particles since the start.
struct AreaLedger {
  double entered = 0;                           // stamped layer and inflow
  double eroded_threshold = 0;                  // removed above wedge.erosion_height
  std::array<double, kSurfaceLaws> eroded{};    // removed by each law
  double deposited = 0;                         // sediment discs laid
  double left = 0;                              // left the domain
  double recycled = 0, bypassed = 0;            // of the laws' net loss: filled into the forelands, or no room there
  double supplied = 0, supply_bypassed = 0;     // of the outside supply: filled into the forelands, or no room there

  double eroded_total() const { return eroded_threshold + eroded[0] + eroded[1] + eroded[2]; }
  // What the model should hold: in - eroded + deposited - out.
  double expected() const { return entered - eroded_total() + deposited - left; }
};

class SurfaceProcesses {
 public:
  SurfaceProcesses() = default;
  // radii: the sizes deposits are drawn from (the layer's); seed: of the draws.
  SurfaceProcesses(SurfaceSpec spec, std::vector<double> radii, std::uint64_t seed)
      : spec_(std::move(spec)), radii_(std::move(radii)), seed_(seed) {}

  bool active() const { return spec_.has_laws(); }
  bool updates_at(const World& w) const { return active() && w.step() % static_cast<std::uint64_t>(spec_.every) == 0; }
  // One update over the whole columns in [x_lo, x_hi), dt the time since the last, on a base
  // at `base` (empty: flat at y = 0). Throws InstabilityError (exit 3) where the laws would
  // remove the whole layer.
  void update(World& w, double x_lo, double x_hi, double dt, const BaseHeight& base = {});

  AreaLedger& ledger() { return ledger_; }
  const AreaLedger& ledger() const { return ledger_; }
  const SurfaceSpec& spec() const { return spec_; }
  void set_script(SurfaceScript script) { spec_.script = std::move(script); }
  // When each disc was laid, by disc id; NaN for discs not deposited.
  double deposition_time(std::int64_t id) const {
    const auto k = static_cast<std::size_t>(id);
    return k < deposited_at_.size() ? deposited_at_[k] : std::numeric_limits<double>::quiet_NaN();
  }

  // The state a checkpoint holds (state_fields). A branch that switches the laws on (orogen run
  // --from a run without them) finds none there; start_in_branch then begins the ledger.
  void load_state(const ArchiveReader& in);
  // In a branch whose source had no laws: the ledger starts from the model's area now, nothing
  // carried, laid or eroded yet. Changes nothing when load_state found a state.
  void start_in_branch(const World& w);

  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    book_fields(self, f);
    // Only with a supply, so that a run without one writes the checkpoint it always did.
    if (self.spec_.sediment_supply > 0) supply_fields(self, f);
  }

 private:
  template <class Self, class F>
  static void book_fields(Self& self, F&& f) {
    f("surface.origin", self.origin_);
    f("surface.due", self.carry_.due);
    f("surface.by_hillslope", self.carry_.by_law[0]);
    f("surface.by_fluvial", self.carry_.by_law[1]);
    f("surface.by_script", self.carry_.by_law[2]);
    f("surface.deposits", self.deposits_);
    f("surface.deposited_at", self.deposited_at_);
    f("surface.entered", self.ledger_.entered);
    f("surface.eroded_threshold", self.ledger_.eroded_threshold);
    f("surface.eroded", self.ledger_.eroded);
    f("surface.deposited", self.ledger_.deposited);
    f("surface.left", self.ledger_.left);
    f("surface.recycled", self.ledger_.recycled);
    f("surface.bypassed", self.ledger_.bypassed);
  }
  template <class Self, class F>
  static void supply_fields(Self& self, F&& f) {
    f("surface.supplied", self.ledger_.supplied);
    f("surface.supply_bypassed", self.ledger_.supply_bypassed);
  }

  // Makes the carry cover absolute columns [first, last) (column k spans [k w, (k + 1) w)).
  void cover(std::int64_t first, std::int64_t last);
  // The surface on absolute columns [first, last).
  Surface columns_of(const World& w, std::int64_t first, std::int64_t last) const;
  // Removes the top particles of surface s (its column 0 is the carry's column `offset`) that
  // their columns owe; returns how many.
  std::size_t pay_removals(World& w, const Surface& s, std::size_t offset);
  // Lays the sediment discs the columns are owed.
  void lay_deposits(World& w, std::int64_t first, std::int64_t last, const BaseHeight& base);
  double draw_radius(std::uint64_t draw, double& offset) const;

  SurfaceSpec spec_;
  std::vector<double> radii_;
  std::uint64_t seed_ = 0;
  bool loaded_ = false;  // load_state found a state in the checkpoint
  std::int64_t origin_ = 0;  // absolute column of carry_.due[0]
  ErosionCarry carry_;
  std::int64_t deposits_ = 0;  // discs laid so far (the draw of the next)
  std::vector<double> deposited_at_;
  AreaLedger ledger_;
};

// The area of the discs of a world [d^2]; of one disc's body (a cluster's members) by index.
double disc_area(const World& w);
double body_area(const World& w, std::size_t disc);

}  // namespace orogen
