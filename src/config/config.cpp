#include "config/config.hpp"
#include "config/config_materials.hpp"
#include "config/toml_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <type_traits>
#include <utility>

namespace orogen {
namespace {

const std::string kDefault = "default";
// The first line of every resolved configuration Orogen writes (Config::to_toml).
constexpr std::string_view kResolvedHeading = "# Orogen configuration, fully resolved: every key with the value used.";
const std::string kSetSource = "--set";

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// Close enough to be a typo rather than a different word.
bool plausible(std::size_t distance, std::string_view word) {
  return distance <= std::max<std::size_t>(2, word.size() / 2);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::vector<std::string> keys_of_section(std::string_view section) {
  std::vector<std::string> out;
  for (const auto& k : schema())
    if (k.section() == section) out.emplace_back(k.key());
  return out;
}

std::string unknown_section_text(std::string_view section) {
  const auto sections = schema_sections();
  std::string best;
  std::size_t best_d = SIZE_MAX;
  for (const auto& s : sections)
    if (std::size_t d = edit_distance(section, s); d < best_d) best_d = d, best = s;
  std::string out = "unknown section [" + std::string(section) + "] (";
  if (plausible(best_d, section)) out += "did you mean [" + best + "]? ";
  return out + "sections: " + join(sections) + ")";
}

// Why `name` is unknown, with the likeliest intended key and the valid alternatives.
std::string unknown_key_text(std::string_view name) {
  const auto dot = name.find('.');
  const auto sections = schema_sections();
  if (dot == std::string_view::npos) {
    // A bare key: the user may have forgotten the section.
    const KeySpec* best = nullptr;
    std::size_t best_d = SIZE_MAX;
    for (const auto& k : schema()) {
      std::size_t d = edit_distance(name, k.key());
      if (d < best_d) best_d = d, best = &k;
    }
    std::string out = "unknown key (";
    if (best && plausible(best_d, name)) out += "did you mean '" + best->name + "'? ";
    return out + "every key belongs in a section: " + join(sections) + ")";
  }
  const auto section = name.substr(0, dot);
  const auto key = name.substr(dot + 1);
  if (std::find(sections.begin(), sections.end(), section) == sections.end())
    return unknown_section_text(section);
  // Known section: the key may live in another section ("contact.dt"), or be a typo.
  std::string suggestion;
  for (const auto& k : schema())
    if (k.key() == key) suggestion = k.name;
  if (suggestion.empty()) {
    std::size_t best_d = SIZE_MAX;
    for (const auto& k : schema()) {
      if (k.section() != section) continue;
      if (std::size_t d = edit_distance(key, k.key()); d < best_d) best_d = d, suggestion = k.name;
    }
    if (!plausible(best_d, key)) suggestion.clear();
  }
  std::string out = "unknown key (";
  if (!suggestion.empty()) out += "did you mean '" + suggestion + "'? ";
  return out + "keys in [" + std::string(section) + "]: " + join(keys_of_section(section)) + ")";
}

// What a value of this key must be, for type errors: "a number > 0", "an integer >= 0".
std::string expected_text(const KeySpec& spec) {
  std::string allowed = allowed_text(spec);
  if (spec.type == KeyType::String && !allowed.empty()) return "a string, " + allowed;
  return type_text(spec.type) + (allowed.empty() ? "" : " " + allowed);
}

// A node as the user wrote it, for messages.
std::string render(const toml::node& node) {
  return node.visit([](const auto& v) -> std::string {
    using T = std::decay_t<decltype(v)>;
    if constexpr (std::is_same_v<T, toml::table>) {
      return "{...}";
    } else if constexpr (std::is_same_v<T, toml::array>) {
      return "[...]";
    } else if constexpr (std::is_same_v<T, toml::value<std::string>>) {
      return format_value(ConfigValue{std::string(v.get())});
    } else if constexpr (std::is_same_v<T, toml::value<double>>) {
      return format_float(v.get());
    } else {
      std::ostringstream os;
      os << v;
      return os.str();
    }
  });
}

// Converts a TOML node to the key's type, then checks range and choices.
// `shown` is the value as the user wrote it (for the message).
ConfigValue convert(const KeySpec& spec, const toml::node& node, const std::string& source,
                    const std::string& shown) {
  auto type_error = [&] {
    return config_error(source, spec.name, shown, "expected " + expected_text(spec));
  };
  ConfigValue value;
  switch (spec.type) {
    case KeyType::Float:
      // Integers are fine where a number is expected ("kn = 10000").
      if (auto i = node.value_exact<std::int64_t>())
        value = static_cast<double>(*i);
      else if (auto d = node.value_exact<double>())
        value = *d;
      else
        throw type_error();
      if (!std::isfinite(std::get<double>(value)))
        throw config_error(source, spec.name, shown,
                           "must be a finite number " + allowed_text(spec));
      break;
    case KeyType::Int:
      if (auto i = node.value_exact<std::int64_t>()) {
        value = *i;
      } else if (auto d = node.value_exact<double>();
                 d && std::floor(*d) == *d && std::abs(*d) < 9.2e18) {
        value = static_cast<std::int64_t>(*d);  // "1e4" is a fine seed, "2.5" is not
      } else {
        throw type_error();
      }
      break;
    case KeyType::Bool:
      if (auto b = node.value_exact<bool>())
        value = *b;
      else
        throw type_error();
      break;
    case KeyType::String:
      if (auto s = node.value_exact<std::string>())
        value = *s;
      else
        throw type_error();
      break;
  }

  if (spec.type == KeyType::Float || spec.type == KeyType::Int) {
    double x = spec.type == KeyType::Float ? std::get<double>(value)
                                           : static_cast<double>(std::get<std::int64_t>(value));
    bool ok = true;
    if (spec.min) ok = ok && (spec.min->inclusive ? x >= spec.min->value : x > spec.min->value);
    if (spec.max) ok = ok && (spec.max->inclusive ? x <= spec.max->value : x < spec.max->value);
    if (!ok) throw config_error(source, spec.name, shown, "must be " + allowed_text(spec));
  }
  if (spec.type == KeyType::String && !spec.choices.empty()) {
    const auto& s = std::get<std::string>(value);
    if (std::find(spec.choices.begin(), spec.choices.end(), s) == spec.choices.end())
      throw config_error(source, spec.name, shown, "must be " + allowed_text(spec));
  }
  return value;
}

std::string where(const std::string& path, const toml::source_region& region) {
  return region.begin.line ? path + ", line " + std::to_string(region.begin.line) : path;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// toml++ parses nested tables, arrays and dotted keys recursively, so a hostile file 50,000
// levels deep overflows the stack. This scan runs first and refuses deep nesting: the bracket
// depth ([ and {, across lines) and the dots of one line (a dotted key or [header]; the dot of
// a number such as 1.5 does not count), outside strings and comments. Returns the first line
// over kMaxConfigNesting (1 for a one-line text), or 0.
std::size_t too_deep_line(std::string_view text) {
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t line = 1;
  int depth = 0, dots = 0;
  char quote = 0;  // the open string's quote, or 0 (strings may span lines)
  bool comment = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line;
      comment = false;
      dots = 0;
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (escaped) escaped = false;
      else if (ch == '\\' && quote == '"') escaped = true;
      else if (ch == quote) quote = 0;
      continue;
    }
    switch (ch) {
      case '"': case '\'': quote = ch; break;
      case '#': comment = true; break;
      case '[': case '{': ++depth; break;
      case ']': case '}': --depth; break;
      case '.':
        if (!(i > 0 && digit(text[i - 1]) && i + 1 < text.size() && digit(text[i + 1]))) ++dots;
        break;
      default: break;
    }
    if (depth > kMaxConfigNesting || dots > kMaxConfigNesting) return line;
  }
  return 0;
}

std::string nesting_text() {
  return "nested too deeply (more than " + std::to_string(kMaxConfigNesting) +
         " levels of [ ], { } or dots in a key); Orogen's keys are section.key";
}

// The file's text; refuses what is not a regular file (a directory, /dev/zero, a pipe) and
// files over kMaxConfigBytes, which no configuration comes near, before reading them.
std::string read_config_text(const std::filesystem::path& file) {
  const std::string path = file.string();
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
    throw config_error(path, "", "", "cannot read the file (does it exist?)");
  if (!std::filesystem::is_regular_file(status))
    throw config_error(path, "", "", "not a regular file; a configuration is a TOML file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || size > kMaxConfigBytes)
    throw config_error(path, "", "",
                       "the file is larger than " + std::to_string(kMaxConfigBytes) +
                           " bytes (1 MiB), the most a configuration file may hold");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw config_error(path, "", "", "cannot read the file (does it exist?)");
  std::string text(kMaxConfigBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  // The file may have grown since it was measured.
  if (text.size() > kMaxConfigBytes)
    throw config_error(path, "", "", "the file is larger than 1 MiB, the most a configuration file may hold");
  return text;
}

toml::table parse_toml_text(const std::string& text, const std::string& path) {
  if (const std::size_t line = too_deep_line(text))
    throw config_error(path + ", line " + std::to_string(line), "", "", nesting_text());
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw config_error(
        path + ", line " + std::to_string(b.line) + ", column " + std::to_string(b.column), "", "",
        "TOML syntax error: " + std::string(e.description()));
  }
}

}  // namespace

toml::table parse_toml_file(const std::filesystem::path& file) {
  return parse_toml_text(read_config_text(file), file.string());
}

ConfigError config_error(std::string_view source, std::string_view key, std::string_view value,
                         std::string_view allowed) {
  std::string msg = "config error in " + std::string(source);
  if (!key.empty()) msg += ": " + std::string(key);
  if (!value.empty()) msg += " = " + std::string(value);
  msg += ": " + std::string(allowed);
  return ConfigError(msg);
}

Config::Config() {
  for (const auto& k : schema()) {
    values_.push_back(k.default_value);
    sources_.push_back(kDefault);
  }
}

Config Config::load(const std::optional<std::filesystem::path>& file,
                    const std::vector<std::string>& overrides) {
  Config cfg;
  if (file) {
    const std::string path = file->string();
    const std::string text = read_config_text(*file);
    toml::table root = parse_toml_text(text, path);
    take_layering(root, path, cfg.layering_);  // [materials.NAME], [[layer.units]]: not flat keys
    // Gather every leaf with its dotted name, then report in file order (toml++ sorts keys).
    struct Entry {
      std::string name;
      const toml::node* node;
    };
    std::vector<Entry> entries;
    for (const auto& [k, node] : root) {
      const std::string name(k.str());
      if (const auto* section = node.as_table(); section && !section->empty()) {
        for (const auto& [k2, leaf] : *section)
          entries.push_back({name + "." + std::string(k2.str()), &leaf});
      } else {
        entries.push_back({name, &node});
      }
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      const auto &ra = a.node->source().begin, &rb = b.node->source().begin;
      return std::pair(ra.line, ra.column) < std::pair(rb.line, rb.column);
    });
    const auto sections = schema_sections();
    for (const auto& e : entries) {
      const std::string src = where(path, e.node->source());
      const auto idx = find_key(e.name);
      if (!idx) {
        const bool is_section =
            std::find(sections.begin(), sections.end(), e.name) != sections.end();
        if (is_section && e.node->is_table()) continue;  // an empty [section]: all defaults
        if (is_section)
          throw config_error(src, e.name, render(*e.node),
                             "expected a table: write [" + e.name + "] and its keys below it");
        throw config_error(
            src, e.name, render(*e.node),
            e.node->is_table() ? unknown_section_text(e.name) : unknown_key_text(e.name));
      }
      cfg.values_[*idx] = convert(schema()[*idx], *e.node, src, render(*e.node));
      cfg.sources_[*idx] = path;
    }
    // A configuration Orogen wrote (a run's config.toml) that lacks a key added later is of a
    // run made before the key: the key holds the value that computes what that run computed.
    if (text.find(kResolvedHeading) != std::string::npos)
      for (const auto& later : later_keys()) {
        if (later.name.starts_with(kAnyMaterial)) continue;  // a material's: its default is the value before
        const std::size_t idx = *find_key(later.name);
        if (cfg.sources_[idx] != kDefault || later.before == format_value(cfg.values_[idx])) continue;
        const toml::table parsed = toml::parse("v = " + later.before);
        cfg.values_[idx] = convert(schema()[idx], *parsed.get("v"), path, later.before);
        cfg.sources_[idx] = path;
      }
  }

