#pragma once
// A run folder is owned by one run: claimed with an exclusive lock before any work, checked
// for files of another run, and on --resume checked against the checkpoint's own copy of the
// configuration, so that no two runs ever write into one folder and no resume mixes runs.
#include <filesystem>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/run_identity.hpp"
#include "io/file_lock.hpp"  // what makes the files of a folder one run
#include "util/command_error.hpp"

namespace orogen {

// A folder that cannot be used as asked (held by another process, holds another run's files,
// files that do not belong together); exit code 2.
struct RunFolderError : BadInput {
  using BadInput::BadInput;
};

// A folder that cannot be created or written (a read-only disk, no permission); exit code 1.
struct RunFolderIoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Holds `DIR/run.lock` locked (flock) while it lives; the kernel drops the lock when the
// process dies, even by kill -9, so a killed run never leaves a folder locked.
class RunFolderLock {
 public:
  // Creates DIR if needed and locks it; throws RunFolderError if another process holds it,
  // RunFolderIoError if the folder cannot be created or written.
  explicit RunFolderLock(const std::filesystem::path& dir);
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;

  // For a run that failed before it began: removes the lock file, and the folder if this
  // lock created it and nothing else is in it.
  void abandon();

 private:
  std::filesystem::path dir_;
  bool created_dir_ = false;
  FileLock lock_;
};

// Names of the files and folders a run writes (config.toml aside) that are present in DIR.
std::vector<std::string> run_files_in(const std::filesystem::path& dir);

// Removes the run files in DIR except config.toml, run.log and run.lock (a run that is
// started again from its set-up).
void remove_run_outputs(const std::filesystem::path& dir);

// A path a command is about to write that is a file of a run folder: the folder, and the name
// of the run's file (its first component there; "" for the folder itself).
struct RunFileAt {
  std::filesystem::path run;
  std::string name;
};
// Where `target` is the folder of a run (config.toml beside run.lock, snapshots.h5 or
// checkpoint.bin, at any level above it, symbolic links followed) or lies in one of that run's
// files (what the run writes, config.toml, run.lock, and analyze's analysis* files), which no
// other command may write over; nullopt otherwise.
std::optional<RunFileAt> run_file_at(const std::filesystem::path& target);
// "--to RUN/series.csv: series.csv belongs to the run in RUN, ..." for a refusal of `target`,
// `option` the option as the user gave it ("--to RUN/series.csv"); "" when target is free.
std::string run_file_refusal(std::string_view option, const std::filesystem::path& target);

// Removes the temporary files (*.tmp-PID) a killed write left in DIR, DIR/vtp and
// DIR/snapshots; returns how many.
int remove_temporary_files(const std::filesystem::path& dir);

}  // namespace orogen
