#pragma once
// The singly-vergent critical wedge (thesis 3.2.3, Appendix A; after Burbidge and Braun 2002):
// a settled layer of thickness h0 on a rough Coulomb base is shortened by a smooth rigid
// backstop (the right wall) moving left at constant speed; the far (left) wall stays. A wedge
// grows against the backstop; its surface taper is measured through time and compared with
// the critical taper of the material's bulk friction (biaxial experiment).
#include "analysis/displacement_tracker.hpp"
#include "analysis/profile_fit.hpp"
#include "experiments/experiment.hpp"
#include "io/archive_fields.hpp"
#include "experiments/packing_experiment.hpp"
#include "surface/surface_processes.hpp"

namespace orogen {

struct SinglyVergentSpec {
  double h0 = 10;            // layer thickness (d)
  double length = 200;       // layer length (d)
  double speed = 0.025;      // backstop speed (sqrt(g d))
  double mu_b = 0.2;         // basal Coulomb friction
  BaseWeakening base_weakening;  // of mu_b with the discs' slip (singly.basal_weakening)
  double shortening = 5;     // run until the backstop has moved this far (h0)
  double initial_slope = 0;  // surface slope of a wedge cut from the layer before shortening (rad); 0: flat
  int outputs = 50;          // output steps over the run
  double steady_from = 0.5;  // the taper statistics use outputs after this fraction of the run
  double column_width_factor = 2.3;
  PackingSpec packing;
  SettleSpec settle;
  SurfaceSpec surface;       // the surface laws ([surface]; none by default), a Python law
};

// The wedge's shape at one moment (lengths in d, angles in rad).
struct SinglyVergentShape {
  double backstop = 0;  // x of the backstop
  double front = 0;     // deformation front: left end of the raised surface next to the backstop
  double height = 0;    // highest surface point of the wedge minus h0
  double taper = 0;     // least-squares surface slope from the front to the backstop
  double taper_front = 0, taper_back = 0;  // the same over the front and back halves
  double taper_mean = 0;  // atan(height / (backstop - front))
  bool has_wedge = false;
};

class SinglyVergentExperiment final : public Experiment {
 public:
  explicit SinglyVergentExperiment(SinglyVergentSpec spec) : spec_(std::move(spec)) {}

  void setup(World& world) override;
  bool advance(World& world) override;
  std::vector<SeriesColumn> columns() const override;
  std::vector<double> measure(const World& world) const override;
  std::vector<SnapshotField> fields(const World& world) const override;
  std::vector<std::pair<std::string, double>> scalars(const World& world) const override;
  void after_output(const World& world) override;
  void save(ArchiveWriter& out) const override;
  void load(const ArchiveReader& in) override;
  void adopt_branch_config(World& w) override;
  std::vector<SummaryValue> summary(const World& world) const override;
  bool runs_over_ranks() const override { return true; }
  std::string status(const World& world) const override;
  double fraction_done(const World& world) const override { return shortening(world) / spec_.shortening; }
  double h0() const override { return spec_.h0; }
  std::array<double, 4> view_box(const World& world) const override;
  std::optional<double> output_interval() const override {
    return spec_.shortening * spec_.h0 / spec_.speed / spec_.outputs;
  }

  // Backstop displacement / h0.
  double shortening(const World& world) const { return spec_.speed * world.time() / spec_.h0; }
  SinglyVergentShape shape(const World& world) const;
  bool set_surface_script(SurfaceScript script) override;

 private:
  void cut_wedge(World& w);
  // By disc, whether it left the box (below its floor, out past either wall): positions only;
  // and their removal, logged.
  std::vector<std::uint8_t> stray_flags(const World& w) const;
  void remove_strays(World& w, std::span<const std::uint8_t> strays);
  // (Re)makes the surface processes from the spec (setup and load): columns 2.3 mean radii of
  // the packing's sizes wide, deposits drawn from those sizes, fixed for the run's life.
  void start_surface();

  SinglyVergentSpec spec_;
  // The checkpointed state, each field once with its key, for save() and load()
  // (io/archive_fields.hpp).
  template <class Self, class F>
  static void state_fields(Self& self, F&& f) {
    f("singly.initial_discs", self.initial_discs_);
    f("singly.history_s", self.history_s_);
    f("singly.history_taper", self.history_taper_);
  }

  std::int64_t initial_discs_ = 0;
  // Shortening and taper at each output, for the steady-state statistics of the summary.
  std::vector<double> history_s_, history_taper_;
  DisplacementTracker displacements_;
  SurfaceProcesses surface_;  // the surface laws and the area ledger
};

std::unique_ptr<Experiment> make_singly_vergent_experiment(const Config& config);

}  // namespace orogen
