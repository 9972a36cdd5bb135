#pragma once
// `orogen run CONFIG --from OTHER_RUN[:OUTPUT]`: the stored output of another run a new run
// (a branch) starts from, and the checks that the new configuration can continue it.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "config/config.hpp"
#include "util/command_error.hpp"

namespace orogen {

// Bad --from (no folder, not a run, an output out of range, another experiment, a key that
// cannot change): exit code 2.
struct BranchError : BadInput {
  using BadInput::BadInput;
};

struct BranchSource {
  std::filesystem::path dir;
  std::int64_t output = 0;   // the output the branch starts from
  std::int64_t outputs = 0;  // complete outputs of the source
  Config config;             // the source's resolved configuration
  // The source's checkpoint holds exactly the state of `output` (a finished run's last one),
  // so no replay is needed.
  bool at_checkpoint = false;
  std::string text() const;  // "DIR:OUTPUT"
};

// Parses "DIR" or "DIR:K" (K an output index, default the last) and checks the folder holds a
// run with that output.
BranchSource find_branch_source(const std::string& from);

// Refuses a configuration that cannot continue the source's state, naming the keys: another
// experiment, or a change of any key but those of kBranchKeys (what a branch may change).
void check_branch_config(const Config& config, const BranchSource& source);
std::string branch_keys_text();

}  // namespace orogen
