#include "exhumation/analyze_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "config/config.hpp"
#include "config/run_identity.hpp"
#include "exhumation/analysis_state.hpp"
#include "exhumation/analysis_writer.hpp"
#include "io/file_lock.hpp"
#include "io/snapshot_reader.hpp"
#include "util/command_error.hpp"

namespace orogen {

namespace fs = std::filesystem;

namespace {

// A refusal with its exit code (2 bad input, 1 I/O).
using AnalyzeError = CommandError;  // its exit code chosen where it is thrown

std::string list(const std::vector<double>& v) {
  std::string s;
  for (double x : v) {
    if (!s.empty()) s += ',';
    s += fmt::format("{}", x);
  }
  return s;
}

struct ErosionLog {
  std::vector<ErosionEvent> events;
  // Every removal up to this step is listed (the run writes removals.csv after an output's
  // snapshot, so a running run's newest output may not be covered yet); -1: not said (older
  // runs, or no file: everything up to now).
  std::int64_t through_step = -1;
};

// removals.csv rows with a reason "eroded..." (the threshold or a surface law: step, time, id, cluster_id, x, y, reason).
ErosionLog read_erosion(const fs::path& path) {
  ErosionLog log;
  auto& out = log.events;
  std::ifstream in(path);
  if (!in) return log;  // a run that removed nothing yet may have none
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    ++row;
    if (line.starts_with("# through_step: ")) {
      try {
        log.through_step = std::stoll(line.substr(16));
      } catch (const std::exception&) {
        throw AnalyzeError(2, fmt::format("{} line {}: not a step: {}", path.string(), row, line));
      }
      continue;
    }
    if (line.empty() || line[0] == '#' || line.starts_with("step,")) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    if (f.size() != 7) throw AnalyzeError(2, fmt::format("{} line {}: {} fields, 7 expected", path.string(), row, f.size()));
    if (!f[6].starts_with("eroded")) continue;  // the threshold's and each surface law's
    try {
      out.push_back({.step = std::stoll(f[0]), .time = std::stod(f[1]), .id = std::stoll(f[2]), .x = std::stod(f[4]),
                     .y = std::stod(f[5])});
    } catch (const std::exception&) {
      throw AnalyzeError(2, fmt::format("{} line {}: not a row of numbers: {}", path.string(), row, line));
    }
  }
  return log;
}

OutputDiscs discs_of(const Snapshot& s) {
  OutputDiscs d;
  d.step = s.step;
  d.time = s.time;
  const auto S = s.attrs.find("S");
  d.S = S == s.attrs.end() ? std::numeric_limits<double>::quiet_NaN() : S->second;
  d.id = s.id;
  d.x = s.field("x");
  d.y = s.field("y");
  d.radius = s.field("radius");
  if (const auto laid = s.fields.find("deposition_time"); laid != s.fields.end()) d.deposition_time = laid->second;
  return d;
}

// A fresh analysis: the column grid and the incoming flux from output 0 and the configuration.
AnalysisState start(const AnalysisSettings& settings, const Config& config, double h0, const Snapshot& first,
                    const std::string& identity) {
  const OutputDiscs d = discs_of(first);
  if (d.id.empty()) throw AnalyzeError(2, "output 0 holds no discs");
  double area = 0, rsum = 0;
  for (double r : d.radius) { area += std::numbers::pi * r * r; rsum += r; }
  const auto [lo, hi] = std::minmax_element(d.x.begin(), d.x.end());
  ExhumationParams p;
  p.h0 = h0;
  p.closure = settings.closure;
  p.mean_radius = rsum / static_cast<double>(d.radius.size());
  p.column_width = config.get_float("layer.column_width_factor") * p.mean_radius;
  // Material enters from the pro side (tiles stamped beyond the active window, which moves
  // pro-ward as the wedge widens) and moves retro-ward at v: the grid reaches s_end + one tile
  // length pro-ward of the first layer.
  p.x_lo = std::floor(*lo - (config.get_float("wedge.s_end") + config.get_float("wedge.tile_length")) * h0);
  const double x_hi = std::max(*hi, config.get_float("wedge.retro_length") * h0) + 1.0;
  p.n_columns = static_cast<std::size_t>(std::ceil((x_hi - p.x_lo) / p.column_width));
  p.particle_stride = settings.particle_stride;
  AnalysisState s{.run_identity = identity, .results = {}, .tracker = ExhumationTracker(p)};
  s.results.settings = settings;
  s.results.v = config.get_float("wedge.speed");
  s.results.solid_fraction = area / ((*hi - *lo) * h0);
  s.results.flux_in = s.results.v * h0 * s.results.solid_fraction;
  return s;
}

// The temporary files (NAME.tmp-PID) a killed call left of analyze's own files.
void remove_own_temporary_files(const fs::path& dir) {
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("analysis") && name.find(".tmp-") != std::string::npos) stale.push_back(entry.path());
  }
  for (const auto& p : stale) fs::remove(p);
}

