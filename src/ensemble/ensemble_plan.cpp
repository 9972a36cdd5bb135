#include "ensemble/ensemble_plan.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "config/config.hpp"
#include "config/toml_file.hpp"
#include "config/schema.hpp"
#include "experiments/experiment.hpp"
#include "world/world.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// More members than this is a typo rather than a plan.
constexpr std::size_t kMaxMembers = 10000;

std::string where(const std::string& path, const toml::node& node) {
  const auto line = node.source().begin.line;
  return line ? fmt::format("{}, line {}", path, line) : path;
}

// A scalar as TOML text for --set; nullopt for tables, arrays and dates.
std::optional<std::string> scalar_text(const toml::node& node) {
  if (auto s = node.value_exact<std::string>()) return format_value(ConfigValue{*s});
  if (auto i = node.value_exact<std::int64_t>()) return std::to_string(*i);
  if (auto d = node.value_exact<double>()) return format_float(*d);
  if (auto b = node.value_exact<bool>()) return std::string(*b ? "true" : "false");
  return std::nullopt;
}

std::string shown(const toml::node& node) {
  if (node.is_table()) return "{...}";
  if (node.is_array()) return "[...]";
  return scalar_text(node).value_or("?");
}

// Overrides of a set table ("a.b" = 1, a.b = 1 and [x.set.a] b = 1 all mean key a.b), in file
// order, each "key=value"; a list or table value is refused at its line.
void collect_overrides(const toml::table& table, const std::string& prefix, const std::string& path,
                       const std::string& table_name, std::vector<std::pair<const toml::node*, std::string>>& out) {
  for (const auto& [k, node] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = node.as_table()) {
      collect_overrides(*sub, key, path, table_name, out);
      continue;
    }
    const auto text = scalar_text(node);
    if (!text)
      throw config_error(where(path, node), table_name + "." + key, shown(node),
                         "expected one value: a number, string or boolean");
    out.emplace_back(&node, key + "=" + *text);
  }
}

std::vector<std::string> overrides_of(const toml::table& table, const std::string& path, const std::string& name) {
  std::vector<std::pair<const toml::node*, std::string>> found;
  collect_overrides(table, "", path, name, found);
  // toml++ keeps keys sorted; later overrides win, so keep the file's order.
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    const auto &ra = a.first->source().begin, &rb = b.first->source().begin;
    return std::pair(ra.line, ra.column) < std::pair(rb.line, rb.column);
  });
  std::vector<std::string> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

// Every key of `table` must be one of `allowed`.
void only_keys(const toml::table& table, const std::string& path, const std::string& prefix,
               const std::vector<std::string>& allowed) {
  for (const auto& [k, node] : table) {
    const std::string key(k.str());
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw config_error(where(path, node), prefix + key, shown(node), "unknown key (allowed here: " + list + ")");
  }
}

std::string string_key(const toml::table& t, const std::string& key, const std::string& path, const std::string& full) {
  const toml::node* node = t.get(key);
  if (!node) return "";
  const auto s = node->value_exact<std::string>();
  if (!s || s->empty()) throw config_error(where(path, *node), full, shown(*node), "expected a non-empty string");
  return *s;
}

double number_key(const toml::table& t, const std::string& key, double fallback, double lower, bool strict,
                  const std::string& path, const std::string& full) {
  const toml::node* node = t.get(key);
  if (!node) return fallback;
  const auto v = node->value<double>();  // an integer is a number too
  if (!v || !node->is_number() || !std::isfinite(*v) || (strict ? *v <= lower : *v < lower))
    throw config_error(where(path, *node), full, shown(*node),
                       fmt::format("expected a number {} {}", strict ? ">" : ">=", format_float(lower)));
  return *v;
}

