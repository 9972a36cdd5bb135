// orogen: the command line front end. Each subcommand is a thin wrapper over the library, in
// a file of its own (run.cpp, render.cpp, ...); this file is their table and what every
// command shares: the unknown-command message, the parse, the check of the OpenMP variables.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "config/schema.hpp"
#include "subcommand.hpp"
#include "util/omp_environment.hpp"
#include "util/parallel.hpp"

namespace {

// In the order of `orogen --help`.
constexpr orogen::cli::AddSubcommand kSubcommands[] = {
    orogen::cli::add_run,     orogen::cli::add_render, orogen::cli::add_sweep,
    orogen::cli::add_ensemble, orogen::cli::add_export, orogen::cli::add_analyze,
    orogen::cli::add_report,  orogen::cli::add_charts, orogen::cli::add_sections, orogen::cli::add_calibrate,
    orogen::cli::add_config,
};

// CLI11 reads an unknown first word as a stray argument ("A subcommand is required"): name it.
bool first_word_is_known(CLI::App& app, int argc, char** argv) {
  if (argc <= 1) return true;
  const std::string first = argv[1];
  if (first == "-h" || first == "--help" || first == "--version") return true;
  std::string known;
  for (const CLI::App* c : app.get_subcommands([](CLI::App*) { return true; })) {
    if (c->get_name() == first) return true;
    known += (known.empty() ? "" : ", ") + c->get_name();
  }
  std::cerr << "error: unknown " << (first.starts_with('-') ? "option '" : "command '") << first
            << "'; orogen takes a command first: " << known << " (orogen --help)\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Orogen: a discrete element model of orogenesis (Naylor 2004)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", OROGEN_VERSION);
  std::vector<orogen::cli::Subcommand> subcommands;
  for (const auto add : kSubcommands) subcommands.push_back(add(app));

  if (!first_word_is_known(app, argc, argv)) return 2;
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
  for (const auto& s : subcommands)
    if (*s.app) return s.run();
  return 2;  // not reached: CLI11 requires one subcommand
}
