#include "sweep/sweep_run_state.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "config/config.hpp"
#include "io/binary_archive.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first key whose value differs between two resolved configurations, as
// "contact.mu = 0.3 there, 0.1 now" (both are Config::to_toml texts: [section] headers, then
// comment and `key = value` lines in schema order).
std::string first_difference(const std::string& there, const std::string& now) {
  std::istringstream a(there), b(now);
  std::string la, lb, section;
  while (true) {
    const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a || !more_b) return "the list of keys differs";
    if (la.starts_with("[")) section = la.substr(1, la.find(']') - 1);
    if (la == lb) continue;
    const auto eq_a = la.find(" = "), eq_b = lb.find(" = ");
    if (eq_a == std::string::npos || eq_b == std::string::npos || la.substr(0, eq_a) != lb.substr(0, eq_b))
      return "the list of keys differs";
    return fmt::format("{}.{} = {} there, {} now", section, la.substr(0, eq_a), la.substr(eq_a + 3),
                       lb.substr(eq_b + 3));
  }
}

void check_same_config(const fs::path& dir, const std::string& resolved_toml) {
  std::string there;
  try {
    // Resolved again with this program's schema, so a key added since (at its default) is no difference.
    there = Config::load(dir / "config.toml", {}).to_toml();
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{} holds a run whose configuration no longer loads ({}); remove that "
                                         "folder, or choose another --out",
                                         dir.string(), e.what()));
  }
  if (there != resolved_toml)
    throw std::runtime_error(fmt::format("{} holds a run of another configuration ({}): the base preset or the sweep "
                                         "file changed since it started; remove that folder, or choose another --out",
                                         dir.string(), first_difference(there, resolved_toml)));
}

}  // namespace

RunInspection inspect_run(const fs::path& dir, const std::string& resolved_toml) {
  RunInspection r;
  if (!fs::exists(dir)) return r;
  if (fs::exists(dir / "config.toml")) check_same_config(dir, resolved_toml);
  const fs::path checkpoint = dir / "checkpoint.bin";
  if (fs::exists(checkpoint)) {
    try {
      const ArchiveReader in(checkpoint);
      if (in.get_scalar<std::uint8_t>("run.finished") != 0) {
        r.stage = RunStage::Finished;
        r.rendered = fs::exists(dir / kRenderedMarker);
        return r;
      }
    } catch (const std::exception& e) {
      // Never delete a run with a checkpoint: `run --resume` reports what is wrong with it.
      r.note = fmt::format("checkpoint unreadable ({})", e.what());
    }
  }
  if (fs::exists(dir / kFailedMarker)) {
    try {
      const std::string marker = slurp(dir / kFailedMarker);
      const int status = std::stoi(marker);
      if (is_verdict(status)) {
        r.stage = RunStage::Failed;
        r.failed_status = status;
        // The second line, where a marker has one (older sweeps wrote the status alone).
        const auto eol = marker.find('\n');
        if (eol != std::string::npos) r.failed_error = marker.substr(eol + 1, marker.find('\n', eol + 1) - eol - 1);
        return r;
      }
    } catch (const std::exception&) {
      // A marker that does not hold a verdict is ignored: the run is tried again.
    }
  }
  if (fs::exists(checkpoint)) {
    r.stage = RunStage::Resume;
    return r;
  }
  r.stage = RunStage::Restart;
  if (r.note.empty()) r.note = "no checkpoint yet";
  return r;
}

}  // namespace orogen