fs::path preset_path(const fs::path& file, const std::string& text, const toml::node& node, const std::string& key) {
  const fs::path p = fs::absolute(file.parent_path() / text).lexically_normal();
  if (!fs::is_regular_file(p))
    throw config_error(where(file.string(), node), key, shown(node),
                       "expected a preset file, relative to the ensemble file: " + p.string() + " does not exist");
  return p;
}

// Names are folder names: letters, digits and ._+- only.
bool good_name(const std::string& s) {
  return !s.empty() && s.size() <= 80 && s != "." && s != ".." && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '+' || c == '-';
  });
}

// Checks a member as `orogen run` would before writing anything (keys, cross-key checks, the
// time step); errors name the ensemble file and the member.
std::string resolve_member(const EnsembleMember& m, const std::string& source) {
  try {
    const Config config = Config::load(m.preset, m.overrides);
    (void)make_experiment(config);
    World scratch;
    apply_engine_config(config, scratch);
    return config.to_toml();
  } catch (const ConfigError& e) {
    std::string msg = e.what();
    const std::string prefix = "config error in ";
    if (msg.starts_with(prefix)) msg = msg.substr(prefix.size());
    throw ConfigError(fmt::format("config error in {} (member {}): {}", source, m.name, msg));
  } catch (const std::exception& e) {
    throw ConfigError(fmt::format("config error in {} (member {}): {}", source, m.name, e.what()));
  }
}


// A list of distinct seeds (run.seed values); empty when the key is absent.
std::vector<std::int64_t> read_seeds(const toml::node* node, const std::string& path, const std::string& key) {
  std::vector<std::int64_t> seeds;
  if (!node) return seeds;
  const auto* list = node->as_array();
  if (!list) throw config_error(where(path, *node), key, shown(*node), "expected a list of seeds, e.g. [1, 2, 3, 4]");
  if (list->empty()) throw config_error(where(path, *node), key, "[]", "expected at least one seed");
  for (const auto& e : *list) {
    const auto v = e.value_exact<std::int64_t>();
    if (!v || *v < 0 || *v > 2147483647)
      throw config_error(where(path, e), key, shown(e), "expected whole numbers from 0 to 2147483647");
    if (std::find(seeds.begin(), seeds.end(), *v) != seeds.end())
      throw config_error(where(path, e), key, shown(e), "listed twice: give each seed once");
    seeds.push_back(*v);
  }
  return seeds;
}

EnsembleStats read_stats(const toml::table* t, const std::string& path) {
  EnsembleStats s;
  for (const auto& name : ensemble_series()) s.offset[name] = "\"auto\"";
  if (!t) return s;
  only_keys(*t, path, "ensemble.stats.", {"s_min", "step_min", "sheet_reference", "offset"});
  s.s_min = number_key(*t, "s_min", s.s_min, 0.0, false, path, "ensemble.stats.s_min");
  s.step_min = number_key(*t, "step_min", s.step_min, 0.0, true, path, "ensemble.stats.step_min");
  s.sheet_reference = number_key(*t, "sheet_reference", s.sheet_reference, 0.0, true, path,
                                 "ensemble.stats.sheet_reference");
  if (const toml::node* node = t->get("offset")) {
    const auto* offsets = node->as_table();
    if (!offsets)
      throw config_error(where(path, *node), "ensemble.stats.offset", shown(*node),
                         "expected a table of series = \"auto\" | \"none\" | a number, e.g. { Dp = \"auto\", H = 0.0 }");
    only_keys(*offsets, path, "ensemble.stats.offset.", ensemble_series());
    for (const auto& [k, v] : *offsets) {
      const std::string key = "ensemble.stats.offset." + std::string(k.str());
      if (auto str = v.value_exact<std::string>()) {
        if (*str != "auto" && *str != "none")
          throw config_error(where(path, v), key, shown(v), "expected \"auto\", \"none\" or a number [h0]");
        s.offset[std::string(k.str())] = format_value(ConfigValue{*str});
      } else if (v.is_number() && std::isfinite(*v.value<double>())) {
        s.offset[std::string(k.str())] = format_float(*v.value<double>());
      } else {
        throw config_error(where(path, v), key, shown(v), "expected \"auto\", \"none\" or a number [h0]");
      }
    }
  }
  return s;
}

}  // namespace

