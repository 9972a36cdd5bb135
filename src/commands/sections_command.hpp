#pragma once
// `orogen sections DIR [OPTIONS]`: the cross-sections of a wedge run for a reader (horizon
// bands, active faults, displacement vectors; frames, animations, PDF/SVG stills), drawn by
// the Python package (`python3 -m orogen.charts.sections`, docs/rendering.md), which reads
// every option. Exit codes: those of the module (0 drawn, 2 bad input), 1 when python3 or the
// package is missing.
#include <filesystem>
#include <string>
#include <vector>

namespace orogen {

struct SectionsOptions {
  std::filesystem::path dir;
  std::vector<std::string> module_options;  // passed on as given (--kinds, --every, ...)
};

int sections_command(const SectionsOptions& options);

}  // namespace orogen
