// Writes analysis.h5 (labelled for xarray: time x column, time x particle, ...) and the CSV
// tables analysis_flux.csv, analysis_columns.csv and analysis_removals.csv.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "exhumation/analysis_results.hpp"
#include "exhumation/flux_balance.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_labelled.hpp"

namespace orogen {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
const std::string kAge = "model time since the particle was last deeper than the closure depth";

std::string num(double v) { return std::isnan(v) ? "" : fmt::format("{}", v); }

template <class T, class F>
std::vector<T> stack(const std::vector<OutputRecord>& recs, F field) {
  std::vector<T> out;
  for (const auto& r : recs) {
    const auto& v = field(r);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

FluxBalance flux_of(const AnalysisResults& res) {
  std::vector<double> t, area;
  for (const auto& r : res.records) { t.push_back(r.time); area.push_back(r.eroded_area); }
  return flux_balance(t, area, res.flux_in, res.settings.flux_window, res.settings.steady_fraction);
}

}  // namespace

void write_analysis_files(const std::filesystem::path& dir, const AnalysisResults& res,
                          const ExhumationTracker& tracker) {
  const auto& p = tracker.params();
  const auto& recs = res.records;
  const std::size_t nt = recs.size(), ncol = p.n_columns, nc = p.closure.size();
  const FluxBalance flux = flux_of(res);
  using h5::VarInfo;

  h5::File f = h5::File::create_in_memory();
  const hid_t root = f.id();
  h5::set_attr_string(root, "title", "orogen exhumation analysis (docs/exhumation.md)");
  h5::set_attr_double(root, "h0", p.h0);
  h5::set_attr_double(root, "flux_in", res.flux_in);
  h5::set_attr_double(root, "solid_fraction", res.solid_fraction);
  h5::set_attr_double(root, "speed", res.v);
  h5::set_attr_int64(root, "steady_output", flux.steady_output);
  h5::set_attr_int64(root, "flux_window", res.settings.flux_window);
  h5::set_attr_double(root, "steady_fraction", res.settings.steady_fraction);
  h5::set_attr_int64(root, "particle_stride", p.particle_stride);

  // Dimensions.
  std::vector<double> time, S, col_x;
  std::vector<std::int64_t> step;
  for (const auto& r : recs) { time.push_back(r.time); step.push_back(r.step); S.push_back(r.S); }
  for (std::size_t c = 0; c < ncol; ++c)
    col_x.push_back((p.x_lo + (static_cast<double>(c) + 0.5) * p.column_width) / p.h0);
  std::vector<std::int64_t> ids;
  for (const auto& r : recs) ids.insert(ids.end(), r.particle_id.begin(), r.particle_id.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  h5::write_dimension(root, "time", time, {"sqrt(d/g)", "model time of the output"});
  h5::write_dimension(root, "column", col_x, {"h0", "x of the column centre, from the S-point"});
  h5::write_dimension(root, "closure", p.closure, {"h0", "closure depth h_i below the local surface"});
  h5::write_dimension(root, "particle", ids, {"1", "stable disc id (the union over outputs; NaN where absent)"});

  // time
  h5::write_variable(root, "step", {"time"}, std::span<const std::int64_t>(step), {"1", "model time step of the output"});
  h5::write_variable(root, "S", {"time"}, std::span<const double>(S), {"1", "normalised convergence v t / h0"});
  const auto per_time = [&](auto get) {
    std::vector<double> v;
    for (const auto& r : recs) v.push_back(get(r));
    return v;
  };
  h5::write_variable(root, "eroded_area", {"time"},
                     std::span<const double>(per_time([](const OutputRecord& r) { return r.eroded_area; })),
                     {"d^2", "disc area eroded since the previous output"});
  h5::write_variable(root, "eroded_count", {"time"},
                     std::span<const double>(per_time([](const OutputRecord& r) { return double(r.eroded_count); })),
                     {"1", "discs eroded since the previous output"});
  h5::write_variable(root, "flux_out", {"time"}, std::span<const double>(flux.flux_out),
                     {"d^2/sqrt(d/g)", "eroded disc area per time over the last output interval"});
  h5::write_variable(root, "flux_out_mean", {"time"}, std::span<const double>(flux.mean_out),
                     {"d^2/sqrt(d/g)", "eroded disc area per time over the last flux_window output intervals"});
  h5::write_variable(root, "flux_ratio", {"time"}, std::span<const double>(flux.ratio),
                     {"1", "flux_out_mean / flux_in (flux_in = speed h0 solid_fraction, thesis eq. 6.1)"});

  // time x column
  h5::write_variable(root, "elevation", {"time", "column"},
                     std::span<const double>(stack<double>(recs, [](const OutputRecord& r) -> auto& { return r.elevation; })),
                     {"h0", "surface: top of the highest disc in the column (NaN: empty)"});
  h5::write_variable(root, "surface_id", {"time", "column"},
                     std::span<const std::int64_t>(stack<std::int64_t>(recs, [](const OutputRecord& r) -> auto& { return r.top_id; })),
                     {"1", "id of the disc at the surface (-1: empty column)"});
  h5::write_variable(root, "surface_max_depth", {"time", "column"},
                     std::span<const double>(stack<double>(recs, [](const OutputRecord& r) -> auto& { return r.top_max_depth; })),
                     {"h0", "maximum depth ever reached by the disc at the surface"});
  h5::write_variable(root, "cum_eroded_area", {"time", "column"},
                     std::span<const double>(stack<double>(recs, [](const OutputRecord& r) -> auto& { return r.cum_eroded_area; })),
                     {"d^2", "disc area eroded from the column up to this output"});
  h5::write_variable(root, "cum_eroded_count", {"time", "column"},
                     std::span<const std::int64_t>(stack<std::int64_t>(recs, [](const OutputRecord& r) -> auto& { return r.cum_eroded_count; })),
                     {"1", "discs eroded from the column up to this output"});
  // time x closure x column
  const std::vector<std::string> tcc = {"time", "closure", "column"};
  h5::write_variable(root, "surface_age", tcc,
                     std::span<const double>(stack<double>(recs, [](const OutputRecord& r) -> auto& { return r.surface_age; })),
                     {"sqrt(d/g)", "age of the disc at the surface: " + kAge});
  h5::write_variable(root, "surface_unreset", tcc,
                     std::span<const std::uint8_t>(stack<std::uint8_t>(recs, [](const OutputRecord& r) -> auto& { return r.surface_unreset; })),
                     {"1", "1: the disc at the surface was never deeper than the closure depth"});
  const auto jc = stack<std::int64_t>(recs, [](const OutputRecord& r) -> auto& { return r.jump_count; });
  const auto jt = stack<double>(recs, [](const OutputRecord& r) -> auto& { return r.jump_total; });
  std::vector<double> jm(jt.size());
  for (std::size_t k = 0; k < jt.size(); ++k) jm[k] = jc[k] > 0 ? jt[k] / static_cast<double>(jc[k]) : kNaN;
  h5::write_variable(root, "jump_count", tcc, std::span<const std::int64_t>(jc),
                     {"1", "outputs so far at which the surface age of the column fell (a jump)"});
  h5::write_variable(root, "jump_total", tcc, std::span<const double>(jt),
                     {"sqrt(d/g)", "sum of the falls of surface age so far"});
  h5::write_variable(root, "jump_mean", tcc, std::span<const double>(jm),
                     {"sqrt(d/g)", "jump_total / jump_count (NaN: no jump yet)"});

  // time x particle (and time x closure x particle), NaN where a particle is absent.
  std::map<std::int64_t, std::size_t> slot;
  for (std::size_t m = 0; m < ids.size(); ++m) slot[ids[m]] = m;
  const std::size_t np = ids.size();
  std::vector<float> px(nt * np, kNaNf), py(nt * np, kNaNf), pd(nt * np, kNaNf), pm(nt * np, kNaNf),
      pa(nt * nc * np, kNaNf);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& r = recs[t];
    const std::size_t kept = r.particle_id.size();
    for (std::size_t j = 0; j < kept; ++j) {
      const std::size_t m = slot.at(r.particle_id[j]);
      px[t * np + m] = r.particle_x[j];
      py[t * np + m] = r.particle_y[j];
      pd[t * np + m] = r.particle_depth[j];
      pm[t * np + m] = r.particle_max_depth[j];
      for (std::size_t i = 0; i < nc; ++i) pa[(t * nc + i) * np + m] = r.particle_age[i * kept + j];
    }
  }
  h5::write_variable(root, "x", {"time", "particle"}, std::span<const float>(px), {"h0", "disc centre x, from the S-point"});
  h5::write_variable(root, "y", {"time", "particle"}, std::span<const float>(py), {"h0", "disc centre elevation above the base"});
  h5::write_variable(root, "depth", {"time", "particle"}, std::span<const float>(pd),
                     {"h0", "depth of the disc centre below the surface of its column"});
  h5::write_variable(root, "max_depth", {"time", "particle"}, std::span<const float>(pm),
                     {"h0", "largest depth reached up to this output"});
  h5::write_variable(root, "age", {"time", "closure", "particle"}, std::span<const float>(pa),
                     {"sqrt(d/g)", kAge + " (un-reset discs: since their first output)"});

  // Trajectories: the discs at the surface at the chosen output, back through time.
  std::vector<std::int64_t> traj;
  std::int64_t at = res.settings.trajectory_output < 0 ? static_cast<std::int64_t>(nt) - 1 : res.settings.trajectory_output;
  at = std::min<std::int64_t>(at, static_cast<std::int64_t>(nt) - 1);
  if (at >= 0)
    for (auto id : recs[static_cast<std::size_t>(at)].top_id)
      if (id >= 0 && slot.contains(id)) traj.push_back(id);
  h5::set_attr_int64(root, "trajectory_output", at);
  h5::write_dimension(root, "trajectory", traj, {"1", "id of a disc at the surface at output trajectory_output"});
  const std::size_t ntr = traj.size();
  std::vector<float> tx(nt * ntr), ty(nt * ntr), td(nt * ntr);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t j = 0; j < ntr; ++j) {
      const std::size_t m = slot.at(traj[j]);
      tx[t * ntr + j] = px[t * np + m];
      ty[t * ntr + j] = py[t * np + m];
      td[t * ntr + j] = pd[t * np + m];
    }
  h5::write_variable(root, "trajectory_x", {"time", "trajectory"}, std::span<const float>(tx), {"h0", "x of the disc"});
  h5::write_variable(root, "trajectory_y", {"time", "trajectory"}, std::span<const float>(ty), {"h0", "elevation of the disc centre"});
  h5::write_variable(root, "trajectory_depth", {"time", "trajectory"}, std::span<const float>(td),
                     {"h0", "depth of the disc below the surface"});

  // Removals by erosion, with the disc's values at the last output that saw it.
  const auto& er = tracker.eroded();
  std::vector<std::int64_t> rid, rstep, rcol, rlast;
  std::vector<double> rt, rx, ry, rd, rm, ra(er.size() * nc);
  std::vector<std::uint8_t> ru(er.size() * nc);
  for (std::size_t k = 0; k < er.size(); ++k) {
    const auto& e = er[k];
    rid.push_back(e.event.id);
    rstep.push_back(e.event.step);
    rcol.push_back(e.column);
    rlast.push_back(e.last_output);
    rt.push_back(e.event.time);
    rx.push_back(e.event.x / p.h0);
    ry.push_back(e.event.y / p.h0);
    rd.push_back(e.depth);
    rm.push_back(e.max_depth);
    for (std::size_t i = 0; i < nc; ++i) { ra[k * nc + i] = e.age[i]; ru[k * nc + i] = e.unreset[i]; }
  }
  std::vector<std::int64_t> rindex(er.size());
  for (std::size_t k = 0; k < er.size(); ++k) rindex[k] = static_cast<std::int64_t>(k);
  h5::write_dimension(root, "removal", rindex, {"1", "row of the eroded discs, in removals.csv order"});
  h5::write_variable(root, "removal_id", {"removal"}, std::span<const std::int64_t>(rid), {"1", "disc id"});
  h5::write_variable(root, "removal_step", {"removal"}, std::span<const std::int64_t>(rstep), {"1", "time step of the erosion"});
  h5::write_variable(root, "removal_time", {"removal"}, std::span<const double>(rt), {"sqrt(d/g)", "model time of the erosion"});
  h5::write_variable(root, "removal_x", {"removal"}, std::span<const double>(rx), {"h0", "x when eroded"});
  h5::write_variable(root, "removal_y", {"removal"}, std::span<const double>(ry), {"h0", "elevation when eroded"});
  h5::write_variable(root, "removal_column", {"removal"}, std::span<const std::int64_t>(rcol), {"1", "column index (-1: outside the grid)"});
  h5::write_variable(root, "removal_last_output", {"removal"}, std::span<const std::int64_t>(rlast),
                     {"1", "last output that saw the disc, whose values follow (-1: none, values NaN)"});
  h5::write_variable(root, "removal_depth", {"removal"}, std::span<const double>(rd), {"h0", "depth at that output"});
  h5::write_variable(root, "removal_max_depth", {"removal"}, std::span<const double>(rm), {"h0", "maximum depth up to that output"});
  h5::write_variable(root, "removal_age", {"removal", "closure"}, std::span<const double>(ra), {"sqrt(d/g)", kAge + " at that output"});
  h5::write_variable(root, "removal_unreset", {"removal", "closure"}, std::span<const std::uint8_t>(ru),
                     {"1", "1: never deeper than the closure depth"});
  write_file_atomically(dir / "analysis.h5", f.image());

  // CSV tables (series format: '#' lines say what each column is).
  std::string fl =
      "# flux balance per output (docs/exhumation.md); flux_in = " + fmt::format("{}", res.flux_in) +
      " d^2/sqrt(d/g), steady_output = " + std::to_string(flux.steady_output) +
      "\n# eroded_area [d^2] and eroded_count since the previous output; flux_out, flux_out_mean [d^2/sqrt(d/g)]; "
      "flux_ratio = flux_out_mean / flux_in; steady: 1 from the steady output on\n"
      "output,step,time,S,eroded_area,eroded_count,flux_out,flux_out_mean,flux_ratio,steady\n";
  for (std::size_t t = 0; t < nt; ++t)
    fl += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", t, recs[t].step, recs[t].time, recs[t].S, recs[t].eroded_area,
                      recs[t].eroded_count, num(flux.flux_out[t]), num(flux.mean_out[t]), num(flux.ratio[t]),
                      flux.steady_output >= 0 && static_cast<std::int64_t>(t) >= flux.steady_output ? 1 : 0);
  write_file_atomically(dir / "analysis_flux.csv", fl);