  for (const auto& arg : overrides) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos || trim(std::string_view(arg).substr(0, eq)).empty())
      throw config_error(kSetSource, arg, "", "expected section.key=value");
    const std::string name(trim(std::string_view(arg).substr(0, eq)));
    const std::string raw(trim(std::string_view(arg).substr(eq + 1)));
    const std::string shown = raw.empty() ? "\"\"" : raw;
    if (is_material_override(name)) {
      set_material_override(cfg.layering_, name, raw);
      continue;
    }
    const auto idx = find_key(name);
    if (!idx) throw config_error(kSetSource, name, shown, unknown_key_text(name));
    const KeySpec& spec = schema()[*idx];
    // Values are read as TOML ("1e4", "true", "\"x\""); a string may also be given bare.
    const bool quoted = !raw.empty() && (raw.front() == '"' || raw.front() == '\'');
    if (spec.type == KeyType::String && !quoted) {
      cfg.values_[*idx] = convert(spec, toml::value<std::string>(raw), kSetSource, shown);
    } else {
      if (too_deep_line(raw)) throw config_error(kSetSource, name, "", nesting_text());
      toml::table parsed;
      try {
        parsed = toml::parse("v = " + raw);
      } catch (const toml::parse_error&) {
      }
      const toml::node* node = parsed.size() == 1 ? parsed.get("v") : nullptr;
      if (!node) throw config_error(kSetSource, name, shown, "expected " + expected_text(spec));
      cfg.values_[*idx] = convert(spec, *node, kSetSource, shown);
    }
    cfg.sources_[*idx] = kSetSource;
  }
  finish_layering(cfg.layering_, cfg.get_float("layer.thickness"), cfg.source_of("layer.thickness"),
                  cfg.get_float("contact.rolling_friction"));
  return cfg;
}

