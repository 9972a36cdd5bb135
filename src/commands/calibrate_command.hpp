#pragma once
// `orogen calibrate CONFIG --out DIR [OPTIONS]`: a material's macroscopic properties from biaxial
// tests at several confining stresses (the Mohr-Coulomb envelopes, peak and residual; the
// stress-strain curves), run and fitted by the Python package (`python3 -m orogen.calibrate`,
// docs/materials.md), which reads every option. Exit codes: those of the module (0 written, 2
// bad input), 1 when python3 or the package is missing or a test failed.
#include <string>
#include <vector>

namespace orogen {

struct CalibrateOptions {
  std::string config;
  std::vector<std::string> module_options;  // passed on as given (--out, --material, --sigma3, ...)
};

int calibrate_command(const CalibrateOptions& options);

}  // namespace orogen
