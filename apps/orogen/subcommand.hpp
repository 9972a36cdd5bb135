#pragma once
// One subcommand of the `orogen` program: added to the CLI11 app by its own file (run.cpp,
// render.cpp, ...), which declares its options and says what it does once parsed. main.cpp
// holds the table of them, in the order `orogen --help` lists them.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace orogen::cli {

struct Subcommand {
  CLI::App* app;              // what CLI11 parses into
  std::function<int()> run;   // called when this subcommand was given; returns the exit code
};

// Adds one subcommand to `parent`; its options live as long as the returned run function.
using AddSubcommand = Subcommand (*)(CLI::App& parent);

// A subcommand whose options a module of the Python package reads: one required positional
// argument, every other word passed on as given (package_subcommand.cpp).
struct PackageSubcommand {
  const char* name;
  const char* description;
  const char* positional;
  const char* positional_help;
  std::function<int(const std::string& positional, std::vector<std::string> rest)> run;
};
Subcommand add_package_subcommand(CLI::App& parent, const PackageSubcommand& spec);

// CLI11 reads an empty value as the default; for a number that is a mistake to report.
CLI::Validator not_empty();
// A count, written as one and in its range: CLI11's own range check calls "1.5", "1e3" or
// "abc" "not in range", which hides what is wrong.
CLI::Validator count_in(long long lo, long long hi);

Subcommand add_run(CLI::App& parent);
Subcommand add_render(CLI::App& parent);
Subcommand add_sweep(CLI::App& parent);
Subcommand add_ensemble(CLI::App& parent);
Subcommand add_export(CLI::App& parent);
Subcommand add_analyze(CLI::App& parent);
Subcommand add_report(CLI::App& parent);
Subcommand add_charts(CLI::App& parent);
Subcommand add_sections(CLI::App& parent);
Subcommand add_calibrate(CLI::App& parent);
Subcommand add_config(CLI::App& parent);

}  // namespace orogen::cli
