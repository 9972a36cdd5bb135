#include "exhumation/analysis_state.hpp"

#include <stdexcept>
#include <type_traits>

#include "io/archive_fields.hpp"
#include "io/binary_archive.hpp"

namespace orogen {
namespace {

// The file's records, each listed once with its key for both the save and the load
// (io/archive_fields.hpp): the run and the settings, the tracker's own, the per-output rows
// and the bookkeeping of the files.
template <class State, class F>
void state_fields(State& s, F&& f) {
  auto& res = s.results;
  f("run_identity", s.run_identity);
  f("closure", res.settings.closure);
  f("flux_window", res.settings.flux_window);
  f("steady_fraction", res.settings.steady_fraction);
  f("particle_stride", res.settings.particle_stride);
  f("trajectory_output", res.settings.trajectory_output);
  f("flux_in", res.flux_in);
  f("v", res.v);
  f("solid_fraction", res.solid_fraction);
  if constexpr (!std::is_const_v<State>) {  // a load: the tracker of the settings just read
    ExhumationParams p;
    p.closure = res.settings.closure;
    p.particle_stride = res.settings.particle_stride;
    s.tracker = ExhumationTracker(p);
  }
  ExhumationTracker::fields(s.tracker, f);
  f("r_step", column(res.outputs, &OutputSummary::step));
  f("r_count", column(res.outputs, &OutputSummary::eroded_count));
  f("r_time", column(res.outputs, &OutputSummary::time));
  f("r_S", column(res.outputs, &OutputSummary::S));
  f("r_area", column(res.outputs, &OutputSummary::eroded_area));
  f("particle_ids", res.particle_ids);
  f("columns_csv_bytes", res.columns_csv_bytes);
}

}  // namespace

void save_analysis_state(const std::filesystem::path& path, const AnalysisState& s) {
  ArchiveWriter w;
  state_fields(s, ArchiveSaver(w));
  w.finish(path);
}

AnalysisState load_analysis_state(const std::filesystem::path& path) {
  const ArchiveReader in(path);
  AnalysisState s;
  state_fields(s, ArchiveLoader(in));
  const auto damaged = [&](const std::string& what) {
    return std::runtime_error("analysis state " + path.string() + ": " + what);
  };
  try {
    s.tracker.check_loaded();
  } catch (const std::runtime_error& e) {
    throw damaged(e.what());
  }
  if (static_cast<std::int64_t>(s.results.outputs.size()) != s.tracker.outputs_seen())
    throw damaged("output count damaged");
  return s;
}

}  // namespace orogen
