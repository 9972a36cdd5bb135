#include "exhumation/analysis_state.hpp"

#include "io/binary_archive.hpp"

namespace orogen {

void save_analysis_state(const std::filesystem::path& path, const AnalysisState& s) {
  ArchiveWriter w;
  const auto& res = s.results;
  const auto& tr = s.tracker;
  const auto& p = tr.params();
  w.put_string("run_identity", s.run_identity);
  w.put("closure", res.settings.closure);
  w.put_scalar("flux_window", res.settings.flux_window);
  w.put_scalar("steady_fraction", res.settings.steady_fraction);
  w.put_scalar("particle_stride", res.settings.particle_stride);
  w.put_scalar("trajectory_output", res.settings.trajectory_output);
  w.put_scalar("flux_in", res.flux_in);
  w.put_scalar("v", res.v);
  w.put_scalar("solid_fraction", res.solid_fraction);
  w.put_scalar("h0", p.h0);
  w.put_scalar("x_lo", p.x_lo);
  w.put_scalar("column_width", p.column_width);
  w.put_scalar("n_columns", static_cast<std::uint64_t>(p.n_columns));
  w.put_scalar("mean_radius", p.mean_radius);

  // Tracker.
  std::vector<std::int64_t> ids, last_output;
  std::vector<double> radius, first_time, time, depth, max_depth, last_deep;
  std::vector<std::uint32_t> dips;
  std::vector<std::uint8_t> seen, deep_now;
  for (const auto& [id, q] : tr.particles_) {
    ids.push_back(id);
    last_output.push_back(q.last_output);
    radius.push_back(q.radius);
    first_time.push_back(q.ages.first_time_);
    time.push_back(q.ages.time_);
    depth.push_back(q.ages.depth_);
    max_depth.push_back(q.ages.max_depth_);
    seen.push_back(q.ages.seen_);
    last_deep.insert(last_deep.end(), q.ages.last_deep_.begin(), q.ages.last_deep_.end());
    dips.insert(dips.end(), q.ages.dips_.begin(), q.ages.dips_.end());
    deep_now.insert(deep_now.end(), q.ages.deep_now_.begin(), q.ages.deep_now_.end());
  }
  w.put("p_id", ids);
  w.put("p_last_output", last_output);
  w.put("p_radius", radius);
  w.put("p_first_time", first_time);
  w.put("p_time", time);
  w.put("p_depth", depth);
  w.put("p_max_depth", max_depth);
  w.put("p_seen", seen);
  w.put("p_last_deep", last_deep);
  w.put("p_dips", dips);
  w.put("p_deep_now", deep_now);
  w.put("prev_surface_age", tr.prev_surface_age_);
  w.put("cum_area", tr.cum_area_);
  w.put("jump_total", tr.jump_total_);
  w.put("cum_count", tr.cum_count_);
  w.put("jump_count", tr.jump_count_);
  w.put_scalar("outputs", tr.outputs_);
  w.put_scalar("last_step", tr.last_step_);
  std::vector<std::int64_t> e_step, e_id, e_col, e_last;
  std::vector<double> e_time, e_x, e_y, e_r, e_d, e_m, e_age;
  std::vector<std::uint8_t> e_un;
  for (const auto& e : tr.eroded_) {
    e_step.push_back(e.event.step);
    e_id.push_back(e.event.id);
    e_col.push_back(e.column);
    e_last.push_back(e.last_output);
    e_time.push_back(e.event.time);
    e_x.push_back(e.event.x);
    e_y.push_back(e.event.y);
    e_r.push_back(e.radius);
    e_d.push_back(e.depth);
    e_m.push_back(e.max_depth);
    e_age.insert(e_age.end(), e.age.begin(), e.age.end());
    e_un.insert(e_un.end(), e.unreset.begin(), e.unreset.end());
  }
  w.put("e_step", e_step);
  w.put("e_id", e_id);
  w.put("e_col", e_col);
  w.put("e_last", e_last);
  w.put("e_time", e_time);
  w.put("e_x", e_x);
  w.put("e_y", e_y);
  w.put("e_r", e_r);
  w.put("e_d", e_d);
  w.put("e_m", e_m);
  w.put("e_age", e_age);
  w.put("e_un", e_un);

  // Per-output summary and the files' bookkeeping.
  std::vector<std::int64_t> r_step, r_count;
  std::vector<double> r_time, r_S, r_area;
  for (const auto& r : res.outputs) {
    r_step.push_back(r.step);
    r_count.push_back(r.eroded_count);
    r_time.push_back(r.time);
    r_S.push_back(r.S);
    r_area.push_back(r.eroded_area);
  }
  w.put("r_step", r_step);
  w.put("r_count", r_count);
  w.put("r_time", r_time);
  w.put("r_S", r_S);
  w.put("r_area", r_area);
  w.put("particle_ids", res.particle_ids);
  w.put_scalar("columns_csv_bytes", res.columns_csv_bytes);
  w.finish(path);
}

AnalysisState load_analysis_state(const std::filesystem::path& path) {
  const ArchiveReader a(path);
  AnalysisResults res;
  a.get("closure", res.settings.closure);
  res.settings.flux_window = a.get_scalar<int>("flux_window");
  res.settings.steady_fraction = a.get_scalar<double>("steady_fraction");
  res.settings.particle_stride = a.get_scalar<int>("particle_stride");
  res.settings.trajectory_output = a.get_scalar<std::int64_t>("trajectory_output");
  res.flux_in = a.get_scalar<double>("flux_in");
  res.v = a.get_scalar<double>("v");
  res.solid_fraction = a.get_scalar<double>("solid_fraction");
  ExhumationParams p;
  p.h0 = a.get_scalar<double>("h0");
  p.closure = res.settings.closure;
  p.x_lo = a.get_scalar<double>("x_lo");
  p.column_width = a.get_scalar<double>("column_width");
  p.n_columns = static_cast<std::size_t>(a.get_scalar<std::uint64_t>("n_columns"));
  p.mean_radius = a.get_scalar<double>("mean_radius");
  p.particle_stride = res.settings.particle_stride;
  AnalysisState s{.run_identity = a.get_string("run_identity"), .results = {}, .tracker = ExhumationTracker(p)};
  auto& tr = s.tracker;
  const std::size_t nc = p.closure.size(), ncol = p.n_columns;

  std::vector<std::int64_t> ids, last_output;
  std::vector<double> radius, first_time, time, depth, max_depth, last_deep;
  std::vector<std::uint32_t> dips;
  std::vector<std::uint8_t> seen, deep_now;
  a.get("p_id", ids);
  a.get("p_last_output", last_output);
  a.get("p_radius", radius);
  a.get("p_first_time", first_time);
  a.get("p_time", time);
  a.get("p_depth", depth);
  a.get("p_max_depth", max_depth);
  a.get("p_seen", seen);
  a.get("p_last_deep", last_deep);
  a.get("p_dips", dips);
  a.get("p_deep_now", deep_now);
  const std::size_t n = ids.size();
  if (last_deep.size() != n * nc || dips.size() != n * nc || deep_now.size() != n * nc || radius.size() != n)
    throw std::runtime_error("analysis state " + path.string() + ": particle arrays of different lengths");
  for (std::size_t j = 0; j < n; ++j) {
    ExhumationTracker::Particle q;
    q.ages = ClosureAges(nc);
    q.radius = radius[j];
    q.last_output = last_output[j];
    q.ages.first_time_ = first_time[j];
    q.ages.time_ = time[j];
    q.ages.depth_ = depth[j];
    q.ages.max_depth_ = max_depth[j];
    q.ages.seen_ = seen[j] != 0;
    for (std::size_t i = 0; i < nc; ++i) {
      q.ages.last_deep_[i] = last_deep[j * nc + i];
      q.ages.dips_[i] = dips[j * nc + i];
      q.ages.deep_now_[i] = deep_now[j * nc + i];
    }
    tr.particles_.emplace(ids[j], std::move(q));
  }
  a.get("prev_surface_age", tr.prev_surface_age_);
  a.get("cum_area", tr.cum_area_);
  a.get("jump_total", tr.jump_total_);
  a.get("cum_count", tr.cum_count_);
  a.get("jump_count", tr.jump_count_);
  if (tr.prev_surface_age_.size() != nc * ncol || tr.cum_area_.size() != ncol)
    throw std::runtime_error("analysis state " + path.string() + ": column arrays of the wrong length");
  tr.outputs_ = a.get_scalar<std::int64_t>("outputs");
  tr.last_step_ = a.get_scalar<std::int64_t>("last_step");
  std::vector<std::int64_t> e_step, e_id, e_col, e_last;
  std::vector<double> e_time, e_x, e_y, e_r, e_d, e_m, e_age;
  std::vector<std::uint8_t> e_un;
  a.get("e_step", e_step);
  a.get("e_id", e_id);
  a.get("e_col", e_col);
  a.get("e_last", e_last);
  a.get("e_time", e_time);
  a.get("e_x", e_x);
  a.get("e_y", e_y);
  a.get("e_r", e_r);
  a.get("e_d", e_d);
  a.get("e_m", e_m);
  a.get("e_age", e_age);
  a.get("e_un", e_un);
  if (e_age.size() != e_step.size() * nc) throw std::runtime_error("analysis state " + path.string() + ": removals damaged");
  for (std::size_t k = 0; k < e_step.size(); ++k) {
    ErodedParticle e;
    e.event = {.step = e_step[k], .time = e_time[k], .id = e_id[k], .x = e_x[k], .y = e_y[k]};
    e.column = e_col[k];
    e.last_output = e_last[k];
    e.radius = e_r[k];
    e.depth = e_d[k];
    e.max_depth = e_m[k];
    e.age.assign(e_age.begin() + static_cast<std::ptrdiff_t>(k * nc), e_age.begin() + static_cast<std::ptrdiff_t>((k + 1) * nc));
    e.unreset.assign(e_un.begin() + static_cast<std::ptrdiff_t>(k * nc), e_un.begin() + static_cast<std::ptrdiff_t>((k + 1) * nc));
    tr.eroded_.push_back(std::move(e));
  }

  std::vector<std::int64_t> r_step, r_count;
  std::vector<double> r_time, r_S, r_area;
  a.get("r_step", r_step);
  a.get("r_count", r_count);
  a.get("r_time", r_time);
  a.get("r_S", r_S);
  a.get("r_area", r_area);
  const std::size_t nt = r_step.size();
  if (static_cast<std::int64_t>(nt) != tr.outputs_ || r_count.size() != nt || r_time.size() != nt ||
      r_S.size() != nt || r_area.size() != nt)
    throw std::runtime_error("analysis state " + path.string() + ": output count damaged");
  for (std::size_t t = 0; t < nt; ++t)
    res.outputs.push_back({.step = r_step[t], .time = r_time[t], .S = r_S[t], .eroded_area = r_area[t],
                           .eroded_count = r_count[t]});
  a.get("particle_ids", res.particle_ids);
  res.columns_csv_bytes = a.get_scalar<std::uint64_t>("columns_csv_bytes");
  s.results = std::move(res);
  return s;
}

}  // namespace orogen
