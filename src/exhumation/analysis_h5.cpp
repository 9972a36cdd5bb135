#include "exhumation/analysis_h5.hpp"

#include <algorithm>
#include <limits>

#include "exhumation/flux_balance.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_labelled.hpp"

namespace orogen {

namespace {

using h5::Shape;
using h5::VarInfo;
using Strings = std::vector<std::string>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
const std::string kAge = "model time since the particle was last deeper than the closure depth";

// Chunks: one output's row of a time series is whole chunks, so that appending an output
// never rewrites an earlier one; a particle row is cut into chunks of kParticleChunk discs,
// small enough that a thinned row (--particle-stride) does not fill whole chunks with NaN,
// and discs not alive in an output cost no disk where whole chunks are absent.
constexpr hsize_t kParticleChunk = 4096, kTimeChunk = 1024, kRemovalChunk = 4096;

enum class Type { F64, F32, I64, U8 };

struct Var {
  std::string name;
  Strings dims;
  Type type;
  VarInfo info;
};

std::vector<Var> variables() {
  const Strings t = {"time"}, tc = {"time", "column"}, tcc = {"time", "closure", "column"}, tp = {"time", "particle"},
                tr = {"time", "trajectory"}, r = {"removal"};
  return {
      {"step", t, Type::I64, {"1", "model time step of the output"}},
      {"S", t, Type::F64, {"1", "normalised convergence v t / h0"}},
      {"eroded_area", t, Type::F64, {"d^2", "disc area eroded since the previous output"}},
      {"eroded_count", t, Type::F64, {"1", "discs eroded since the previous output"}},
      {"flux_out", t, Type::F64, {"d^2/sqrt(d/g)", "eroded disc area per time over the last output interval"}},
      {"flux_out_mean", t, Type::F64,
       {"d^2/sqrt(d/g)", "eroded disc area per time over the last flux_window output intervals"}},
      {"flux_ratio", t, Type::F64, {"1", "flux_out_mean / flux_in (flux_in = speed h0 solid_fraction, thesis eq. 6.1)"}},
      {"elevation", tc, Type::F64, {"h0", "surface: top of the highest disc in the column (NaN: empty)"}},
      {"surface_id", tc, Type::I64, {"1", "id of the disc at the surface (-1: empty column)"}},
      {"surface_max_depth", tc, Type::F64, {"h0", "maximum depth ever reached by the disc at the surface"}},
      {"cum_eroded_area", tc, Type::F64, {"d^2", "disc area eroded from the column up to this output"}},
      {"cum_eroded_count", tc, Type::I64, {"1", "discs eroded from the column up to this output"}},
      {"deposit_thickness", tc, Type::F64,
       {"h0", "sediment laid by the surface laws (surface.deposition) in the column now: its discs' area over the "
              "column width"}},
      {"deposit_age", tc, Type::F64,
       {"sqrt(d/g)", "area-weighted mean age of the sediment in the column (NaN: none)"}},
      {"deposition_time", {"particle"}, Type::F64,
       {"sqrt(d/g)", "model time the disc was laid as sediment (surface.deposition); NaN: not a deposit"}},
      {"surface_age", tcc, Type::F64, {"sqrt(d/g)", "age of the disc at the surface: " + kAge}},
      {"surface_unreset", tcc, Type::U8, {"1", "1: the disc at the surface was never deeper than the closure depth"}},
      {"jump_count", tcc, Type::I64, {"1", "outputs so far at which the surface age of the column fell (a jump)"}},
      {"jump_total", tcc, Type::F64, {"sqrt(d/g)", "sum of the falls of surface age so far"}},
      {"jump_mean", tcc, Type::F64, {"sqrt(d/g)", "jump_total / jump_count (NaN: no jump yet)"}},
      {"x", tp, Type::F32, {"h0", "disc centre x, from the S-point"}},
      {"y", tp, Type::F32, {"h0", "disc centre elevation above the base"}},
      {"depth", tp, Type::F32, {"h0", "depth of the disc centre below the surface of its column"}},
      {"max_depth", tp, Type::F32, {"h0", "largest depth reached up to this output"}},
      {"age", {"time", "closure", "particle"}, Type::F32,
       {"sqrt(d/g)", kAge + " (un-reset discs: since their first output)"}},
      {"trajectory_x", tr, Type::F32, {"h0", "x of the disc"}},
      {"trajectory_y", tr, Type::F32, {"h0", "elevation of the disc centre"}},
      {"trajectory_depth", tr, Type::F32, {"h0", "depth of the disc below the surface"}},
      {"removal_id", r, Type::I64, {"1", "disc id"}},
      {"removal_step", r, Type::I64, {"1", "time step of the erosion"}},
      {"removal_time", r, Type::F64, {"sqrt(d/g)", "model time of the erosion"}},
      {"removal_x", r, Type::F64, {"h0", "x when eroded"}},
      {"removal_y", r, Type::F64, {"h0", "elevation when eroded"}},
      {"removal_column", r, Type::I64, {"1", "column index (-1: outside the grid)"}},
      {"removal_last_output", r, Type::I64,
       {"1", "last output that saw the disc, whose values follow (-1: none, values NaN)"}},
      {"removal_depth", r, Type::F64, {"h0", "depth at that output"}},
      {"removal_max_depth", r, Type::F64, {"h0", "maximum depth up to that output"}},
      {"removal_age", {"removal", "closure"}, Type::F64, {"sqrt(d/g)", kAge + " at that output"}},
      {"removal_unreset", {"removal", "closure"}, Type::U8, {"1", "1: never deeper than the closure depth"}},
  };
}

Shape chunk_of(const Strings& dims, const ExhumationParams& p) {
  const bool traj = std::find(dims.begin(), dims.end(), "trajectory") != dims.end();
  Shape c;
  for (const auto& d : dims) {
    if (d == "time") c.push_back(dims.size() == 1 ? kTimeChunk : traj ? 64 : 1);
    else if (d == "column") c.push_back(std::min<hsize_t>(std::max<std::size_t>(p.n_columns, 1), 4096));
    else if (d == "closure") c.push_back(dims.back() == "particle" ? 1 : p.closure.size());
    else if (d == "particle") c.push_back(kParticleChunk);
    else if (d == "trajectory") c.push_back(256);
    else c.push_back(dims.size() == 1 ? kRemovalChunk : 1024);  // removal
  }
  return c;
}

template <class T>
std::span<const T> view(const std::vector<T>& v) {
  return std::span<const T>(v);
}

std::vector<double> column_x(const ExhumationParams& p) {
  std::vector<double> x;
  for (std::size_t c = 0; c < p.n_columns; ++c)
    x.push_back((p.x_lo + (static_cast<double>(c) + 0.5) * p.column_width) / p.h0);
  return x;
}

}  // namespace

void create_analysis_h5(hid_t root, const std::string& run_identity, const AnalysisResults& res,
                        const ExhumationParams& p) {
  h5::set_attr_string(root, "title", "orogen exhumation analysis (docs/exhumation.md)");
  h5::set_attr_string(root, "run_identity", run_identity);
  h5::set_attr_double(root, "h0", p.h0);
  h5::set_attr_int64(root, "particle_stride", p.particle_stride);
  h5::set_attr_int64(root, "flux_window", res.settings.flux_window);
  h5::set_attr_double(root, "steady_fraction", res.settings.steady_fraction);
  h5::create_dimension<double>(root, "time", kTimeChunk, {"sqrt(d/g)", "model time of the output"});
  h5::create_dimension<double>(root, "column", chunk_of({"column"}, p)[0],
                               {"h0", "x of the column centre, from the S-point"});
  h5::create_dimension<double>(root, "closure", p.closure.size(), {"h0", "closure depth h_i below the local surface"});
  h5::create_dimension<std::int64_t>(root, "particle", kParticleChunk,
                                     {"1", "stable disc id, in order of first appearance (NaN where absent)"});
  h5::create_dimension<std::int64_t>(root, "trajectory", 256,
                                     {"1", "id of a disc at the surface at output trajectory_output"});
  h5::create_dimension<std::int64_t>(root, "removal", kRemovalChunk,
                                     {"1", "row of the eroded discs, in removals.csv order"});
  const auto col_x = column_x(p);
  h5::write_all<double>(root, "column", {col_x.size()}, view(col_x));
  h5::write_all<double>(root, "closure", {p.closure.size()}, view(p.closure));
  for (const auto& v : variables()) {
    const Shape chunk = chunk_of(v.dims, p);
    switch (v.type) {
      case Type::F64: h5::create_variable<double>(root, v.name, v.dims, chunk, v.info); break;
      case Type::F32: h5::create_variable<float>(root, v.name, v.dims, chunk, v.info); break;
      case Type::I64: h5::create_variable<std::int64_t>(root, v.name, v.dims, chunk, v.info); break;
      case Type::U8: h5::create_variable<std::uint8_t>(root, v.name, v.dims, chunk, v.info); break;
    }
    // The fixed dimensions have their length from the start.
    Shape s;
    for (const auto& d : v.dims) s.push_back(d == "column" ? p.n_columns : d == "closure" ? p.closure.size() : 0);
    h5::resize(root, v.name, s);
  }
}

bool check_analysis_h5(hid_t root, const std::string& run_identity, const AnalysisResults& res,
                       const ExhumationParams& p) {
  const auto mismatch = [](const std::string& what) { throw h5::Error("analysis.h5 does not continue the state: " + what); };
  if (h5::get_attr_string(root, "run_identity") != run_identity) mismatch("another run");
  if (h5::get_attr_int64(root, "particle_stride") != p.particle_stride) mismatch("another particle stride");
  if (h5::read_block<double>(root, "closure", {0}, {h5::shape(root, "closure").at(0)}) != p.closure)
    mismatch("other closure depths");
  if (h5::read_block<double>(root, "column", {0}, {h5::shape(root, "column").at(0)}) != column_x(p))
    mismatch("another column grid");
  const hsize_t nt = res.outputs.size(), np = res.particle_ids.size();
  const hsize_t file_nt = h5::shape(root, "time").at(0), file_np = h5::shape(root, "particle").at(0);
  if (file_nt < nt) mismatch("fewer outputs than the state counts");
  if (file_np < np) mismatch("fewer discs than the state counts");
  if (h5::read_block<std::int64_t>(root, "particle", {0}, {np}) != res.particle_ids) mismatch("other disc ids");
  if (!h5::exists(root, "deposition_time")) mismatch("a file made before the deposits' datasets");
  return file_nt > nt || file_np > np;
}

void trim_analysis_h5(hid_t root, const AnalysisResults& res) {
  const hsize_t nt = res.outputs.size(), np = res.particle_ids.size();
  h5::resize(root, "time", {nt});
  h5::resize(root, "particle", {np});
  for (const auto& v : variables()) {
    if (v.dims == Strings{"particle"}) h5::resize(root, v.name, {np});
    if (v.dims.front() != "time" || v.dims.back() == "trajectory") continue;
    Shape s = h5::shape(root, v.name);
    s.front() = nt;
    if (v.dims.back() == "particle") s.back() = np;
    h5::resize(root, v.name, s);
  }
}

void append_analysis_h5(hid_t root, const OutputRecord& r, AnalysisResults& res,
                        std::unordered_map<std::int64_t, std::size_t>& slot, const ExhumationParams& p) {
  const hsize_t t = res.outputs.size(), nc = p.closure.size();
  res.outputs.push_back(
      {.step = r.step, .time = r.time, .S = r.S, .eroded_area = r.eroded_area, .eroded_count = r.eroded_count});

  // Discs seen for the first time extend the particle dimension (ascending id within an output).
  const hsize_t np_before = res.particle_ids.size();
  std::vector<std::int64_t> fresh;
  for (auto id : r.particle_id)
    if (!slot.contains(id)) fresh.push_back(id);
  std::sort(fresh.begin(), fresh.end());
  for (auto id : fresh) {
    slot.emplace(id, res.particle_ids.size());
    res.particle_ids.push_back(id);
  }
  const hsize_t np = res.particle_ids.size();
  if (np > np_before) {
    h5::resize(root, "particle", {np});
    h5::write_block<std::int64_t>(root, "particle", {np_before}, {np - np_before}, view(fresh));
    // When each new disc was laid, if it is a deposit: a constant of the disc.
    std::unordered_map<std::int64_t, double> laid;
    for (std::size_t j = 0; j < r.particle_id.size(); ++j) laid.emplace(r.particle_id[j], r.particle_deposition_time[j]);
    std::vector<double> times;
    for (auto id : fresh) times.push_back(laid.at(id));
    h5::resize(root, "deposition_time", {np});
    h5::write_block<double>(root, "deposition_time", {np_before}, {np - np_before}, view(times));
  }

  const auto scalar = [&](const std::string& name, auto value) {
    h5::resize(root, name, {t + 1});
    h5::write_block<decltype(value)>(root, name, {t}, {1}, std::span(&value, 1));
  };
  scalar("time", r.time);
  scalar("step", r.step);
  scalar("S", r.S);
  scalar("eroded_area", r.eroded_area);
  scalar("eroded_count", static_cast<double>(r.eroded_count));

  const auto row = [&](const std::string& name, const auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    Shape s = h5::shape(root, name), start(s.size(), 0), count = s;
    s.front() = t + 1;
    start.front() = t;
    count.front() = 1;
    h5::resize(root, name, s);
    h5::write_block<T>(root, name, start, count, view(values));
  };
  row("elevation", r.elevation);
  row("surface_id", r.top_id);
  row("surface_max_depth", r.top_max_depth);
  row("cum_eroded_area", r.cum_eroded_area);
  row("cum_eroded_count", r.cum_eroded_count);
  row("deposit_thickness", r.deposit_thickness);
  row("deposit_age", r.deposit_age);
  row("surface_age", r.surface_age);
  row("surface_unreset", r.surface_unreset);
  row("jump_count", r.jump_count);
  row("jump_total", r.jump_total);
  std::vector<double> jm(r.jump_total.size());
  for (std::size_t k = 0; k < jm.size(); ++k)
    jm[k] = r.jump_count[k] > 0 ? r.jump_total[k] / static_cast<double>(r.jump_count[k]) : kNaN;
  row("jump_mean", jm);

  // The particle row: only the span of slots holding a disc now is written (NaN between).
  for (const char* name : {"x", "y", "depth", "max_depth"}) h5::resize(root, name, {t + 1, np});
  h5::resize(root, "age", {t + 1, nc, np});
  const std::size_t kept = r.particle_id.size();
  if (kept == 0) return;
  std::vector<std::size_t> at(kept);
  for (std::size_t j = 0; j < kept; ++j) at[j] = slot.at(r.particle_id[j]);
  const auto [lo_it, hi_it] = std::minmax_element(at.begin(), at.end());
  const std::size_t lo = *lo_it, width = *hi_it - lo + 1;
  std::vector<float> buf(width * nc);
  const auto put = [&](const char* name, const std::vector<float>& v) {
    std::fill(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(width), kNaNf);
    for (std::size_t j = 0; j < kept; ++j) buf[at[j] - lo] = v[j];
    h5::write_block<float>(root, name, {t, lo}, {1, width}, std::span<const float>(buf.data(), width));
  };
  put("x", r.particle_x);
  put("y", r.particle_y);
  put("depth", r.particle_depth);
  put("max_depth", r.particle_max_depth);
  std::fill(buf.begin(), buf.end(), kNaNf);
  for (std::size_t i = 0; i < nc; ++i)
    for (std::size_t j = 0; j < kept; ++j) buf[i * width + at[j] - lo] = r.particle_age[i * kept + j];
  h5::write_block<float>(root, "age", {t, 0, lo}, {1, nc, width}, view(buf));
}

void finish_analysis_h5(hid_t root, const AnalysisResults& res, const std::unordered_map<std::int64_t, std::size_t>& slot,
                        const ExhumationTracker& tracker) {
  const auto& p = tracker.params();
  const std::size_t nt = res.outputs.size(), nc = p.closure.size();

  std::vector<double> time, area;
  for (const auto& o : res.outputs) { time.push_back(o.time); area.push_back(o.eroded_area); }
  const FluxBalance flux =
      flux_balance(time, area, res.flux_in, res.settings.flux_window, res.settings.steady_fraction);
  h5::write_all<double>(root, "flux_out", {nt}, view(flux.flux_out));
  h5::write_all<double>(root, "flux_out_mean", {nt}, view(flux.mean_out));
  h5::write_all<double>(root, "flux_ratio", {nt}, view(flux.ratio));
  h5::set_attr_double(root, "flux_in", res.flux_in);
  h5::set_attr_double(root, "solid_fraction", res.solid_fraction);
  h5::set_attr_double(root, "speed", res.v);
  h5::set_attr_int64(root, "steady_output", flux.steady_output);

  // Trajectories: the discs at the surface at the chosen output, back through time, read
  // back from the particle series one output at a time.
  std::int64_t at = res.settings.trajectory_output < 0 ? static_cast<std::int64_t>(nt) - 1 : res.settings.trajectory_output;
  at = std::min<std::int64_t>(at, static_cast<std::int64_t>(nt) - 1);
  std::vector<std::int64_t> traj;
  std::vector<std::size_t> traj_slot;
  if (at >= 0)
    for (auto id : h5::read_block<std::int64_t>(root, "surface_id", {static_cast<hsize_t>(at), 0}, {1, p.n_columns}))
      if (const auto s = slot.find(id); id >= 0 && s != slot.end()) {
        traj.push_back(id);
        traj_slot.push_back(s->second);
      }
  h5::set_attr_int64(root, "trajectory_output", at);
  h5::write_all<std::int64_t>(root, "trajectory", {traj.size()}, view(traj));
  const std::size_t ntr = traj.size();
  std::vector<float> tx(nt * ntr), ty(nt * ntr), td(nt * ntr);
  if (ntr > 0) {
    const auto [lo_it, hi_it] = std::minmax_element(traj_slot.begin(), traj_slot.end());
    const hsize_t lo = *lo_it, width = *hi_it - lo + 1;
    for (std::size_t t = 0; t < nt; ++t)
      for (auto [name, out] : {std::pair{"x", &tx}, std::pair{"y", &ty}, std::pair{"depth", &td}}) {
        const auto v = h5::read_block<float>(root, name, {t, lo}, {1, width});
        for (std::size_t j = 0; j < ntr; ++j) (*out)[t * ntr + j] = v[traj_slot[j] - lo];
      }
  }
  h5::write_all<float>(root, "trajectory_x", {nt, ntr}, view(tx));
  h5::write_all<float>(root, "trajectory_y", {nt, ntr}, view(ty));
  h5::write_all<float>(root, "trajectory_depth", {nt, ntr}, view(td));

  // Removals by erosion, with the disc's values at the last output that saw it.
  const auto& er = tracker.eroded();
  const std::size_t nr = er.size();
  std::vector<std::int64_t> rid, rstep, rcol, rlast, rindex;
  std::vector<double> rt, rx, ry, rd, rm, ra(nr * nc);
  std::vector<std::uint8_t> ru(nr * nc);
  for (std::size_t k = 0; k < nr; ++k) {
    const auto& e = er[k];
    rindex.push_back(static_cast<std::int64_t>(k));
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
  h5::write_all<std::int64_t>(root, "removal", {nr}, view(rindex));
  h5::write_all<std::int64_t>(root, "removal_id", {nr}, view(rid));
  h5::write_all<std::int64_t>(root, "removal_step", {nr}, view(rstep));
  h5::write_all<double>(root, "removal_time", {nr}, view(rt));
  h5::write_all<double>(root, "removal_x", {nr}, view(rx));
  h5::write_all<double>(root, "removal_y", {nr}, view(ry));
  h5::write_all<std::int64_t>(root, "removal_column", {nr}, view(rcol));
  h5::write_all<std::int64_t>(root, "removal_last_output", {nr}, view(rlast));
  h5::write_all<double>(root, "removal_depth", {nr}, view(rd));
  h5::write_all<double>(root, "removal_max_depth", {nr}, view(rm));
  h5::write_all<double>(root, "removal_age", {nr, nc}, view(ra));
  h5::write_all<std::uint8_t>(root, "removal_unreset", {nr, nc}, view(ru));
}

}  // namespace orogen
