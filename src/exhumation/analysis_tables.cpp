#include "exhumation/analysis_tables.hpp"

#include <fmt/format.h>

#include <cmath>

#include "exhumation/flux_balance.hpp"
#include "io/atomic_file.hpp"

namespace orogen {

namespace {

std::string num(double v) { return std::isnan(v) ? "" : fmt::format("{}", v); }

}  // namespace

std::string columns_csv_header(const ExhumationParams& p) {
  std::string co =
      "# per output and surface column (docs/exhumation.md); x [h0] column centre from the S-point; elevation, "
      "surface_max_depth [h0]; cum_eroded_area [d^2]; surface ages and jump totals [sqrt(d/g)] for each closure depth "
      "h (in h0) in the column names\noutput,time,column,x,elevation,surface_id,surface_max_depth,cum_eroded_area,"
      "cum_eroded_count";
  for (double h : p.closure)
    co += fmt::format(",surface_age_{0},surface_unreset_{0},jump_count_{0},jump_total_{0}", h);
  return co + "\n";
}

std::string columns_csv_rows(std::size_t t, const OutputRecord& r, const ExhumationParams& p) {
  const std::size_t ncol = p.n_columns, nc = p.closure.size();
  std::string co;
  for (std::size_t c = 0; c < ncol; ++c) {
    const double x = (p.x_lo + (static_cast<double>(c) + 0.5) * p.column_width) / p.h0;
    co += fmt::format("{},{},{},{},{},{},{},{},{}", t, r.time, c, x, num(r.elevation[c]), r.top_id[c],
                      num(r.top_max_depth[c]), r.cum_eroded_area[c], r.cum_eroded_count[c]);
    for (std::size_t i = 0; i < nc; ++i) {
      const std::size_t cell = i * ncol + c;
      co += fmt::format(",{},{},{},{}", num(r.surface_age[cell]), r.surface_unreset[cell], r.jump_count[cell],
                        r.jump_total[cell]);
    }
    co += "\n";
  }
  return co;
}

void write_flux_csv(const std::filesystem::path& path, const AnalysisResults& res) {
  const auto& o = res.outputs;
  std::vector<double> time, area;
  for (const auto& r : o) { time.push_back(r.time); area.push_back(r.eroded_area); }
  const FluxBalance flux =
      flux_balance(time, area, res.flux_in, res.settings.flux_window, res.settings.steady_fraction);
  std::string fl =
      "# flux balance per output (docs/exhumation.md); flux_in = " + fmt::format("{}", res.flux_in) +
      " d^2/sqrt(d/g), steady_output = " + std::to_string(flux.steady_output) +
      "\n# eroded_area [d^2] and eroded_count since the previous output; flux_out, flux_out_mean [d^2/sqrt(d/g)]; "
      "flux_ratio = flux_out_mean / flux_in; steady: 1 from the steady output on\n"
      "output,step,time,S,eroded_area,eroded_count,flux_out,flux_out_mean,flux_ratio,steady\n";
  for (std::size_t t = 0; t < o.size(); ++t)
    fl += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", t, o[t].step, o[t].time, o[t].S, o[t].eroded_area,
                      o[t].eroded_count, num(flux.flux_out[t]), num(flux.mean_out[t]), num(flux.ratio[t]),
                      flux.steady_output >= 0 && static_cast<std::int64_t>(t) >= flux.steady_output ? 1 : 0);
  write_file_atomically(path, fl);
}

void write_removals_csv(const std::filesystem::path& path, const ExhumationTracker& tracker) {
  const auto& p = tracker.params();
  std::string rm =
      "# removals.csv rows with reason eroded, with the disc's values at the last output that saw it "
      "(last_output -1: none); x, y, depth, max_depth [h0]; ages [sqrt(d/g)]\nstep,time,id,x,y,column,last_output,"
      "depth,max_depth";
  for (double h : p.closure) rm += fmt::format(",age_{0},unreset_{0}", h);
  rm += "\n";
  for (const auto& e : tracker.eroded()) {
    rm += fmt::format("{},{},{},{},{},{},{},{},{}", e.event.step, e.event.time, e.event.id, e.event.x / p.h0,
                      e.event.y / p.h0, e.column, e.last_output, num(e.depth), num(e.max_depth));
    for (std::size_t i = 0; i < p.closure.size(); ++i) rm += fmt::format(",{},{}", num(e.age[i]), e.unreset[i]);
    rm += "\n";
  }
  write_file_atomically(path, rm);
}

}  // namespace orogen
