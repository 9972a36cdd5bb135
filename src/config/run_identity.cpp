#include "config/run_identity.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "config/config.hpp"
#include "config/schema.hpp"
#include "io/binary_archive.hpp"
#include "io/snapshot_reader.hpp"

namespace orogen {
namespace {

// The keys that extend a run (the schema's RunEnd and OutputCount keys), in schema order.
const std::vector<std::string>& extension_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const KeySpec& spec : schema())
      if (spec.changes & (kRunEnd | kOutputCount)) k.push_back(spec.name);
    return k;
  }();
  return keys;
}

}  // namespace

// "section.key" -> value text of each assignment line of a resolved configuration.
std::map<std::string, std::string> key_values(std::string_view toml) {
  std::map<std::string, std::string> out;
  std::string section;
  std::size_t begin = 0;
  while (begin < toml.size()) {
    std::size_t end = toml.find('\n', begin);
    if (end == std::string_view::npos) end = toml.size();
    const std::string_view line = toml.substr(begin, end - begin);
    begin = end + 1;
    if (line.empty() || line.front() == '#') continue;
    if (line.front() == '[' && line.back() == ']') {
      section = std::string(line.substr(1, line.size() - 2));
      continue;
    }
    const std::size_t eq = line.find(" = ");
    if (eq == std::string_view::npos) continue;
    out[section + "." + std::string(line.substr(0, eq))] = std::string(line.substr(eq + 3));
  }
  return out;
}

namespace {
// The key-value pairs of a stored configuration, a later key it lacks at its value before
// (schema.hpp, LaterKey).
std::map<std::string, std::string> stored_key_values(std::string_view toml) {
  auto kv = key_values(toml);
  for (const auto& key : later_keys())
    if (!key.name.starts_with(kAnyMaterial)) kv.emplace(key.name, key.before);
  return kv;
}
}  // namespace

std::string config_differences(std::string_view here, std::string_view there, std::string_view here_name,
                               std::string_view there_name) {
  const auto a = stored_key_values(here), b = stored_key_values(there);
  std::string out;
  auto add = [&](const std::string& key, const std::string& va, const std::string& vb) {
    out += fmt::format("{}{} = {} in {}, {} in {}", out.empty() ? "" : "; ", key, va.empty() ? "(absent)" : va,
                       here_name, vb.empty() ? "(absent)" : vb, there_name);
  };
  // Keys that may differ between the two: they extend a run, or change only how it goes or
  // what is computed from its outputs.
  auto free_to_differ = [](const std::string& key) {
    return is_extension_key(key) || is_analysis_key(key) || is_display_key(key);
  };
  // A material's later key that one side lacks holds its value before there (kAnyMaterial).
  auto absent_as_before = [](const std::string& key, const std::string& value) {
    const LaterKey* later = find_later_key(key);
    return later != nullptr && later->before == value;
  };
  for (const auto& [key, value] : a) {
    if (free_to_differ(key)) continue;
    const auto it = b.find(key);
    if (it == b.end()) {
      if (!absent_as_before(key, value)) add(key, value, "");
    } else if (it->second != value) {
      add(key, value, it->second);
    }
  }
  for (const auto& [key, value] : b)
    if (!a.contains(key) && !free_to_differ(key) && !absent_as_before(key, value)) add(key, "", value);
  return out;
}

// The [analysis] keys say only what is computed from the outputs, never what is simulated:
// outside the identity, and free to differ between a checkpoint and config.toml.
bool is_analysis_key(std::string_view key) { return key.starts_with("analysis."); }

bool is_display_key(std::string_view key) { return key_may(key, kDisplay); }

bool is_extension_key(std::string_view key) { return key_may(key, kRunEnd) || key_may(key, kOutputCount); }

std::string extension_changes(std::string_view now, std::string_view before) {
  const auto a = key_values(now), b = key_values(before);
  std::string out;
  for (const std::string& key : extension_keys()) {
    const auto ia = a.find(key), ib = b.find(key);
    if (ia == a.end() || ib == b.end() || ia->second == ib->second) continue;
    out += fmt::format("{}{} {} -> {}", out.empty() ? "" : ", ", key, ib->second, ia->second);
  }
  return out.empty() ? "no key changed" : out;
}

std::string extension_keys_text() { return fmt::format("{}", fmt::join(extension_keys(), ", ")); }

std::string run_identity(const Config& config) { return run_identity_of_toml(config.to_toml()); }

std::string run_identity_of_toml(std::string_view toml) {
  std::string text;
  for (const auto& [key, value] : key_values(toml)) {
    if (const LaterKey* later = find_later_key(key); later && later->before == value) continue;
    if (!is_display_key(key) && !is_extension_key(key) && !is_analysis_key(key))
      text += key + "=" + value + "\n";
  }
  return fmt::format("{:016x}", fnv1a64(text));
}

std::string foreign_output(const SnapshotReader& reader, std::int64_t k, const OutputStamp& stamp,
                           const std::string& identity, const std::string& config_toml) {
  if (stamp.config_toml.empty()) return "";
  const std::string theirs = run_identity_of_toml(stamp.config_toml);
  if (theirs == identity) return "";
  const std::string keys = config_differences(config_toml, stamp.config_toml, "this run", "that file");
  return fmt::format("{} comes from another run (identity {}, this run's is {}){}{}", reader.output_path(k).string(),
                     theirs, identity, keys.empty() ? "" : ": ", keys);
}

}  // namespace orogen
