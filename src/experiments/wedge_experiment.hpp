#pragma once
// The doubly-vergent wedge (MODEL §7, thesis chapters 4-6): a settled layer of thickness h0 on
// a flat base, driven toward the S-point (x = 0) by the pro-side plate at speed v while the
// retro-side plate is at rest, in the frame of the S-point. Two basal conditions (constant
// velocity, thesis 4.3; traction, 4.4), a reduced active region fed by a kinematic incoming
// slab built from a repeated settled tile (4.2), optional erosion above a threshold height
// (6.3), and the wedge measurements of MODEL §8.
#include <optional>
#include <string_view>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/packing_experiment.hpp"
#include "analysis/displacement_tracker.hpp"
#include "analysis/surface.hpp"
#include "analysis/wedge_geometry.hpp"
#include "experiments/wedge_summary.hpp"
#include "io/archive_fields.hpp"
#include "packing/tile.hpp"
#include "isostasy/isostatic_base.hpp"
#include "surface/surface_processes.hpp"

namespace orogen {

enum class BasalCondition { Traction, ConstantVelocity };
// The pro-side plate's law under the traction condition: a Coulomb belt (the rough wall's
// spring moving with the plate) or eq. 4.1's drag (wedge.traction_law, docs/model.md "Bases").
enum class TractionLaw { Spring, Drag };

struct WedgeSpec {
  BasalCondition basal = BasalCondition::Traction;
  double h0 = 10;              // layer thickness (d)
  double v = 0.025;            // convergence speed of the pro-side plate (d per sqrt(d/g))
  double mu_bp = 0.2, mu_br = 0.4;  // basal friction, pro and retro side
  BaseWeakening base_weakening;     // of both with the discs' slip (wedge.basal_weakening)
  TractionLaw traction_law = TractionLaw::Spring;
  double gamma_b = 1e4;        // traction drag coefficient (m g / sqrt(g d)), TractionLaw::Drag only
  double s_end = 8;            // run until this normalised convergence S
  int outputs = 100;           // output steps over the run
  double window = 6;           // active region reaches this many h0 beyond each front
  double initial_active = 12;  // pro-side active length before any front forms (h0)
  double retro_length = 8;     // retro-side layer length (h0)
  double tile_length = 8;      // length of the settled tile (h0)
  double erosion_height = 0;   // erode above this multiple of h0 (0: no erosion)
  int erosion_every = 50;      // steps between erosion passes
  double marker_height = 1.5;  // marker fronts at this multiple of h0
  FrontRule fronts = FrontRule::Surface;  // how series.csv's Dp, Dr are measured (wedge.fronts)
  double column_width_factor = 2.3;
  bool analysis_in_run = false;    // the exhumation analysis during the run (analysis.in_run)
  std::int64_t analysis_every = 1;  // after every this many outputs and at the end (analysis.every)
  std::string packing_file;    // settled tile from a packing run; empty: settle one first
  PackingSpec packing;         // for settling the tile
  SettleSpec settle;
  SurfaceSpec surface;                  // the surface laws ([surface]; none by default), a Python law
  IsostasySpec isostasy;                // a base that deflects under the load ([isostasy]; rigid by default)
};

// One output's measurements of the wedge, in the units of series.csv (the table in
// wedge_experiment.cpp names each field's column).
struct WedgeSample {
  double step, time, S, H, Dp, Mp, Dr, Mr, T, alpha, beta, alpha_fit, beta_fit, slip_pro, slip_retro, n_active,
      n_discs, n_eroded, n_left, n_entered, window_pro, window_retro;
};

class WedgeExperiment final : public Experiment {
 public:
  explicit WedgeExperiment(WedgeSpec spec) : spec_(std::move(spec)) {}

  void setup(World& world) override;
  void attach(World& world) override;
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  std::vector<SnapshotField> fields(const World& world) const override;
  std::vector<std::pair<std::string, double>> scalars(const World& world) const override;
  void after_output(const World& world) override;
  std::vector<OutputObserver> output_observers(const std::filesystem::path& run_dir) const override;
  std::vector<SummaryValue> summary(const World& world) const override;
  void save(ArchiveWriter& out) const override;
  void load(const ArchiveReader& in) override;
  void adopt_branch_config(World& w) override;
  bool runs_over_ranks() const override { return true; }
  std::string status(const World& world) const override;
  double fraction_done(const World& world) const override { return convergence(world) / spec_.s_end; }
  double h0() const override { return spec_.h0; }
  std::array<double, 4> view_box(const World& world) const override;
  std::optional<double> output_interval() const override {
    return spec_.s_end * spec_.h0 / spec_.v / spec_.outputs;
  }
  double x_split() const override { return 0.0; }
  bool set_surface_script(SurfaceScript script) override;

  // Normalised convergence S = v t / h0 since the plates started.
  double convergence(const World& world) const { return spec_.v * (world.time() - t_start_) / spec_.h0; }