EnsemblePlan load_ensemble(const fs::path& file) {
  EnsemblePlan plan;
  plan.file = file;
  const std::string path = file.string();
  const toml::table root = parse_toml_file(file);
  only_keys(root, path, "", {"ensemble", "member"});
  const auto* ens = root["ensemble"].as_table();
  if (!ens)
    throw config_error(path, "[ensemble]", "", "missing: an ensemble file starts with [ensemble] and preset = \"...\"");
  only_keys(*ens, path, "ensemble.", {"preset", "title", "seeds", "set", "stats"});
  plan.title = string_key(*ens, "title", path, "ensemble.title");
  if (plan.title.empty()) plan.title = file.stem().string();

  std::optional<fs::path> preset;
  if (const auto text = string_key(*ens, "preset", path, "ensemble.preset"); !text.empty())
    preset = preset_path(file, text, *ens->get("preset"), "ensemble.preset");

  const std::vector<std::int64_t> seeds = read_seeds(ens->get("seeds"), path, "ensemble.seeds");
  if (const toml::node* node = ens->get("set")) {
    if (!node->is_table())
      throw config_error(where(path, *node), "ensemble.set", shown(*node), "expected a table of key = value overrides");
    plan.fixed = overrides_of(*node->as_table(), path, "ensemble.set");
  }
  if (const toml::node* node = ens->get("stats"); node && !node->is_table())
    throw config_error(where(path, *node), "ensemble.stats", shown(*node), "expected a table");
  plan.stats = read_stats(ens->get_as<toml::table>("stats"), path);

  // The member entries: [[member]] tables, or one unnamed entry (the preset itself).
  struct Entry {
    std::string name;
    fs::path preset;
    std::vector<std::string> set;
    std::string source;
    std::vector<std::int64_t> seeds;  // its own, else the ensemble's
  };
  std::vector<Entry> entries;
  if (const toml::node* node = root.get("member")) {
    const auto* list = node->as_array();
    if (!list || !list->is_array_of_tables())
      throw config_error(where(path, *node), "member", shown(*node), "expected [[member]] tables");
    if (list->empty()) throw config_error(where(path, *node), "member", "[]", "expected at least one member");
    for (const auto& e : *list) {
      const auto& t = *e.as_table();
      const std::string src = where(path, e);
      only_keys(t, path, "member.", {"name", "preset", "set", "seeds"});
      Entry entry{string_key(t, "name", path, "member.name"), {}, {}, src, {}};
      entry.seeds = read_seeds(t.get("seeds"), path, "member.seeds");
      if (entry.seeds.empty()) entry.seeds = seeds;
      if (entry.name.empty()) throw config_error(src, "member.name", "", "missing: every [[member]] needs a name");
      if (!good_name(entry.name))
        throw config_error(where(path, *t.get("name")), "member.name", shown(*t.get("name")),
                           "expected letters, digits and . _ + - only (it names a folder), at most 80");
      for (const auto& other : entries)
        if (other.name == entry.name)
          throw config_error(where(path, *t.get("name")), "member.name", shown(*t.get("name")),
                             "listed twice: every member needs a name of its own");
      if (const auto text = string_key(t, "preset", path, "member.preset"); !text.empty())
        entry.preset = preset_path(file, text, *t.get("preset"), "member.preset");
      else if (preset)
        entry.preset = *preset;
      else
        throw config_error(src, "member.preset", "", "missing: give [ensemble] preset or a preset for this member");
      if (const toml::node* set = t.get("set")) {
        if (!set->is_table())
          throw config_error(where(path, *set), "member.set", shown(*set), "expected a table of key = value overrides");
        entry.set = overrides_of(*set->as_table(), path, "member.set");
      }
      entries.push_back(std::move(entry));
    }
  } else {
    if (!preset) throw config_error(path, "ensemble.preset", "", "missing: name the preset the members start from, "
                                                                 "relative to the ensemble file");
    if (seeds.empty())
      throw config_error(path, "ensemble.seeds", "", "missing: without [[member]] tables, list the seeds to run");
    entries.push_back({"", *preset, {}, path, seeds});
  }
  std::size_t total = 0;
  for (const auto& entry : entries) total += std::max<std::size_t>(1, entry.seeds.size());
  if (total > kMaxMembers) throw config_error(path, "ensemble.seeds", "", fmt::format("makes more than {} members", kMaxMembers));

  // Members: each entry once per seed (entry order, then seed order).
  for (const auto& entry : entries) {
    const auto& seeds_here = entry.seeds;
    const std::size_t n = std::max<std::size_t>(1, seeds_here.size());
    for (std::size_t k = 0; k < n; ++k) {
      EnsembleMember m;
      m.group = entry.name;
      m.preset = entry.preset;
      m.overrides = plan.fixed;
      m.overrides.insert(m.overrides.end(), entry.set.begin(), entry.set.end());
      m.name = entry.name;
      if (!seeds_here.empty()) {
        m.seed = seeds_here[k];
        m.overrides.push_back("run.seed=" + std::to_string(seeds_here[k]));
        m.name += (m.name.empty() ? "seed" : "_seed") + std::to_string(seeds_here[k]);
      }
      m.resolved_toml = resolve_member(m, entry.source);
      plan.members.push_back(std::move(m));
    }
  }
  std::set<std::string> names;
  for (const auto& m : plan.members)
    if (!names.insert(m.name).second)
      throw config_error(path, "member.name", m.name, "two members would share this folder name; rename one");
  return plan;
}

