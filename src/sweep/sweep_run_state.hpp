#pragma once
// Where one run of a sweep stands, read from its folder, so that a sweep started again does
// only the work left: the run's own checkpoint says whether it finished (written by `orogen
// run` itself, so it is right even when the sweep was killed just after the run ended), and
// the sweep's markers in the folder record a failed run and a finished rendering.
#include <filesystem>
#include <string>

namespace orogen {

enum class RunStage {
  Absent,    // no folder: start it
  Restart,   // a folder with no checkpoint (killed before its first one): remove it, start again
  Resume,    // a checkpoint of an unfinished run: `orogen run --resume`
  Finished,  // the checkpoint says the run finished
  Failed,    // the run ended with a verdict on its configuration (exit 2 or 3), recorded
};

struct RunInspection {
  RunStage stage = RunStage::Absent;
  int failed_status = 0;  // Failed: the recorded exit status
  std::string failed_error;  // Failed: the run's last log line, as recorded
  bool rendered = false;  // Finished: both renders done
  std::string note;       // why (for the sweep log), e.g. "checkpoint unreadable: ..."
};

// Marker files the sweep writes into a run folder.
inline constexpr const char* kFailedMarker = "sweep.failed";      // the exit status, then the last log line
inline constexpr const char* kRenderedMarker = "sweep.rendered";  // empty

// Inspects a run folder. Throws std::runtime_error, naming the folder and the first differing
// key, when the folder holds a run of another configuration than `resolved_toml` (the base or
// sweep file changed since): its results would not be those of this sweep.
RunInspection inspect_run(const std::filesystem::path& run_dir, const std::string& resolved_toml);

// Exit statuses that are the run's verdict on its configuration and would come again on a
// retry: 2 (bad input) and 3 (unstable). Anything else (killed, an I/O error) is retried.
inline bool is_verdict(int status) { return status == 2 || status == 3; }

}  // namespace orogen
