#pragma once
// The table of every configuration key: name, type, default, allowed values and a one-line
// doc. Config (config.hpp) validates against it, writes the resolved copy from it, and
// docs/configuration.md is generated from it (reference_markdown), so they cannot drift.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace orogen {

// Limits on input, beyond each key's range (docs/configuration.md lists them).
constexpr int kMaxThreads = 1024;          // run.threads and --threads
constexpr int kMaxOutputs = 100000;        // *.outputs
constexpr double kMaxParticles = 50e6;     // estimated discs (and surface columns) of a run
constexpr std::uintmax_t kMaxConfigBytes = 1 << 20;  // size of a configuration file
constexpr int kMaxConfigNesting = 32;      // brackets and dotted-key levels in a configuration file

enum class KeyType : std::uint8_t { Float, Int, Bool, String };

// A configuration value; the alternative always matches the key's KeyType.
using ConfigValue = std::variant<double, std::int64_t, bool, std::string>;

// One end of an allowed range.
struct Bound {
  double value = 0;
  bool inclusive = true;
};

// What a key may change in a run that exists, declared with the key so that the run driver
// names none (a new experiment declares its own): Display, only how fast or visibly it goes
// (outside the run's identity, changed by any resume); RunEnd and OutputCount, the end of the
// run and the number of outputs over it (a resume may move the end on, the outputs following
// at the same spacing: wedge.s_end, wedge.outputs); OnBranch, a key that acts on the state
// as it stands, so a branch (--from) may change it (friction, erosion).
enum KeyChange : std::uint8_t { kChangesNothing = 0, kDisplay = 1, kRunEnd = 2, kOutputCount = 4, kOnBranch = 8 };

struct KeySpec {
  std::string name;  // dotted "section.key"
  KeyType type = KeyType::Float;
  ConfigValue default_value;
  std::optional<Bound> min, max;     // numeric keys only; either may be absent
  std::vector<std::string> choices;  // string keys only; empty = any string
  std::string doc;                   // one line, unit in brackets
  std::uint8_t changes = kChangesNothing;  // KeyChange flags

  std::string_view section() const;  // "contact" of "contact.kn"
  std::string_view key() const;      // "kn" of "contact.kn"
};

// Every key, grouped by section, in the order the resolved copy lists them.
const std::vector<KeySpec>& schema();

// The keys of one named material, [materials.NAME] (docs/materials.md), by their short names
// ("friction"). All are numbers; `friction` is required, friction_residual defaults to
// friction and bond_shear_strength to bond_tensile_strength (their specs' defaults are unused).
const std::vector<KeySpec>& material_schema();
const KeySpec* find_material_key(std::string_view key);

// Index into schema() of a dotted name, or nullopt.
std::optional<std::size_t> find_key(std::string_view name);

// A key added after runs were made, with the value (as TOML writes it) that computes what
// those runs computed: a stored resolved configuration that lacks the key holds that value,
// and the key enters a run's identity only when set away from it, so that older runs keep
// their identity and resume as they were (config/run_identity.hpp). For most such keys the
// value before is the default; for a fixed defect (wedge.traction_law) it is the old law.
struct LaterKey {
  std::string name;
  std::string before;
};
// A later key of every material is named kAnyMaterial + KEY ("materials.*.KEY"): find_later_key
// finds it for materials.NAME.KEY of any NAME; it names no key of schema().
inline constexpr std::string_view kAnyMaterial = "materials.*.";
const std::vector<LaterKey>& later_keys();
const LaterKey* find_later_key(std::string_view name);  // nullptr: not a later key

// Whether the key carries the KeyChange flag; the keys that do, in schema order.
bool key_may(std::string_view name, KeyChange change);
std::vector<std::string> keys_that(KeyChange change);

// Section names in schema order.
std::vector<std::string> schema_sections();

// Human text for messages and docs: "a number", "an integer", "true or false", "a string".
std::string type_text(KeyType type);
// The allowed values alone: "> 0 and <= 1", "one of \"a\", \"b\"", or "" when anything of the
// right type goes.
std::string allowed_text(const KeySpec& spec);

// Shortest text that parses back to exactly `x` and reads as a TOML float ("10000.0", "1e-06").
std::string format_float(double x);
// A value as TOML writes it (strings quoted and escaped).
std::string format_value(const ConfigValue& value);

// The reference table of docs/configuration.md (markdown, one row per key).
std::string reference_markdown();

}  // namespace orogen
