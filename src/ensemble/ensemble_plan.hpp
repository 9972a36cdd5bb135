#pragma once
// The plan of `orogen ensemble`: an ensemble file (TOML) names a preset, the seeds and/or a
// list of named members (each a preset and overrides), and the settings of the statistics.
// load_ensemble reads it and checks every member's whole configuration before anything
// starts, so a bad member fails at once, named, with the file and line (a ConfigError).
// The format is in docs/ensembles.md.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace orogen {

// One member: an ordinary `orogen run PRESET --set ...` into DIR/members/NAME.
struct EnsembleMember {
  std::string name;                    // folder name under members/, unique
  std::string group;                   // the [[member]] entry it comes from ("" without any)
  std::optional<std::int64_t> seed;    // run.seed, when the ensemble lists seeds
  std::filesystem::path preset;        // absolute
  std::vector<std::string> overrides;  // "key=value": [ensemble.set], the member's set, run.seed
  std::string resolved_toml;           // its fully resolved configuration (Config::to_toml)
};

// Settings of the statistics (python3 -m orogen.stats), checked here so that a typo stops
// the ensemble before it runs rather than after.
struct EnsembleStats {
  double s_min = 2.0;                     // power-law fits over S > s_min [h0]
  std::map<std::string, std::string> offset;  // series -> "auto", "none" or a number (TOML text)
  double step_min = 0.5;                  // a step-out: the front jumps outward by more than this [h0]
  double sheet_reference = 5.0;           // convergence per new pro thrust sheet to compare with [h0]
};

struct EnsemblePlan {
  std::filesystem::path file;        // the ensemble file
  std::string title;                 // for tables and charts
  std::vector<std::string> fixed;    // [ensemble.set] as "key=value", in file order
  EnsembleStats stats;
  std::vector<EnsembleMember> members;
};

// The series whose offset may be set in [ensemble.stats.offset].
inline const std::vector<std::string>& ensemble_series() {
  static const std::vector<std::string> names = {"Dp", "Mp", "Dr", "Mr", "H", "T"};
  return names;
}

// Reads and checks an ensemble file; throws ConfigError.
EnsemblePlan load_ensemble(const std::filesystem::path& file);

// The plan as a self-described TOML file for the statistics (DIR/ensemble.toml).
std::string plan_to_toml(const EnsemblePlan& plan);

}  // namespace orogen
