#pragma once
// `orogen charts DIR [--out OUTDIR]`: the charts of a run, sweep or ensemble folder, drawn by
// the Python package (`python3 -m orogen.charts`, which picks the charts by what DIR holds:
// docs/python.md). Exit codes: those of the package's module (0 drawn, 2 bad input), 1 when
// python3 or the package is missing.
#include <filesystem>

namespace orogen {

struct ChartsOptions {
  std::filesystem::path dir;
  std::filesystem::path out;  // empty: DIR/charts
};

int charts_command(const ChartsOptions& options);

}  // namespace orogen
