#pragma once
// `orogen export DIR`: one output of a run written in a format another tool reads (LAMMPS
// data file or text dump, extended XYZ, CSV; src/io/snapshot_export.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

namespace orogen {

struct ExportCommandOptions {
  std::filesystem::path dir;
  std::int64_t output = -1;  // -1: the last output
  std::string format;
  std::filesystem::path to;  // the file to write
};

// Exit codes: 0 written; 2 bad input (no run in DIR, an output out of range, an unknown
// format: each named with what is allowed); 1 I/O (the file cannot be written).
int export_command(const ExportCommandOptions& options);

}  // namespace orogen