ConfigValue convert_value(const KeySpec& spec, const toml::node& node, const std::string& source,
                          const std::string& shown) {
  return convert(spec, node, source, shown);
}

std::string render_node(const toml::node& node) { return render(node); }

const ConfigValue& Config::lookup(std::string_view key, KeyType type) const {
  const auto idx = find_key(key);
  if (!idx) throw std::logic_error("Config: unknown key '" + std::string(key) + "'");
  if (schema()[*idx].type != type)
    throw std::logic_error("Config: key '" + std::string(key) + "' is not " + type_text(type));
  return values_[*idx];
}

double Config::get_float(std::string_view key) const {
  return std::get<double>(lookup(key, KeyType::Float));
}

std::int64_t Config::get_int(std::string_view key) const {
  return std::get<std::int64_t>(lookup(key, KeyType::Int));
}

int Config::get_int32(std::string_view key) const {
  const std::int64_t v = get_int(key);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw std::logic_error("Config: key '" + std::string(key) + "' = " + std::to_string(v) + " does not fit an int");
  return static_cast<int>(v);
}

bool Config::get_bool(std::string_view key) const {
  return std::get<bool>(lookup(key, KeyType::Bool));
}

const std::string& Config::get_string(std::string_view key) const {
  return std::get<std::string>(lookup(key, KeyType::String));
}

