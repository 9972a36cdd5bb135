// `orogen export DIR --format F --to FILE`: one output for other tools (src/commands/export_command).
#include <limits>
#include <memory>
#include <string>

#include "commands/export_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_export(CLI::App& parent) {
  struct Options {
    ExportCommandOptions exp;
    std::string dir, to;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand("export", "write one output of a run for other tools: a LAMMPS data file "
                                              "or dump, extended XYZ, CSV");
  cmd->add_option("dir", o->dir, "run folder")->required();
  cmd->add_option("--output", o->exp.output, "output index (default: the last)")
      ->check(not_empty())
      ->check(count_in(0, std::numeric_limits<long long>::max()));
  cmd->add_option("--format", o->exp.format, "lammps-data | lammps-dump | xyz | csv")->required();
  cmd->add_option("--to", o->to, "the file to write")->required();
  return {cmd, [o] {
            o->exp.dir = o->dir;
            o->exp.to = o->to;
            return export_command(o->exp);
          }};
}

}  // namespace orogen::cli
