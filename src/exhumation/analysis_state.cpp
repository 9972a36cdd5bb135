#include "exhumation/analysis_state.hpp"

#include "io/archive_fields.hpp"
#include "io/binary_archive.hpp"

namespace orogen {
namespace {

// The file's layout: every record, flat, each listed once with its key in fields() for both
// the save and the load (io/archive_fields.hpp). Per-closure values of particles and removals
// are closure-minor (particle j, closure i at j * n_closure + i).
struct StateArchive {
  std::string run_identity;
  AnalysisSettings settings;
  double flux_in = 0, v = 0, solid_fraction = 0;
  double h0 = 0, x_lo = 0, column_width = 0, mean_radius = 0;
  std::uint64_t n_columns = 0;
  std::vector<std::int64_t> p_id, p_last_output;
  std::vector<double> p_radius, p_first_time, p_time, p_depth, p_max_depth, p_last_deep;
  std::vector<std::uint32_t> p_dips;
  std::vector<std::uint8_t> p_seen, p_deep_now;
  std::vector<double> prev_surface_age, cum_area, jump_total;
  std::vector<std::int64_t> cum_count, jump_count;
  std::int64_t outputs = 0, last_step = 0;
  std::vector<std::int64_t> e_step, e_id, e_col, e_last;
  std::vector<double> e_time, e_x, e_y, e_r, e_d, e_m, e_age;
  std::vector<std::uint8_t> e_un;
  std::vector<std::int64_t> r_step, r_count;
  std::vector<double> r_time, r_S, r_area;
  std::vector<std::int64_t> particle_ids;
  std::uint64_t columns_csv_bytes = 0;

