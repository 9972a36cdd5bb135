#pragma once
// The plan of `orogen sweep`: a sweep file (TOML) names a base preset, fixed overrides and a
// matrix of values; every combination of the matrix is one run. load_sweep reads the file and
// checks every run's configuration before anything starts, so a bad value in the last run of
// a long sweep fails at once, naming the sweep file, its line, the key, the value and what is
// allowed (a ConfigError, like the run configuration itself).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace orogen {

// One swept key and its values, in the sweep file's order.
struct SweepAxis {
  std::string key;                  // dotted configuration key
  std::string label;                // its short name in run names ("mu" of "contact.mu")
  std::vector<std::string> shown;   // each value as a table shows it (strings unquoted)
  std::vector<std::string> toml;    // each value as TOML text, for --set
};

// One combination: a run of `orogen run BASE --set ...`.
struct SweepRun {
  std::size_t index = 0;               // row-major over the axes, the first axis outermost
  std::string name;                    // folder name under runs/, e.g. "003_packing=random_discs_mu=0.1"
  std::vector<std::size_t> choice;     // the value index on each axis
  std::vector<std::string> overrides;  // "key=value": [set] then the matrix values
  std::string resolved_toml;           // the run's fully resolved configuration (Config::to_toml)
};

struct SweepPlan {
  std::filesystem::path file;             // the sweep file
  std::filesystem::path base;             // the base preset, absolute
  std::vector<std::string> fixed;         // [set] as "key=value", in file order
  std::vector<SweepAxis> axes;            // [matrix], in file order
  std::vector<SweepRun> runs;
};

// Reads and checks a sweep file; throws ConfigError.
SweepPlan load_sweep(const std::filesystem::path& file);

}  // namespace orogen
