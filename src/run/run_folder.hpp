#pragma once
// A run folder is owned by one run: claimed with an exclusive lock before any work, checked
// for files of another run, and on --resume checked against the checkpoint's own copy of the
// configuration, so that no two runs ever write into one folder and no resume mixes runs.
#include <filesystem>
#include <stdexcept>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace orogen {

class Config;

// A folder that cannot be used as asked (held by another process, holds another run's files,
// files that do not belong together); exit code 2.
struct RunFolderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Holds `DIR/run.lock` locked (flock) while it lives; the kernel drops the lock when the
// process dies, even by kill -9, so a killed run never leaves a folder locked.
class RunFolderLock {
 public:
  // Creates DIR if needed and locks it; throws RunFolderError if another process holds it.
  explicit RunFolderLock(const std::filesystem::path& dir);
  ~RunFolderLock();
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;

  // For a run that failed before it began: removes the lock file, and the folder if this
  // lock created it and nothing else is in it.
  void abandon();

 private:
  std::filesystem::path dir_;
  int fd_ = -1;
  bool created_dir_ = false;
};

// Names of the files and folders a run writes (config.toml aside) that are present in DIR.
std::vector<std::string> run_files_in(const std::filesystem::path& dir);

// Removes the run files in DIR except config.toml, run.log and run.lock (a run that is
// started again from its set-up).
void remove_run_outputs(const std::filesystem::path& dir);

// Removes the temporary files (*.tmp-PID) a killed write left in DIR, DIR/vtp and
// DIR/snapshots; returns how many.
int remove_temporary_files(const std::filesystem::path& dir);

// "contact.kn = 5000.0 in config.toml, 10000.0 in the checkpoint; ..." for every key whose
// value differs between two resolved configurations (Config::to_toml texts), the extension,
// analysis and display keys aside; "" if none.
std::string config_differences(std::string_view here, std::string_view there, std::string_view here_name,
                               std::string_view there_name);

// "section.key" -> value text of each assignment line of a resolved configuration (Config::to_toml).
std::map<std::string, std::string> key_values(std::string_view toml);

// Keys a resume may change: they move a run's end and the spacing of its outputs, never what
// it computes up to there (`orogen run --resume DIR --set wedge.s_end=30`).
bool is_extension_key(std::string_view key);
// The [analysis] keys: outside the run identity and free to change on a resume.
bool is_analysis_key(std::string_view key);
// Keys that change how fast or how visibly a run goes, never what it computes (threads,
// thread tuning, progress, checkpoint interval, .vtp output): outside the run identity, and a
// resume may set them for itself (`--resume DIR --set output.progress=never`).
bool is_display_key(std::string_view key);
std::string extension_keys_text();  // "wedge.s_end, wedge.outputs"
// "wedge.s_end 8.0 -> 16.0, ..." for the extension keys that differ from `before` to `now`.
std::string extension_changes(std::string_view now, std::string_view before);

// 16 hex digits identifying what a run computes: a hash of the resolved configuration without
// the keys that change only speed or display (threads, thread tuning, progress, checkpoint
// interval, .vtp output) and the extension keys. Stored with the outputs and the checkpoint.
std::string run_identity(const Config& config);

}  // namespace orogen
