#pragma once
// Streams the outputs of a wedge run one at a time and keeps, per particle (by stable id), its
// depth below the local surface, maximum depth and closure-depth ages; per surface column the
// elevation, cumulative erosion, surface ages and age jumps. Memory: the particles alive now
// plus what each output adds to the records (see docs/exhumation.md).
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "exhumation/closure_ages.hpp"
#include "io/archive_fields.hpp"

namespace orogen {

struct ExhumationParams {
  double h0 = 10;                                          // layer thickness [d]; depths are in h0
  std::vector<double> closure = {0.15, 0.3, 0.5, 0.7, 0.9};  // closure depths h_i [h0], ascending
  double x_lo = 0, column_width = 1;                       // fixed column grid [d]
  std::size_t n_columns = 1;
  double mean_radius = 0.5;  // for an eroded particle never seen in an output [d]
  int particle_stride = 1;   // per-particle series keep ids divisible by this
};

// One output as read from the snapshots (positions in d).
struct OutputDiscs {
  std::int64_t step = 0;
  double time = 0, S = 0;
  std::vector<std::int64_t> id;
  std::vector<double> x, y, radius;
  std::vector<double> deposition_time;  // a run with surface.deposition: when each was laid (NaN: not a deposit); else empty
};

// A row of removals.csv with reason "eroded".
struct ErosionEvent {
  std::int64_t step = 0;
  double time = 0;
  std::int64_t id = 0;
  double x = 0, y = 0;
};

// An eroded particle with its values at the last output it was seen in (last_output = -1 and
// NaN values: eroded before any output saw it).
struct ErodedParticle {
  ErosionEvent event;
  std::int64_t column = -1, last_output = -1;
  double radius = 0, depth = 0, max_depth = 0;
  std::vector<double> age;             // per closure depth [time]
  std::vector<std::uint8_t> unreset;   // per closure depth
};

// What one output adds: column arrays (closure-major for [closure][column]) and the series
// of the particles kept (ids divisible by particle_stride).
struct OutputRecord {
  std::int64_t step = 0;
  double time = 0, S = 0;
  double eroded_area = 0;          // eroded since the previous output [d^2]
  std::int64_t eroded_count = 0;   // eroded since the previous output
  std::vector<double> elevation, top_max_depth, cum_eroded_area;
  std::vector<double> deposit_thickness, deposit_age;  // the sediment in each column now [h0], its mean age
  std::vector<std::int64_t> top_id, cum_eroded_count;
  std::vector<double> surface_age, jump_total;      // [closure][column]
  std::vector<std::uint8_t> surface_unreset;        // [closure][column]
  std::vector<std::int64_t> jump_count;             // [closure][column]
  std::vector<std::int64_t> particle_id;
  std::vector<float> particle_x, particle_y, particle_depth, particle_max_depth;
  std::vector<float> particle_age;                  // [closure][particle]
  std::vector<double> particle_deposition_time;     // per kept particle (NaN: not a deposit)
};

class ExhumationTracker {
 public:
  explicit ExhumationTracker(ExhumationParams params);

  // The next output; `eroded` holds the erosion events after the previous output's step up
  // to this output's step.
  OutputRecord observe(const OutputDiscs& out, std::span<const ErosionEvent> eroded);

  const ExhumationParams& params() const { return p_; }
  std::int64_t outputs_seen() const { return outputs_; }
  std::int64_t last_step() const { return last_step_; }
  const std::vector<ErodedParticle>& eroded() const { return eroded_; }
  // The closure-depth ages of a disc still in the model, or nullptr for one never seen or gone.
  const ClosureAges* ages_of(std::int64_t id) const {
    const auto it = particles_.find(id);
    return it == particles_.end() ? nullptr : &it->second.ages;
  }

  struct Particle {
    ClosureAges ages;
    double radius = 0;
    std::int64_t last_output = -1;
  };

  // Its state, each field once with its key, for the incremental analysis's state file
  // (analysis_state.cpp, io/archive_fields.hpp); per-closure values are row-major. The closure
  // depths and the particle stride are not listed: a load goes into a tracker made with them,
  // then check_loaded().
  template <class Self, class F>
  static void fields(Self& self, F&& f) {
    static_assert(sizeof(std::size_t) == sizeof(std::uint64_t), "n_columns is stored as uint64");
    const std::size_t nc = self.p_.closure.size();
    f("h0", self.p_.h0);
    f("x_lo", self.p_.x_lo);
    f("column_width", self.p_.column_width);
    f("n_columns", self.p_.n_columns);
    f("mean_radius", self.p_.mean_radius);
    f("p_id", keyed_rows(self.particles_, [nc](auto& rows, auto&& g) {
      g("p_last_output", column(rows, &Particle::last_output));
      g("p_radius", column(rows, &Particle::radius));
      ClosureAges::columns(rows, &Particle::ages, nc, "p_", g);
    }));
    f("prev_surface_age", self.prev_surface_age_);
    f("cum_area", self.cum_area_);
    f("jump_total", self.jump_total_);
    f("cum_count", self.cum_count_);
    f("jump_count", self.jump_count_);
    f("outputs", self.outputs_);
    f("last_step", self.last_step_);
    auto& e = self.eroded_;
    const auto event = [](auto member) { return [member](auto& row) -> auto& { return row.event.*member; }; };
    f("e_step", column(e, event(&ErosionEvent::step)));
    f("e_id", column(e, event(&ErosionEvent::id)));
    f("e_col", column(e, &ErodedParticle::column));
    f("e_last", column(e, &ErodedParticle::last_output));
    f("e_time", column(e, event(&ErosionEvent::time)));
    f("e_x", column(e, event(&ErosionEvent::x)));
    f("e_y", column(e, event(&ErosionEvent::y)));
    f("e_r", column(e, &ErodedParticle::radius));
    f("e_d", column(e, &ErodedParticle::depth));
    f("e_m", column(e, &ErodedParticle::max_depth));
    f("e_age", flat_column(e, &ErodedParticle::age, nc));
    f("e_un", flat_column(e, &ErodedParticle::unreset, nc));
  }
  // Throws if the column arrays loaded do not fit the column grid (the message names no file).
  void check_loaded() const;

 private:
  std::unordered_map<std::int64_t, Particle> particles_;
  std::vector<double> prev_surface_age_, cum_area_, jump_total_;
  std::vector<std::int64_t> cum_count_, jump_count_;
  std::vector<ErodedParticle> eroded_;
  std::int64_t outputs_ = 0, last_step_ = -1;
  ExhumationParams p_;
  void record_erosion(std::span<const ErosionEvent> eroded, OutputRecord& r);
  void record_deposits(const OutputDiscs& out, OutputRecord& r) const;
};

}  // namespace orogen