  template <class Self, class F>
  static void fields(Self& a, F&& f) {
    f("run_identity", a.run_identity);
    f("closure", a.settings.closure);
    f("flux_window", a.settings.flux_window);
    f("steady_fraction", a.settings.steady_fraction);
    f("particle_stride", a.settings.particle_stride);
    f("trajectory_output", a.settings.trajectory_output);
    f("flux_in", a.flux_in);
    f("v", a.v);
    f("solid_fraction", a.solid_fraction);
    f("h0", a.h0);
    f("x_lo", a.x_lo);
    f("column_width", a.column_width);
    f("n_columns", a.n_columns);
    f("mean_radius", a.mean_radius);
    // Tracker: particles.
    f("p_id", a.p_id);
    f("p_last_output", a.p_last_output);
    f("p_radius", a.p_radius);
    f("p_first_time", a.p_first_time);
    f("p_time", a.p_time);
    f("p_depth", a.p_depth);
    f("p_max_depth", a.p_max_depth);
    f("p_seen", a.p_seen);
    f("p_last_deep", a.p_last_deep);
    f("p_dips", a.p_dips);
    f("p_deep_now", a.p_deep_now);
    // Tracker: columns and counts.
    f("prev_surface_age", a.prev_surface_age);
    f("cum_area", a.cum_area);
    f("jump_total", a.jump_total);
    f("cum_count", a.cum_count);
    f("jump_count", a.jump_count);
    f("outputs", a.outputs);
    f("last_step", a.last_step);
    // Tracker: removals.
    f("e_step", a.e_step);
    f("e_id", a.e_id);
    f("e_col", a.e_col);
    f("e_last", a.e_last);
    f("e_time", a.e_time);
    f("e_x", a.e_x);
    f("e_y", a.e_y);
    f("e_r", a.e_r);
    f("e_d", a.e_d);
    f("e_m", a.e_m);
    f("e_age", a.e_age);
    f("e_un", a.e_un);
    // Per-output summary and the files' bookkeeping.
    f("r_step", a.r_step);
    f("r_count", a.r_count);
    f("r_time", a.r_time);
    f("r_S", a.r_S);
    f("r_area", a.r_area);
    f("particle_ids", a.particle_ids);
    f("columns_csv_bytes", a.columns_csv_bytes);
  }
};

}  // namespace

void save_analysis_state(const std::filesystem::path& path, const AnalysisState& s) {
  StateArchive a;
  const auto& res = s.results;
  const auto& tr = s.tracker;
  const auto& p = tr.params();
  a.run_identity = s.run_identity;
  a.settings = res.settings;
  a.flux_in = res.flux_in;
  a.v = res.v;
  a.solid_fraction = res.solid_fraction;
  a.h0 = p.h0;
  a.x_lo = p.x_lo;
  a.column_width = p.column_width;
  a.n_columns = static_cast<std::uint64_t>(p.n_columns);
  a.mean_radius = p.mean_radius;
  for (const auto& [id, q] : tr.particles_) {
    a.p_id.push_back(id);
    a.p_last_output.push_back(q.last_output);
    a.p_radius.push_back(q.radius);
    a.p_first_time.push_back(q.ages.first_time_);
    a.p_time.push_back(q.ages.time_);
    a.p_depth.push_back(q.ages.depth_);
    a.p_max_depth.push_back(q.ages.max_depth_);
    a.p_seen.push_back(q.ages.seen_);
    a.p_last_deep.insert(a.p_last_deep.end(), q.ages.last_deep_.begin(), q.ages.last_deep_.end());
    a.p_dips.insert(a.p_dips.end(), q.ages.dips_.begin(), q.ages.dips_.end());
    a.p_deep_now.insert(a.p_deep_now.end(), q.ages.deep_now_.begin(), q.ages.deep_now_.end());
  }
  a.prev_surface_age = tr.prev_surface_age_;
  a.cum_area = tr.cum_area_;
  a.jump_total = tr.jump_total_;
  a.cum_count = tr.cum_count_;
  a.jump_count = tr.jump_count_;
  a.outputs = tr.outputs_;
  a.last_step = tr.last_step_;
  for (const auto& e : tr.eroded_) {
    a.e_step.push_back(e.event.step);
    a.e_id.push_back(e.event.id);
    a.e_col.push_back(e.column);
    a.e_last.push_back(e.last_output);
    a.e_time.push_back(e.event.time);
    a.e_x.push_back(e.event.x);
    a.e_y.push_back(e.event.y);
    a.e_r.push_back(e.radius);
    a.e_d.push_back(e.depth);
    a.e_m.push_back(e.max_depth);
    a.e_age.insert(a.e_age.end(), e.age.begin(), e.age.end());
    a.e_un.insert(a.e_un.end(), e.unreset.begin(), e.unreset.end());
  }
  for (const auto& r : res.outputs) {
    a.r_step.push_back(r.step);
    a.r_count.push_back(r.eroded_count);
    a.r_time.push_back(r.time);
    a.r_S.push_back(r.S);
    a.r_area.push_back(r.eroded_area);
  }
  a.particle_ids = res.particle_ids;
  a.columns_csv_bytes = res.columns_csv_bytes;
  ArchiveWriter w;
  StateArchive::fields(a, ArchiveSaver(w));
  w.finish(path);
}

AnalysisState load_analysis_state(const std::filesystem::path& path) {
  StateArchive a;
  const ArchiveReader in(path);
  StateArchive::fields(a, ArchiveLoader(in));
  AnalysisResults res;
  res.settings = a.settings;
  res.flux_in = a.flux_in;
  res.v = a.v;
  res.solid_fraction = a.solid_fraction;
  ExhumationParams p;
  p.h0 = a.h0;
  p.closure = res.settings.closure;
  p.x_lo = a.x_lo;
  p.column_width = a.column_width;
  p.n_columns = static_cast<std::size_t>(a.n_columns);
  p.mean_radius = a.mean_radius;
  p.particle_stride = res.settings.particle_stride;
  AnalysisState s{.run_identity = a.run_identity, .results = {}, .tracker = ExhumationTracker(p)};
  auto& tr = s.tracker;
  const std::size_t nc = p.closure.size(), ncol = p.n_columns;

  const std::size_t n = a.p_id.size();
  if (a.p_last_deep.size() != n * nc || a.p_dips.size() != n * nc || a.p_deep_now.size() != n * nc ||
      a.p_radius.size() != n)
    throw std::runtime_error("analysis state " + path.string() + ": particle arrays of different lengths");
  for (std::size_t j = 0; j < n; ++j) {
    ExhumationTracker::Particle q;
    q.ages = ClosureAges(nc);
    q.radius = a.p_radius[j];
    q.last_output = a.p_last_output[j];
    q.ages.first_time_ = a.p_first_time[j];
    q.ages.time_ = a.p_time[j];
    q.ages.depth_ = a.p_depth[j];
    q.ages.max_depth_ = a.p_max_depth[j];
    q.ages.seen_ = a.p_seen[j] != 0;
    for (std::size_t i = 0; i < nc; ++i) {
      q.ages.last_deep_[i] = a.p_last_deep[j * nc + i];
      q.ages.dips_[i] = a.p_dips[j * nc + i];
      q.ages.deep_now_[i] = a.p_deep_now[j * nc + i];
    }
    tr.particles_.emplace(a.p_id[j], std::move(q));
  }
  tr.prev_surface_age_ = std::move(a.prev_surface_age);
  tr.cum_area_ = std::move(a.cum_area);
  tr.jump_total_ = std::move(a.jump_total);
  tr.cum_count_ = std::move(a.cum_count);
  tr.jump_count_ = std::move(a.jump_count);
  if (tr.prev_surface_age_.size() != nc * ncol || tr.cum_area_.size() != ncol)
    throw std::runtime_error("analysis state " + path.string() + ": column arrays of the wrong length");
  tr.outputs_ = a.outputs;
  tr.last_step_ = a.last_step;
  if (a.e_age.size() != a.e_step.size() * nc) throw std::runtime_error("analysis state " + path.string() + ": removals damaged");
  for (std::size_t k = 0; k < a.e_step.size(); ++k) {
    ErodedParticle e;
    e.event = {.step = a.e_step[k], .time = a.e_time[k], .id = a.e_id[k], .x = a.e_x[k], .y = a.e_y[k]};
    e.column = a.e_col[k];
    e.last_output = a.e_last[k];
    e.radius = a.e_r[k];
    e.depth = a.e_d[k];
    e.max_depth = a.e_m[k];
    const auto at = [&](std::size_t m) { return static_cast<std::ptrdiff_t>(m * nc); };
    e.age.assign(a.e_age.begin() + at(k), a.e_age.begin() + at(k + 1));
    e.unreset.assign(a.e_un.begin() + at(k), a.e_un.begin() + at(k + 1));
    tr.eroded_.push_back(std::move(e));
  }

  const std::size_t nt = a.r_step.size();
  if (static_cast<std::int64_t>(nt) != tr.outputs_ || a.r_count.size() != nt || a.r_time.size() != nt ||
      a.r_S.size() != nt || a.r_area.size() != nt)
    throw std::runtime_error("analysis state " + path.string() + ": output count damaged");
  for (std::size_t t = 0; t < nt; ++t)
    res.outputs.push_back({.step = a.r_step[t], .time = a.r_time[t], .S = a.r_S[t], .eroded_area = a.r_area[t],
                           .eroded_count = a.r_count[t]});
  res.particle_ids = std::move(a.particle_ids);
  res.columns_csv_bytes = a.columns_csv_bytes;
  s.results = std::move(res);
  return s;
}

}  // namespace orogen
