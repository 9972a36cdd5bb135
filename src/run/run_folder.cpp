#include "run/run_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace fs = std::filesystem;

namespace orogen {
namespace {

// Everything a run writes into its folder besides config.toml and run.lock.
constexpr std::array<const char*, 14> kRunOutputs = {"checkpoint.bin", "snapshots.h5",    "snapshots",    "series.csv",
                                                     "removals.csv",   "bond_breaks.csv", "summary.csv",  "run.pvd",
                                                     "vtp",            "packing.h5",      "profile.csv",  "run.log",
                                                     "snapshots.xmf",  "packing.xmf"};

bool is_run_folder(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "config.toml", ec) &&
         (fs::exists(dir / "run.lock", ec) || fs::exists(dir / "snapshots.h5", ec) ||
          fs::exists(dir / "checkpoint.bin", ec));
}

// A name of the run's own files, or of what analyze writes there.
bool is_run_file_name(std::string_view name) {
  if (name == "config.toml" || name == "run.lock" || name.starts_with("analysis")) return true;
  return std::find(kRunOutputs.begin(), kRunOutputs.end(), name) != kRunOutputs.end();
}

bool is_temporary(const fs::path& p) { return p.filename().string().find(".tmp-") != std::string::npos; }

bool create_folder(const fs::path& dir) {
  std::error_code ec;
  const bool created = fs::create_directories(dir, ec);
  // A file where the folder (or one above it) should be is the user's to move: bad input.
  if (ec == std::errc::not_a_directory || ec == std::errc::file_exists)
    throw RunFolderError(fmt::format("cannot create the run folder {}: {} (a file is in the way)", dir.string(),
                                     ec.message()));
  if (ec) throw RunFolderIoError(fmt::format("cannot create the run folder {}: {}", dir.string(), ec.message()));
  return created;
}

}  // namespace

RunFolderLock::RunFolderLock(const fs::path& dir)
    : dir_(dir), created_dir_(create_folder(dir)), lock_(dir / "run.lock") {
  if (lock_.open_error() != 0)
    throw RunFolderIoError(
        fmt::format("cannot write in the run folder {}: {}", dir.string(), std::strerror(lock_.open_error())));
  if (!lock_.locked())
    throw RunFolderError(fmt::format("{} is in use by another orogen process (it holds {}); wait for it to end or "
                                     "choose another folder",
                                     dir.string(), lock_.path().string()));
}

void RunFolderLock::abandon() {
  lock_.release_and_remove();
  std::error_code ec;
  if (created_dir_ && fs::is_empty(dir_, ec)) fs::remove(dir_, ec);
}

std::vector<std::string> run_files_in(const fs::path& dir) {
  std::vector<std::string> found;
  for (const char* name : kRunOutputs)
    if (fs::exists(dir / name)) found.emplace_back(name);
  return found;
}

void remove_run_outputs(const fs::path& dir) {
  for (const char* name : kRunOutputs)
    if (std::string_view(name) != "run.log") fs::remove_all(dir / name);
}

std::optional<RunFileAt> run_file_at(const fs::path& target) {
  std::error_code ec;
  const fs::path full = fs::weakly_canonical(fs::absolute(target, ec), ec);
  if (ec) return std::nullopt;
  for (fs::path dir = full;; dir = dir.parent_path()) {
    if (is_run_folder(dir)) {
      const fs::path rel = full.lexically_relative(dir);
      const std::string first = rel.empty() || rel == "." ? "" : rel.begin()->string();
      if (first.empty() || is_run_file_name(first)) return RunFileAt{dir, first};
      return std::nullopt;
    }
    if (dir == dir.parent_path()) return std::nullopt;
  }
}

std::string run_file_refusal(std::string_view option, const fs::path& target) {
  const auto at = run_file_at(target);
  if (!at) return "";
  if (at->name.empty())
    return fmt::format("{}: that is the folder of the run in {}; give a path outside the run's own files", option,
                       at->run.string());
  return fmt::format("{}: {} belongs to the run in {}, which only that run (and orogen analyze, for its analysis "
                     "files) may write; give a path outside the run's own files",
                     option, at->name, at->run.string());
}

int remove_temporary_files(const fs::path& dir) {
  int removed = 0;
  for (const fs::path& folder : {dir, dir / "vtp", dir / "snapshots"}) {
    if (!fs::is_directory(folder)) continue;
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(folder))
      if (is_temporary(entry.path())) stale.push_back(entry.path());
    for (const auto& p : stale) removed += fs::remove(p) ? 1 : 0;
  }
  return removed;
}

}  // namespace orogen
