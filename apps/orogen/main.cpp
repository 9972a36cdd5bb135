// orogen: the command line front end. Each subcommand is a thin wrapper over the library.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <iostream>
#include <limits>

#include "commands/export_command.hpp"
#include "commands/render_command.hpp"
#include "commands/charts_command.hpp"
#include "commands/report_command.hpp"
#include "config/config.hpp"
#include "config/schema.hpp"
#include "ensemble/ensemble_command.hpp"
#include "exhumation/analyze_command.hpp"
#include "run/runner.hpp"
#include "sweep/sweep_command.hpp"
#include "util/omp_environment.hpp"
#include "util/parallel.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Orogen: a discrete element model of orogenesis (Naylor 2004)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", OROGEN_VERSION);

  // CLI11 reads an empty value as the default; for a number that is a mistake to report.
  const CLI::Validator not_empty(
      [](std::string& value) { return value.empty() ? std::string("an empty value (a number is needed)") : ""; },
      "", "not empty");
  // A count, written as one and in its range: CLI11's own range check calls "1.5", "1e3" or
  // "abc" "not in range", which hides what is wrong.
  const auto count_in = [](long long lo, long long hi) {
    return CLI::Validator(
        [lo, hi](std::string& value) {
          long long v = 0;
          const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
          const bool ok = !value.empty() && ec == std::errc() && end == value.data() + value.size() &&
                          value.front() != '-' && v >= lo && v <= hi;
          return ok ? std::string() : "'" + value + "' must be a whole number from " + std::to_string(lo) + " to " +
                                          std::to_string(hi);
        },
        "", "count");
  };

  orogen::RunOptions run;
  std::string config_path, out = "out";
  auto* run_cmd = app.add_subcommand("run", "run an experiment (no CONFIG: the built-in default)");
  run_cmd->add_option("config", config_path, "TOML configuration file");
  run_cmd->add_option("--out,-o", out, "output folder")->capture_default_str();
  run_cmd->add_option("--set", run.overrides, "override a key: --set contact.mu=0.2 (repeatable)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: run.threads, 0 = all cores)")
      ->check(not_empty)
      ->check(count_in(0, orogen::kMaxThreads));
  std::string resume_dir;
  auto* resume_opt = run_cmd->add_option("--resume", resume_dir, "continue the killed run in this folder");
  auto* from_opt = run_cmd->add_option(
      "--from", run.from, "start from an output of another run: RUN_DIR[:OUTPUT] (default the last), a branch");
  run_cmd->add_option("--abort-after-outputs", run.abort_after_outputs,
                      "test hook: exit 137 with no cleanup once this many outputs are written")
      ->group("");  // hidden

  orogen::RenderCommandOptions render;
  std::string render_dir;
  auto* render_cmd = app.add_subcommand("render", "draw the output steps of a run as PNG frames and an animation");
  render_cmd->add_option("dir", render_dir, "run folder")->required();
  render_cmd->add_option("--color", render.color,
                         "horizons | cluster | forces | field:NAME (field:max_rel_disp uses the hot colormap; forces "
                         "draws the contact forces of a run with output.contacts = true)")
      ->capture_default_str();
  render_cmd->add_option("--width", render.width_px, "picture width in pixels")
      ->capture_default_str()
      ->check(not_empty);  // the range is checked by render_command, with the other options
  render_cmd->add_option("--every", render.every, "draw every n-th output")
      ->capture_default_str()
      ->check(not_empty);
  render_cmd->add_option("--frames-dir", render.frames_name,
                         "subfolder for the frames (the animation is named after it)")->capture_default_str();
  render_cmd->add_option("--fps", render.fps, "animation frames per second")
      ->capture_default_str()
      ->check(not_empty);
  bool no_animation = false;  // a plain flag: CLI11 prints "{false}" after a negated one in --help
  render_cmd->add_flag("--no-animation", no_animation, "only the PNG frames");
  render_cmd->add_flag("--vectors", render.vectors,
                       "draw each disc's displacement over the last three outputs as an arrow");
  render_cmd->add_option("--vector-scale", render.vector_scale, "arrow length per unit displacement")
      ->capture_default_str();
  render_cmd->add_option("--vector-stride", render.vector_stride, "draw every n-th disc's arrow")
      ->capture_default_str();

  orogen::SweepOptions sweep;
  std::string sweep_file, sweep_out;
  auto* sweep_cmd = app.add_subcommand("sweep", "run every combination of a sweep file's matrix, several at once, "
                                                "and tabulate the results (resumable)");
  sweep_cmd->add_option("file", sweep_file, "sweep file (TOML, see docs/sweeps.md)")->required();
  sweep_cmd->add_option("--out,-o", sweep_out, "sweep folder: runs/, logs/, results.csv, results.md")->required();
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "runs at once (default: hardware threads / --threads)")
      ->check(not_empty)
      ->check(count_in(1, 4096));
  sweep_cmd->add_option("--threads", sweep.threads, "threads of each run (more only helps from 16384 discs up)")
      ->capture_default_str()
      ->check(not_empty)
      ->check(count_in(1, orogen::kMaxThreads));
  sweep_cmd->add_flag("--render", sweep.render, "render each finished run (horizons and max_rel_disp)");
  sweep_cmd->add_flag("--dry-run", sweep.dry_run, "check the sweep, list its runs and what each needs; run nothing");

  orogen::EnsembleOptions ensemble;
  std::string ensemble_file, ensemble_out;
  auto* ensemble_cmd = app.add_subcommand("ensemble", "run a preset over seeds and/or variants (in parallel, or "
                                                      "under mpirun) and compute their statistics (resumable)");
  ensemble_cmd->add_option("file", ensemble_file, "ensemble file (TOML, see docs/ensembles.md)")->required();
  ensemble_cmd->add_option("--out,-o", ensemble_out, "ensemble folder: members/, aggregate/, results.csv, results.md")
      ->required();
  ensemble_cmd->add_option("--jobs,-j", ensemble.jobs, "members at once (default: the cores, or the members if fewer)")
      ->check(not_empty)
      ->check(count_in(1, 4096));
  ensemble_cmd->add_option("--threads", ensemble.threads,
                           "threads of each member (default: the cores left over when members are fewer)")
      ->check(not_empty)
      ->check(count_in(1, orogen::kMaxThreads));
  ensemble_cmd->add_flag("--dry-run", ensemble.dry_run, "check the ensemble, list its members; run nothing");
  ensemble_cmd->add_flag("--no-stats", ensemble.no_stats, "run the members only (python3 -m orogen.stats DIR later)");

  orogen::ExportCommandOptions export_opt;
  std::string export_dir, export_to;
  auto* export_cmd = app.add_subcommand("export", "write one output of a run for other tools: a LAMMPS data file "
                                                  "or dump, extended XYZ, CSV");
  export_cmd->add_option("dir", export_dir, "run folder")->required();
  export_cmd->add_option("--output", export_opt.output, "output index (default: the last)")
      ->check(not_empty)
      ->check(count_in(0, std::numeric_limits<long long>::max()));
  export_cmd->add_option("--format", export_opt.format, "lammps-data | lammps-dump | xyz | csv")->required();
  export_cmd->add_option("--to", export_to, "the file to write")->required();

  orogen::AnalyzeOptions analyze;
  std::string analyze_dir, closure_text;
  int flux_window = 0, particle_stride = 0;
  double steady_fraction = 0;
  std::int64_t trajectory_output = 0;
  auto* analyze_cmd = app.add_subcommand("analyze", "exhumation analysis of a wedge run (finished or running): depths, "
                                                    "closure-depth ages, erosion, flux steady state (docs/exhumation.md)");
  analyze_cmd->add_option("dir", analyze_dir, "run folder")->required();
  auto* closure_opt = analyze_cmd->add_option(
      "--closure-depths", closure_text,
      "closure depths h_i below the surface [h0], ascending, comma-separated (default: the run's analysis.closure_depths)");
  auto* window_opt = analyze_cmd->add_option("--flux-window", flux_window,
                                             "outputs averaged by the flux steady-state rule (default: analysis.flux_window)")
                         ->check(not_empty);
  auto* fraction_opt = analyze_cmd->add_option("--steady-fraction", steady_fraction,
                                               "averaged eroded flux / incoming flux v h0 that counts as steady "
                                               "(default: analysis.steady_fraction)")
                           ->check(not_empty);
  auto* stride_opt = analyze_cmd->add_option("--particle-stride", particle_stride,
                                             "per-particle series keep the ids divisible by this "
                                             "(default: analysis.particle_stride)")
                         ->check(not_empty);
  auto* trajectory_opt = analyze_cmd->add_option("--trajectory-output", trajectory_output,
                                                 "trace back the surface particles of this output (default -1: the last)")
                             ->check(not_empty);

  orogen::ReportOptions report;
  std::string report_dir, report_out;
  auto* report_cmd = app.add_subcommand("report", "build or update the results atlas: a static web site of every "
                                                  "run, sweep and ensemble under DIR (docs/atlas.md)");
  report_cmd->add_option("dir", report_dir, "folder holding runs, sweeps and ensembles (searched at any depth)")
      ->required();
  report_cmd->add_option("--out,-o", report_out, "site folder (default DIR/atlas); open SITE/index.html");

  orogen::ChartsOptions charts;
  std::string charts_dir, charts_out;
  auto* charts_cmd = app.add_subcommand("charts", "draw the charts of a run, sweep or ensemble folder, chosen by "
                                                  "what it holds (python3 -m orogen.charts; docs/python.md)");
  charts_cmd->add_option("dir", charts_dir, "a run, sweep or ensemble folder")->required();
  charts_cmd->add_option("--out,-o", charts_out, "folder for the charts (default DIR/charts)");

  bool markdown = false;
  auto* config_cmd = app.add_subcommand("config", "print the default configuration (every key, documented)");
  config_cmd->add_flag("--markdown", markdown, "print the key reference as Markdown tables instead");

  // CLI11 reads an unknown first word as a stray argument ("A subcommand is required"): name it.
  if (argc > 1) {
    const std::string first = argv[1];
    const bool known_option = first == "-h" || first == "--help" || first == "--version";
    const bool known_command =
        !app.get_subcommands([&](CLI::App* c) { return c->get_name() == first; }).empty();
    if (!known_option && !known_command) {
      std::string known;
      for (const CLI::App* c : app.get_subcommands([](CLI::App*) { return true; }))
        known += (known.empty() ? "" : ", ") + c->get_name();
      std::cerr << "error: unknown " << (first.starts_with('-') ? "option '" : "command '") << first
                << "'; orogen takes a command first: " << known << " (orogen --help)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  const std::string environment_errors[] = {orogen::parallel_environment_error(),
                                            orogen::omp_environment_error(orogen::kMaxThreads)};
  for (const std::string& error : environment_errors)
    if (!error.empty()) {
      std::cerr << "error: " << error << "\n";
      return 2;
    }
  if (*config_cmd) {
    std::cout << (markdown ? orogen::reference_markdown() : orogen::Config::load(std::nullopt, {}).to_toml());
    return 0;
  }
  if (*run_cmd) {
    if (!config_path.empty()) run.config = config_path;
    if (resume_opt->count() > 0 && resume_dir.empty()) {
      std::cerr << "error: --resume needs a run folder (got an empty one)\n";
      return 2;
    }
    if (from_opt->count() > 0 && run.from.empty()) {
      std::cerr << "error: --from needs a run folder (got an empty one)\n";
      return 2;
    }
    if (!resume_dir.empty()) { run.resume = true; run.out = resume_dir; }
    else run.out = out;
    return orogen::run_command(run);
  }
  if (*sweep_cmd) {
    sweep.file = sweep_file;
    sweep.out = sweep_out;
    return orogen::sweep_command(sweep);
  }
  if (*ensemble_cmd) {
    ensemble.file = ensemble_file;
    ensemble.out = ensemble_out;
    return orogen::ensemble_command(ensemble);
  }
  if (*export_cmd) {
    export_opt.dir = export_dir;
    export_opt.to = export_to;
    return orogen::export_command(export_opt);
  }
  if (*report_cmd) {
    report.dir = report_dir;
    report.out = report_out;
    return orogen::report_command(report);
  }
  if (*charts_cmd) {
    charts.dir = charts_dir;
    charts.out = charts_out;
    return orogen::charts_command(charts);
  }
  if (*analyze_cmd) {
    analyze.dir = analyze_dir;
    if (closure_opt->count() > 0) {
      analyze.closure = orogen::parse_closure_depths(closure_text);
      if (!analyze.closure) {
        std::cerr << "error: --closure-depths " << closure_text
                  << ": not a comma-separated list of numbers; give depths in h0, e.g. 0.15,0.3,0.5\n";
        return 2;
      }
    }
    if (window_opt->count() > 0) analyze.flux_window = flux_window;
    if (fraction_opt->count() > 0) analyze.steady_fraction = steady_fraction;
    if (stride_opt->count() > 0) analyze.particle_stride = particle_stride;
    if (trajectory_opt->count() > 0) analyze.trajectory_output = trajectory_output;
    return orogen::analyze_command(analyze);
  }
  render.dir = render_dir;
  render.animation = !no_animation;
  return orogen::render_command(render);
}