bool same_settings(const AnalysisSettings& a, const AnalysisSettings& b) {
  return a.closure == b.closure && a.flux_window == b.flux_window && a.steady_fraction == b.steady_fraction &&
         a.particle_stride == b.particle_stride && a.trajectory_output == b.trajectory_output;
}

int analyze(const AnalyzeOptions& options) {
  const fs::path& dir = options.dir;
  if (dir.empty() || !fs::is_directory(dir))
    throw AnalyzeError(2, fmt::format("{}: no such folder; analyze takes the folder of a wedge run", dir.string()));
  const fs::path index = dir / "snapshots.h5", config_path = dir / "config.toml";
  if (!fs::is_regular_file(index) || !fs::is_regular_file(config_path))
    throw AnalyzeError(2, fmt::format("{} is not a run folder (no {}); analyze takes the folder of a wedge run",
                                      dir.string(), fs::is_regular_file(index) ? "config.toml" : "snapshots.h5"));
  // One analysis at a time writes a folder: it locks the folder itself (flock, nothing
  // written; a running run holds its run.lock and writes its outputs meanwhile, of which
  // analyze reads only the complete ones).
  FileLock lock(dir, FileLock::On::Folder);
  if (lock.open_error() != 0)
    throw AnalyzeError(1, fmt::format("cannot open {}: {}", dir.string(), std::strerror(lock.open_error())));
  if (!lock.locked())
    throw AnalyzeError(2, fmt::format("{} is being analysed by another orogen process (it holds a lock on the folder); "
                                      "wait for it to end",
                                      dir.string()));
  std::optional<Config> config;
  try {
    config = Config::load(config_path, {});
  } catch (const std::exception& e) {
    throw AnalyzeError(2, fmt::format("{}: {}", config_path.string(), e.what()));
  }
  // The run's [analysis] keys, then what the command line gives.
  struct Settings : AnalyzeOptions {
    AnalysisSettings settings;
  } o;
  static_cast<AnalyzeOptions&>(o) = options;
  try {
    o.settings = analysis_settings(*config);
  } catch (const std::exception& e) {
    throw AnalyzeError(2, fmt::format("{}: {}", config_path.string(), e.what()));
  }
  if (options.closure) o.settings.closure = *options.closure;
  if (options.flux_window) o.settings.flux_window = *options.flux_window;
  if (options.particle_stride) o.settings.particle_stride = *options.particle_stride;
  if (options.steady_fraction) o.settings.steady_fraction = *options.steady_fraction;
  if (options.trajectory_output) o.settings.trajectory_output = *options.trajectory_output;
  if (const std::string e = analysis_settings_error(o.settings); !e.empty()) throw AnalyzeError(2, e);
  const std::string experiment = config->get_string("run.experiment");
  if (experiment != "wedge")
    throw AnalyzeError(2, fmt::format("{} is a {} run (run.experiment = \"{}\"); analyze takes a wedge run",
                                      dir.string(), experiment, experiment));
  std::optional<SnapshotReader> reader;
  try {
    reader.emplace(index);
  } catch (const SnapshotFormatError& e) {
    throw AnalyzeError(2, fmt::format("{} is not a snapshot file this orogen reads: {}", index.string(), e.what()));
  } catch (const std::exception& e) {
    throw AnalyzeError(1, fmt::format("{} is not a readable orogen snapshot file: {}", index.string(), e.what()));
  }
  const auto& meta = reader->metadata();
  const auto h0_it = meta.numbers.find("h0");
  if (h0_it == meta.numbers.end() || !(h0_it->second > 0))
    throw AnalyzeError(2, fmt::format("{} has no positive h0 attribute", index.string()));
  const double h0 = h0_it->second;
  for (double h : o.settings.closure)
    if (h > config->get_float("layer.thickness") / h0 + 1e-12 || h > 1.0)
      throw AnalyzeError(2, fmt::format("closure depths {}: {} h0 is below the base of the layer (thickness 1 h0); "
                                        "closure depths must lie within the layer",
                                        list(o.settings.closure), h));
  const auto id_it = meta.strings.find("run_identity");
  const std::string identity = id_it == meta.strings.end() ? "" : id_it->second;
  // Early runs stored no identity: nothing to compare then.
  if (const std::string ours = run_identity(*config); !identity.empty() && identity != ours)
    throw AnalyzeError(2, fmt::format("{} and {} are not of one run (identities {} and {})", index.string(),
                                      config_path.string(), identity, ours));
  const std::int64_t count = reader->count();
  if (count == 0) throw AnalyzeError(2, fmt::format("{} lists no complete output yet", index.string()));

  // Output k, refused if it was copied in from another run.
  const std::string config_toml = config->to_toml();
  const auto read = [&](std::int64_t k) {
    std::string foreign;
    try {
      foreign = foreign_output(*reader, k, reader->stamp(k), identity, config_toml);
      if (foreign.empty()) return reader->read(k);
    } catch (const std::exception& e) {
      throw AnalyzeError(1, fmt::format("{}: output {} cannot be read (corrupt or truncated): {}", index.string(), k, e.what()));
    }
    throw AnalyzeError(2, foreign);
  };
  remove_own_temporary_files(dir);  // what killed calls left; every check above has passed
  const fs::path state_path = dir / "analysis_state.bin";
  std::optional<AnalysisState> state;
  if (fs::exists(state_path)) {
    try {
      AnalysisState old = load_analysis_state(state_path);
      // Only a state of this run, with these settings and not ahead of the index, is continued.
      if (old.run_identity == identity && same_settings(old.results.settings, o.settings) &&
          old.tracker.outputs_seen() <= count)
        state.emplace(std::move(old));
    } catch (const std::exception& e) {
      if (!o.quiet) std::cerr << "note: " << state_path.string() << " not used (" << e.what() << "); starting over\n";
    }
  }
  // removals.csv after the index: it is never older than the outputs it says it covers.
  const ErosionLog erosion = read_erosion(dir / "removals.csv");
  // A state continues only with the files it describes; otherwise everything starts over.
  std::optional<AnalysisWriter> writer;
  if (state) {
    try {
      writer.emplace(AnalysisWriter::resume(dir, identity, state->results, state->tracker.params()));
    } catch (const std::exception& e) {
      if (!o.quiet) std::cerr << "note: " << state_path.string() << " not used (" << e.what() << "); starting over\n";
      state.reset();
    }
  }
  if (!state) {
    state.emplace(start(o.settings, *config, h0, read(0), identity));
    writer.emplace(AnalysisWriter::fresh(dir, identity, state->results, state->tracker.params()));
  }
  const std::int64_t from = state->tracker.outputs_seen();
  try {
    for (std::int64_t k = from; k < count; ++k) {
      const Snapshot snap = read(k);
      if (erosion.through_step >= 0 && snap.step > erosion.through_step) break;  // the next call takes it
      const std::int64_t prev = state->tracker.last_step();
      std::vector<ErosionEvent> now;
      for (const auto& e : erosion.events)
        if (e.step > prev && e.step <= snap.step) now.push_back(e);
      writer->append(state->tracker.observe(discs_of(snap), now));
    }
    writer->commit(state->tracker);
    save_analysis_state(state_path, *state);
  } catch (const AnalyzeError&) {
    throw;
  } catch (const std::exception& e) {
    throw AnalyzeError(1, fmt::format("cannot write the analysis in {}: {}", dir.string(), e.what()));
  }
  if (!o.quiet)
    std::cout << fmt::format("analyze {}: {} outputs ({} new), {} eroded discs; analysis.h5 written\n", dir.string(),
                             state->tracker.outputs_seen(), state->tracker.outputs_seen() - from,
                             state->tracker.eroded().size());
  return 0;
}

}  // namespace