  std::string co =
      "# per output and surface column (docs/exhumation.md); x [h0] column centre from the S-point; elevation, "
      "surface_max_depth [h0]; cum_eroded_area [d^2]; surface ages and jump totals [sqrt(d/g)] for each closure depth "
      "h (in h0) in the column names\noutput,time,column,x,elevation,surface_id,surface_max_depth,cum_eroded_area,"
      "cum_eroded_count";
  for (double h : p.closure)
    co += fmt::format(",surface_age_{0},surface_unreset_{0},jump_count_{0},jump_total_{0}", h);
  co += "\n";
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& r = recs[t];
    for (std::size_t c = 0; c < ncol; ++c) {
      co += fmt::format("{},{},{},{},{},{},{},{},{}", t, r.time, c, col_x[c], num(r.elevation[c]), r.top_id[c],
                        num(r.top_max_depth[c]), r.cum_eroded_area[c], r.cum_eroded_count[c]);
      for (std::size_t i = 0; i < nc; ++i) {
        const std::size_t cell = i * ncol + c;
        co += fmt::format(",{},{},{},{}", num(r.surface_age[cell]), r.surface_unreset[cell], r.jump_count[cell],
                          r.jump_total[cell]);
      }
      co += "\n";
    }
  }
  write_file_atomically(dir / "analysis_columns.csv", co);

  std::string rm_csv =
      "# removals.csv rows with reason eroded, with the disc's values at the last output that saw it "
      "(last_output -1: none); x, y, depth, max_depth [h0]; ages [sqrt(d/g)]\nstep,time,id,x,y,column,last_output,"
      "depth,max_depth";
  for (double h : p.closure) rm_csv += fmt::format(",age_{0},unreset_{0}", h);
  rm_csv += "\n";
  for (std::size_t k = 0; k < er.size(); ++k) {
    rm_csv += fmt::format("{},{},{},{},{},{},{},{},{}", rstep[k], rt[k], rid[k], rx[k], ry[k], rcol[k], rlast[k],
                          num(rd[k]), num(rm[k]));
    for (std::size_t i = 0; i < nc; ++i) rm_csv += fmt::format(",{},{}", num(ra[k * nc + i]), ru[k * nc + i]);
    rm_csv += "\n";
  }
  write_file_atomically(dir / "analysis_removals.csv", rm_csv);
}

}  // namespace orogen