bool Config::was_set(std::string_view key) const { return source_of(key) != kDefault; }

const std::string& Config::source_of(std::string_view key) const {
  const auto idx = find_key(key);
  if (!idx) throw std::logic_error("Config: unknown key '" + std::string(key) + "'");
  return sources_[*idx];
}

std::string Config::describe(const std::vector<std::string_view>& keys) const {
  std::string out;
  for (const auto key : keys) {
    const auto idx = find_key(key);
    if (!idx) throw std::logic_error("Config: unknown key '" + std::string(key) + "'");
    out += (out.empty() ? "" : ", ") + std::string(key) + " = " + format_value(values_[*idx]) + " (" +
           sources_[*idx] + ")";
  }
  return out;
}

std::string Config::sources_of(const std::vector<std::string_view>& keys) const {
  std::vector<std::string> seen;
  for (const auto key : keys) {
    const std::string& src = source_of(key);
    if (src != kDefault && std::find(seen.begin(), seen.end(), src) == seen.end()) seen.push_back(src);
  }
  if (seen.empty()) return kDefault;
  std::string out;
  for (const auto& s : seen) out += (out.empty() ? "" : " and ") + s;
  return out;
}

std::string Config::to_toml() const {
  std::string out = std::string(kResolvedHeading) + "\n";
  std::string_view section;
  const auto& s = schema();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].section() != section) {
      if (section == "layer") out += units_toml(layering_);  // a key of [layer] outside the schema
      section = s[i].section();
      out += "\n[" + std::string(section) + "]\n";
    }
    std::string allowed = allowed_text(s[i]);
    if (s[i].type == KeyType::Int) allowed = "integer " + allowed;
    if (allowed.empty()) allowed = s[i].type == KeyType::Bool ? "true or false" : "any";
    out += "# " + s[i].doc + " (allowed: " + allowed + ")\n";
    out += std::string(s[i].key()) + " = " + format_value(values_[i]) + "\n";
  }
  return out + materials_toml(layering_);
}

}  // namespace orogen
