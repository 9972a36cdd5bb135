#include "run/branch_source.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "config/schema.hpp"
#include "io/binary_archive.hpp"
#include "io/snapshot_reader.hpp"
#include "run/run_folder.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// Keys a branch may change (the schema's OnBranch keys): they act on the state as it is
// (friction between discs and on the bases, erosion, the end and spacing of outputs, speed and
// display). Every other key shaped the stored state (packing, particles, wall positions, time
// step), so changing it would not continue that state. Basal friction sits in the loaded
// walls: the experiment puts the branch's values back (Experiment::adopt_branch_config).
bool is_branch_key(std::string_view key) { return key_may(key, kOnBranch); }

}  // namespace

std::string BranchSource::text() const { return fmt::format("{}:{}", dir.string(), output); }

std::string branch_keys_text() { return fmt::format("{}", fmt::join(keys_that(kOnBranch), ", ")); }

BranchSource find_branch_source(const std::string& from) {
  BranchSource s;
  std::string dir = from;
  std::int64_t output = -1;
  // "DIR:K" when what follows the last ':' is a number; a folder may hold ':' itself.
  if (const auto colon = from.rfind(':'); colon != std::string::npos && colon + 1 < from.size() &&
                                          std::all_of(from.begin() + colon + 1, from.end(), ::isdigit)) {
    dir = from.substr(0, colon);
    try {
      output = std::stoll(from.substr(colon + 1));
    } catch (const std::exception&) {
      throw BranchError(fmt::format("--from {}: output {} is not a valid output index", from, from.substr(colon + 1)));
    }
  }
  s.dir = dir;
  if (dir.empty()) throw BranchError(fmt::format("--from {}: needs a run folder (--from RUN_DIR[:OUTPUT])", from));
  if (!fs::is_directory(s.dir)) throw BranchError(fmt::format("--from {}: no such folder {}", from, dir));
  const fs::path h5 = s.dir / "snapshots.h5";
  if (!fs::exists(s.dir / "config.toml") || !fs::exists(h5))
    throw BranchError(fmt::format("--from {}: {} is not a run folder (it needs config.toml and snapshots.h5)", from,
                                  dir));
  try {
    s.config = Config::load(s.dir / "config.toml", {});
    s.outputs = SnapshotReader(h5).count();
  } catch (const std::exception& e) {
    throw BranchError(fmt::format("--from {}: cannot read the run in {}: {}", from, dir, e.what()));
  }
  if (s.outputs < 1) throw BranchError(fmt::format("--from {}: {} holds no output yet", from, dir));
  s.output = output < 0 ? s.outputs - 1 : output;
  if (s.output >= s.outputs)
    throw BranchError(fmt::format("--from {}: output {} is out of range; {} has outputs 0 to {}", from, output, dir,
                                  s.outputs - 1));
  // The checkpoint holds this output's state when it was taken at that output's step.
  try {
    const fs::path ckpt = s.dir / "checkpoint.bin";
    if (fs::exists(ckpt)) {
      const ArchiveReader in(ckpt);
      s.at_checkpoint = in.get_scalar<std::int64_t>("run.outputs") == s.output + 1 &&
                        in.get_scalar<std::uint64_t>("run.last_output_step") == in.get_scalar<std::uint64_t>("world.step");
    }
  } catch (const std::exception&) {
    s.at_checkpoint = false;  // an unreadable checkpoint: the state is rebuilt by a replay
  }
  return s;
}

void check_branch_config(const Config& config, const BranchSource& source) {
  const std::string& experiment = config.get_string("run.experiment");
  const std::string& theirs = source.config.get_string("run.experiment");
  if (experiment != theirs)
    throw BranchError(fmt::format("--from {}: that run is of experiment '{}', this configuration's is '{}' "
                                  "(run.experiment): a branch continues the same experiment",
                                  source.text(), theirs, experiment));
  const auto now = key_values(config.to_toml()), before = key_values(source.config.to_toml());
  std::string refused;
  for (const auto& [key, value] : now) {
    const auto it = before.find(key);
    const std::string was = it == before.end() ? "(absent)" : it->second;
    if (was != value && !is_branch_key(key))
      refused += fmt::format("{}{} = {} (the source run has {})", refused.empty() ? "" : "; ", key, value, was);
  }
  if (!refused.empty())
    throw BranchError(fmt::format("--from {}: a branch continues the stored state and cannot change {}; it may "
                                  "change only {}",
                                  source.text(), refused, branch_keys_text()));
}

}  // namespace orogen
