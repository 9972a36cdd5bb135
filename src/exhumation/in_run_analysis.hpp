#pragma once
// The exhumation analysis during a run (analysis.in_run): the same incremental analysis as
// `orogen analyze DIR` afterwards, which reads only the outputs it has not seen, run after
// every `every`-th output and at the end. A failure is logged and the run goes on (the
// analysis can be made again later).
#include <cstdint>
#include <filesystem>
#include <functional>

namespace orogen {

// An output observer of the run driver (experiments/experiment.hpp, OutputObserver).
std::function<void(std::int64_t outputs, bool finished)> in_run_analysis(const std::filesystem::path& run_dir,
                                                                         std::int64_t every);

}  // namespace orogen