 private:
  void build_layer(World& world);
  void feed_slab(World& world);
  void update_windows(World& world);
  // The constant-velocity base's pin (StageHooks::Pin): sized, set and read by disc index.
  void size_pins(const World& world);
  void pin(const World& world, std::size_t disc);
  bool pinned(const World& world, std::size_t disc) const;
  // Removes the discs flagged above the threshold (World::flags_above).
  void erode(World& world, std::span<const std::uint8_t> above);
  // (Re)makes the deflecting base from the spec and the tile (setup and load); the indices of the
  // walls of each base (attach).
  void start_isostasy();
  // A branch that switches isostasy on (its source ran on a rigid base): the base becomes the
  // segments set-up makes, balanced against the load of the tile the layer is stamped from.
  void start_isostasy_in_branch(World& world);
  double layer_load(const World& world) const;
  void find_base_walls(const World& world);
  std::vector<Wall> segmented_base(const Wall& pro, const Wall& retro, const Wall& end) const;
  // Moves the base's segments and the end wall to where the base is at this step.
  void place_base(World& world) const;
  // The base's height at x now (0: a rigid base), and as a function (empty: a rigid base).
  double base_height(const World& world, double x) const;
  BaseHeight on_base(const World& world) const;
  // Vertical speed of a kinematic body at x moving at vx that keeps it on the deflecting base
  // until the next window update.
  double riding_speed(const World& world, double x, double vx) const;
  WallContactStats base_stats(const World& world, const std::vector<std::size_t>& walls) const;
  // Stops the run (InstabilityError, exit 3) where the base's next position is deeper than 10 h0.
  void check_base_depth(const World& world) const;
  // series.csv's columns of the deflecting base, and their values with the fronts Dp, Dr [h0].
  static const std::vector<SeriesColumn>& isostasy_columns();
  std::vector<double> isostasy_values(const World& world, double dp, double dr) const;
  // By disc, whether it left the model (below the base, past the far end, far above): positions
  // only; and their removal, logged.
  std::vector<std::uint8_t> stray_flags(const World& world) const;
  void remove_strays(World& world, std::span<const std::uint8_t> strays);
  // The area of the discs [first, last), counted as entered.
  void count_entered(const World& world, std::size_t first, std::size_t last);
  // (Re)makes the surface processes from the spec and the tile (setup and load).
  void start_surface();
  Surface surface(const Discs& discs) const;
  std::unique_ptr<Discs> crust(const World& world) const;
  WedgeSample sample(const World& world) const;
  // Margin cut off each side of the settled box, where its walls loosened the packing.
  double tile_margin() const { return tile_margin_for(spec_.h0); }
  // Kinematic slab kept beyond the pro window: the transition band and the surface
  // measurement (from 1 h0 before the window) need a few d of it; more is only cost, and it
  // is updated every step (a whole tile more was 25% of the discs at h0 = 20).
  double slab_reserve() const { return 2.0 * spec_.h0; }

 public:
  // Steps between window and stray checks: the kinematic slab's riding speeds hold until the
  // next (isostasy.every is a multiple of it).
  static constexpr std::uint64_t kHousekeepingEvery = 100;
  // The walls of a rigid base (a deflecting base splits the first two into segments).
  static constexpr std::string_view kProBase = "pro_base", kRetroBase = "retro_base", kRetroEnd = "retro_end";
  static double tile_margin_for(double h0) { return 0.5 * h0 + 2.0; }
  // The checkpointed scalars and arrays, each once with its key, for save() and load()
  // (io/archive_fields.hpp); the tile, the displacements and the history save themselves.
  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("wedge.t_start", self.t_start_);
    f("wedge.slab_left", self.slab_left_);
    f("wedge.window_pro", self.window_pro_);
    f("wedge.window_retro", self.window_retro_);
    f("wedge.x_end", self.x_end_);
    f("wedge.entered", self.entered_);
    f("wedge.pinned", self.pinned_);
  }
  // Why a settled packing cannot give this wedge its tiles (not h0 thick, or too short for a
  // tile of at least h0 between its margins), or empty if it can: the factory's configuration
  // check and setup() ask this one function.
  static std::string tile_problem(const Tile& tile, double h0);

  WedgeSpec spec_;
  Tile tile_;
  double t_start_ = 0;
  double slab_left_ = 0;     // left edge of the leftmost stamped tile (moves with the plate)
  double window_pro_ = 0;    // discs left of this are kinematic, moving with the plate
  double window_retro_ = 0;  // discs right of this are kinematic at rest (the end wall: none)
  double x_end_ = 0;         // right end wall of the retro-side layer
  std::int64_t entered_ = 0; // discs ever added to the model
  std::vector<std::uint8_t> pinned_;  // by disc id: held at rest on the retro base (pin)
  DisplacementTracker displacements_;  // for the per-output displacement fields
  WedgeHistory history_;               // the shape at each output, for summary.csv
  SurfaceProcesses surface_;           // the surface laws and the area ledger
  IsostaticBase base_;                 // the base's deflection (isostasy)
  bool base_loaded_ = false;           // load() found the base's state (not a branch switching it on)
  std::vector<std::size_t> pro_walls_, retro_walls_;  // each base's walls: one, or its segments
};

// The wedge from the [wedge], [layer], [particles] and [settle] keys (wedge_from_config.cpp);
// checks across keys throw ConfigError.
std::unique_ptr<Experiment> make_wedge_experiment(const Config& config);

}  // namespace orogen