std::string plan_to_toml(const EnsemblePlan& plan) {
  // Written by hand (not toml++'s printer) so that the text is the same on every build.
  std::string out = "# The plan of an Orogen ensemble, written by `orogen ensemble` for the statistics\n"
                    "# (python3 -m orogen.stats) and for reading; docs/ensembles.md.\n\n[ensemble]\n";
  out += fmt::format("file = {}  # the ensemble file\n", format_value(ConfigValue{plan.file.string()}));
  out += fmt::format("title = {}\n", format_value(ConfigValue{plan.title}));
  out += "\n[stats]\n";
  out += fmt::format("s_min = {}  # power-law fits over S > s_min [h0]\n", format_float(plan.stats.s_min));
  out += fmt::format("step_min = {}  # a step-out: the front jumps outward by more than this between outputs [h0]\n",
                     format_float(plan.stats.step_min));
  out += fmt::format("sheet_reference = {}  # convergence per new pro thrust sheet to compare with [h0]\n",
                     format_float(plan.stats.sheet_reference));
  out += "\n[stats.offset]  # per series: \"auto\" (extrapolated to S = 0), \"none\" (0) or a value [h0]\n";
  for (const auto& name : ensemble_series()) out += fmt::format("{} = {}\n", name, plan.stats.offset.at(name));
  for (const auto& m : plan.members) {
    out += "\n[[member]]\n";
    out += fmt::format("name = {}  # folder under members/\n", format_value(ConfigValue{m.name}));
    out += fmt::format("group = {}  # its [[member]] entry; members of a group differ only in the seed\n",
                       format_value(ConfigValue{m.group}));
    if (m.seed) out += fmt::format("seed = {}\n", *m.seed);
    out += fmt::format("preset = {}\n", format_value(ConfigValue{m.preset.string()}));
    out += "overrides = [";
    for (std::size_t i = 0; i < m.overrides.size(); ++i)
      out += (i ? ", " : "") + format_value(ConfigValue{m.overrides[i]});
    out += "]\n";
  }
  return out;
}

}  // namespace orogen
