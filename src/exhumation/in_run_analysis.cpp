#include "exhumation/in_run_analysis.hpp"

#include <spdlog/spdlog.h>

#include "exhumation/analyze_command.hpp"

namespace orogen {

std::function<void(std::int64_t, bool)> in_run_analysis(const std::filesystem::path& run_dir, std::int64_t every) {
  return [run_dir, every](std::int64_t outputs, bool finished) {
    if (!finished && outputs % every != 0) return;
    AnalyzeOptions analysis;
    analysis.dir = run_dir;
    analysis.quiet = true;
    if (analyze_command(analysis) != 0)
      if (auto log = spdlog::get("orogen")) log->warn("in-run analysis failed (see the error above); the run goes on");
  };
}

}  // namespace orogen
