#pragma once
// The run configuration: a TOML file plus --set overrides, checked strictly against the schema
// (schema.hpp). Every mistake is a ConfigError naming where it came from, the key, the value
// and what is allowed, so a bad run fails before it starts rather than after hours.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "config/schema.hpp"
#include "contact/materials.hpp"
#include "util/command_error.hpp"

namespace orogen {

// A user mistake in the configuration (file or command line).
// Bad input (exit 2) whose message is a whole line of its own: "config error in ...".
struct ConfigError : BadInput {
  explicit ConfigError(const std::string& message) : BadInput(message) {}
  std::string line() const override { return what(); }
};

// "config error in SOURCE: KEY = VALUE: ALLOWED"; an empty key or value is left out.
// SOURCE is a file path, "--set", or Config::source_of(key) for cross-key checks.
ConfigError config_error(std::string_view source, std::string_view key, std::string_view value,
                         std::string_view allowed);

// [materials.NAME] and [[layer.units]] (docs/materials.md): read by config_materials.cpp.
struct LayeringConfig {
  MaterialTable materials;  // its units: [[layer.units]]
  std::vector<std::vector<std::string>> given;  // per material: the keys set (the others default)
  std::string source = "default";               // where they were given
};

class Config {
 public:
  Config();  // every key at its default
  // Parse `file` (if given), apply the "section.key=value" overrides in order (later wins,
  // and they beat the file), fill defaults, validate. Throws ConfigError.
  static Config load(const std::optional<std::filesystem::path>& file,
                     const std::vector<std::string>& overrides);

  // Typed getters; an unknown key or the wrong getter is a programming error (std::logic_error).
  double get_float(std::string_view key) const;
  std::int64_t get_int(std::string_view key) const;
  // An integer key as int: every Int key's range lies inside int (schema.cpp), and this checks it.
  int get_int32(std::string_view key) const;
  bool get_bool(std::string_view key) const;
  const std::string& get_string(std::string_view key) const;

  // Whether the user gave the key (in the file or by --set) rather than taking the default.
  bool was_set(std::string_view key) const;
  // Where the key's value came from: the file path, "--set", or "default".
  const std::string& source_of(std::string_view key) const;

  // For messages of derived bounds (a limit computed from other keys): each key with its value
  // and where it came from, "contact.kn = 10000.0 (default), time.dt_fraction = 1.0 (--set)".
  std::string describe(const std::vector<std::string_view>& keys) const;
  // Where a derived bound's keys were set, for the message's heading: the distinct sources other
  // than the default ("--set", "FILE and --set"), or "default" when none was set.
  std::string sources_of(const std::vector<std::string_view>& keys) const;

  // The fully resolved configuration as TOML, every key in schema order with its doc; loading
  // it back gives the same configuration (floats round-trip exactly).
  std::string to_toml() const;

  // Named materials ([materials.NAME], in file order) and the incoming section ([[layer.units]],
  // from the base up): both empty for the thesis's one material (docs/materials.md).
  const MaterialTable& materials() const { return layering_.materials; }
  const std::vector<LayerUnit>& units() const { return layering_.materials.units; }
  // Where the materials or the units were given, for messages ("default" when not).
  const std::string& materials_source() const { return layering_.source; }

 private:
  const ConfigValue& lookup(std::string_view key, KeyType type) const;
  LayeringConfig layering_;

  std::vector<ConfigValue> values_;   // one per schema() entry, same order
  std::vector<std::string> sources_;  // "default", "--set" or the file path
};

}  // namespace orogen