std::optional<std::vector<double>> parse_closure_depths(const std::string& text) {
  std::vector<double> out;
  std::string cell;
  for (std::size_t at = 0; at <= text.size(); ++at) {
    if (at < text.size() && text[at] != ',') {
      cell += text[at];
      continue;
    }
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(cell, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (cell.empty() || used != cell.size()) return std::nullopt;
    out.push_back(value);
    cell.clear();
  }
  return out;
}

AnalysisSettings analysis_settings(const Config& config) {
  AnalysisSettings s;
  const std::string& text = config.get_string("analysis.closure_depths");
  const auto closure = parse_closure_depths(text);
  if (!closure)
    throw ConfigError(fmt::format("analysis.closure_depths = \"{}\": not a comma-separated list of numbers; give "
                                  "depths in h0, e.g. \"0.15,0.3,0.5\"", text));
  s.closure = *closure;
  s.flux_window = config.get_int32("analysis.flux_window");
  s.steady_fraction = config.get_float("analysis.steady_fraction");
  s.particle_stride = config.get_int32("analysis.particle_stride");
  if (const std::string e = analysis_settings_error(s, true); !e.empty()) throw ConfigError(e);
  for (double h : s.closure)
    if (h > 1.0)
      throw ConfigError(fmt::format("analysis.closure_depths = \"{}\": {} h0 is below the base of the layer "
                                    "(thickness 1 h0); closure depths must lie within the layer", text, h));
  return s;
}

void check_in_run_analysis(const Config& config) {
  analysis_settings(config);  // a later `orogen analyze` reads them: refused now, not then
  if (config.get_bool("analysis.in_run") && config.get_string("run.experiment") != "wedge")
    throw ConfigError(fmt::format("analysis.in_run = true needs run.experiment = \"wedge\" (it is \"{}\"): the "
                                  "exhumation analysis is of wedge runs",
                                  config.get_string("run.experiment")));
}

std::string analysis_settings_error(const AnalysisSettings& s, bool from_config) {
  const std::string name = from_config ? "analysis.closure_depths =" : "--closure-depths";
  if (s.closure.empty()) return name + " is empty; give one or more depths in h0, e.g. 0.15,0.3,0.5";
  for (std::size_t i = 0; i < s.closure.size(); ++i) {
    if (!(s.closure[i] > 0))
      return fmt::format("{} {}: {} is not positive; closure depths are depths below the surface in "
                         "h0, each in (0, 1]", name, list(s.closure), s.closure[i]);
    if (i > 0 && !(s.closure[i] > s.closure[i - 1]))
      return fmt::format("{} {}: not in strictly ascending order; list them shallowest first", name,
                         list(s.closure));
  }
  if (s.flux_window < 1) return fmt::format("--flux-window {}: must be at least 1 output", s.flux_window);
  if (!(s.steady_fraction > 0) || !std::isfinite(s.steady_fraction))
    return fmt::format("--steady-fraction {}: must be a positive number (0.9: the eroded flux reaches 90% of v h0)",
                       s.steady_fraction);
  if (s.particle_stride < 1) return fmt::format("--particle-stride {}: must be at least 1", s.particle_stride);
  if (s.trajectory_output < -1) return fmt::format("--trajectory-output {}: must be an output index, or -1 for the last", s.trajectory_output);
  return "";
}

int analyze_command(const AnalyzeOptions& o) {
  return run_reporting_errors("analyze " + o.dir.string(), [&] { return analyze(o); });
}

}  // namespace orogen
