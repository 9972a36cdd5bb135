// Benchmark of `orogen analyze` (issue 15): a synthetic eroding wedge run of --particles discs
// and --outputs outputs (default 50,000 x 636, as the thesis's long runs E(V), E(VI)) is
// written once into --dir (kept for reuse with --reuse), then analysed from scratch and timed.
// See docs/performance.md ("Exhumation analysis") and docs/exhumation.md.
//
// The synthetic run: a layer of discs on a lattice, h0 = --rows discs thick, moved each output
// by a growing Gaussian uplift centred on the S-point and shifted retro-ward at the plate
// speed; discs rising above 2 h0 are eroded (logged in removals.csv) and the layer is fed at
// the pro end so that the count stays near --particles.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "exhumation/analyze_command.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot_writer.hpp"
#include "particles/discs.hpp"

using namespace orogen;
namespace fs = std::filesystem;

namespace {

struct Synthetic {
  int particles = 50000, outputs = 636, rows = 40;
};

void write_run(const fs::path& dir, const Synthetic& s) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const double h0 = s.rows, v = 0.025;
  const int columns = s.particles / s.rows;
  const double length = columns;  // discs of diameter 1 on a square lattice
  const double s_end = 21.0, t_end = s_end * h0 / v;
  const Config config = Config::load(std::nullopt, {"run.experiment=wedge", fmt::format("layer.thickness={}", h0),
                                                    fmt::format("wedge.s_end={}", s_end),
                                                    fmt::format("wedge.outputs={}", s.outputs - 1),
                                                    fmt::format("wedge.retro_length={}", length / 2 / h0),
                                                    "wedge.tile_length=1", "wedge.erosion_height=2"});
  write_file_atomically(dir / "config.toml", config.to_toml());
  SnapshotMetadata meta;
  meta.strings["experiment"] = "wedge";
  meta.strings["run_identity"] = "0000000000000000";
  meta.numbers["h0"] = h0;
  meta.numbers["x_split"] = 0;
  SnapshotWriter writer(dir / "snapshots.h5", meta, {.deflate = 0});
  // Lattice sites (x0, y0) of the discs alive; a disc's position is its site moved.
  std::vector<std::int64_t> id;
  std::vector<double> x0, y0;
  std::int64_t next_id = 0;
  double pro_end = -length / 2;
  for (int c = 0; c < columns; ++c)
    for (int r = 0; r < s.rows; ++r) {
      id.push_back(next_id++);
      x0.push_back(pro_end + c + 0.5);
      y0.push_back(r + 0.5);
    }
  std::string removals = "# synthetic\nstep,time,id,cluster_id,x,y,reason\n";
  for (int k = 0; k < s.outputs; ++k) {
    const double time = t_end * k / (s.outputs - 1), shift = v * time;
    const double amp = 3.0 * h0 * std::min(1.0, time / (0.3 * t_end));  // uplift grows, then holds
    Discs d;
    std::vector<std::int64_t> keep_id;
    std::vector<double> keep_x0, keep_y0;
    for (std::size_t i = 0; i < id.size(); ++i) {
      const double x = x0[i] + shift;
      const double g = std::exp(-x * x / (2 * (3 * h0) * (3 * h0)));
      const double y = y0[i] * (1 + amp / h0 * g) + 0.05 * std::sin(0.3 * x + k);
      if (y > 2 * h0 && k > 0) {
        removals += fmt::format("{},{},{},-1,{},{},eroded\n", k * 1000 - 1, time, id[i], x, y);
        continue;
      }
      d.add(id[i], x, y, 0.5);
      keep_id.push_back(id[i]);
      keep_x0.push_back(x0[i]);
      keep_y0.push_back(y0[i]);
    }
    id = std::move(keep_id);
    x0 = std::move(keep_x0);
    y0 = std::move(keep_y0);
    // Feed the pro end with whole lattice columns as discs were eroded.
    while (static_cast<int>(id.size()) + s.rows <= s.particles) {
      pro_end -= 1;
      for (int r = 0; r < s.rows; ++r) {
        id.push_back(next_id++);
        x0.push_back(pro_end + 0.5);
        y0.push_back(r + 0.5);
      }
    }
    SnapshotFrame frame;
    frame.step = k * 1000;
    frame.time = time;
    frame.attrs = {{"S", shift / h0}};
    frame.discs = &d;
    writer.append(frame);
    write_file_atomically(dir / "removals.csv", removals);
  }
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"time orogen analyze on a synthetic eroding wedge run"};
  Synthetic s;
  std::string dir = "/tmp/orogen_bench_analyze";
  bool reuse = false;
  AnalyzeOptions o;
  app.add_option("--particles", s.particles, "discs per output")->capture_default_str();
  app.add_option("--outputs", s.outputs, "outputs")->capture_default_str()->check(CLI::Range(2, 100000));
  app.add_option("--rows", s.rows, "layer thickness h0 in discs")->capture_default_str()->check(CLI::Range(2, 10000));
  app.add_option("--dir", dir, "folder of the synthetic run")->capture_default_str();
  app.add_flag("--reuse", reuse, "analyse the run already in --dir instead of writing it");
  int stride = 1;
  app.add_option("--particle-stride", stride, "orogen analyze --particle-stride")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (!reuse) {
    const auto t0 = std::chrono::steady_clock::now();
    write_run(dir, s);
    std::cout << fmt::format("wrote {} outputs of about {} discs in {:.1f} s\n", s.outputs, s.particles,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  // No state: the analysis starts from scratch.
  for (const char* f : {"analysis_state.bin", "analysis.h5", "analysis_columns.csv"}) fs::remove(fs::path(dir) / f);
  o.dir = dir;
  o.particle_stride = stride;
  o.quiet = true;
  const double rss_before = peak_rss_mib();
  const auto t0 = std::chrono::steady_clock::now();
  const int status = analyze_command(o);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto mib = [&](const char* name) {
    std::error_code ec;
    const auto size = fs::file_size(fs::path(dir) / name, ec);
    return ec ? 0.0 : static_cast<double>(size) / 1048576.0;
  };
  std::cout << fmt::format("analyze: exit {}, {:.1f} s wall, peak RSS {:.0f} MiB (before: {:.0f} MiB), "
                           "analysis.h5 {:.0f} MiB, analysis_columns.csv {:.0f} MiB, analysis_state.bin {:.1f} MiB, "
                           "particle stride {}\n",
                           status, wall, peak_rss_mib(), rss_before, mib("analysis.h5"), mib("analysis_columns.csv"),
                           mib("analysis_state.bin"), stride);
  return status;
}
