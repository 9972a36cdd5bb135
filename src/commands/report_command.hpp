#pragma once
// `orogen report DIR [--out SITE]`: the results atlas, a static web site of every run, sweep
// and ensemble under DIR (docs/atlas.md). The pages are built by the Python package's module
// orogen.atlas (`python3 -m orogen.atlas`), as the ensemble statistics are: Python already
// reads every file the site shows.
#include <filesystem>

namespace orogen {

struct ReportOptions {
  std::filesystem::path dir;
  std::filesystem::path out;  // empty: DIR/atlas
};

// Exit codes: 0 built; 2 bad input (DIR missing or not a folder, SITE a file or a folder
// that holds something other than an atlas), each named on one "error: ..." line; 1 I/O or
// a missing /usr/bin/python3 or Python package orogen.
int report_command(const ReportOptions& options);

}  // namespace orogen
