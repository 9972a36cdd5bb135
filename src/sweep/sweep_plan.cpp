#include "sweep/sweep_plan.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "config/config.hpp"
#include "config/toml_file.hpp"
#include "config/schema.hpp"
#include "experiments/experiment.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// More runs than this is a typo in the matrix rather than a plan.
constexpr std::size_t kMaxRuns = 100000;

std::string where(const std::string& path, const toml::source_region& region) {
  return region.begin.line ? fmt::format("{}, line {}", path, region.begin.line) : path;
}

// A scalar as TOML text (for --set) and as a table shows it (strings without quotes).
struct ValueText {
  std::string toml, shown;
};

std::optional<ValueText> value_text(const toml::node& node) {
  if (auto s = node.value_exact<std::string>()) return ValueText{format_value(ConfigValue{*s}), *s};
  if (auto i = node.value_exact<std::int64_t>()) return ValueText{std::to_string(*i), std::to_string(*i)};
  if (auto d = node.value_exact<double>()) return ValueText{format_float(*d), format_float(*d)};
  if (auto b = node.value_exact<bool>()) return ValueText{*b ? "true" : "false", *b ? "true" : "false"};
  return std::nullopt;
}

// A node as the user wrote it, for messages.
std::string render(const toml::node& node) {
  if (node.is_table()) return "{...}";
  if (node.is_array()) return "[...]";
  if (auto v = value_text(node)) return v->toml;
  return "?";
}

// Every leaf under a table with its dotted name, in file order ("output.vtp" = false,
// output.vtp = false and [set.output] vtp = false all name the key output.vtp).
struct Leaf {
  std::string name;
  const toml::node* node;
};

void flatten(const toml::table& table, const std::string& prefix, std::vector<Leaf>& out) {
  for (const auto& [k, node] : table) {
    const std::string name = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = node.as_table())
      flatten(*sub, name, out);
    else
      out.push_back({name, &node});
  }
}

std::vector<Leaf> leaves(const toml::table& table) {
  std::vector<Leaf> out;
  flatten(table, "", out);
  // toml++ keeps keys sorted; messages and run order follow the file instead.
  std::stable_sort(out.begin(), out.end(), [](const Leaf& a, const Leaf& b) {
    const auto &ra = a.node->source().begin, &rb = b.node->source().begin;
    return std::pair(ra.line, ra.column) < std::pair(rb.line, rb.column);
  });
  return out;
}

// Resolves and checks one run's configuration as `orogen run` would before writing anything:
// the keys, the experiment's cross-key checks and the time step. Returns the resolved TOML.
std::string resolve(const fs::path& base, const std::vector<std::string>& overrides) {
  const Config config = Config::load(base, overrides);
  (void)make_experiment(config);
  World scratch;
  apply_engine_config(config, scratch);
  return config.to_toml();
}

// Runs `check`; a ConfigError about a --set value is re-thrown as one at `source`, because
// the user wrote that value in the sweep file, not on a command line. Other errors (in the
// base preset, say) already name their source; anything else becomes a ConfigError at `source`.
template <class F>
auto at_source(const std::string& source, F&& check) {
  static const std::string kSetPrefix = "config error in --set";
  try {
    return check();
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    if (msg.starts_with(kSetPrefix)) throw ConfigError("config error in " + source + msg.substr(kSetPrefix.size()));
    throw;
  } catch (const std::exception& e) {
    throw config_error(source, "", "", e.what());
  }
}


// Keeps run names portable and shell-friendly: letters, digits and ._+- only.
std::string sanitise(const std::string& value) {
  std::string out;
  for (char c : value.substr(0, 40)) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '_' || c == '+' || c == '-';
    out += ok ? c : '-';
  }
  return out.empty() ? "-" : out;
}

void name_runs(SweepPlan& plan) {
  // Short labels ("mu") unless two keys share one ("contact.mu", "wall.mu"): then the full key.
  std::map<std::string, int> uses;
  for (auto& a : plan.axes) {
    a.label = a.key.substr(a.key.rfind('.') + 1);
    ++uses[a.label];
  }
  for (auto& a : plan.axes)
    if (uses[a.label] > 1) a.label = a.key;
  const std::size_t width = std::max<std::size_t>(3, std::to_string(plan.runs.size() - 1).size());
  for (auto& run : plan.runs) {
    run.name = fmt::format("{:0{}d}", run.index, width);
    for (std::size_t a = 0; a < plan.axes.size(); ++a)
      run.name += "_" + plan.axes[a].label + "=" + sanitise(plan.axes[a].shown[run.choice[a]]);
  }
}

}  // namespace

SweepPlan load_sweep(const fs::path& file) {
  SweepPlan plan;
  plan.file = file;
  const std::string path = file.string();
  const toml::table root = parse_toml_file(file);

  const toml::table *sweep = nullptr, *set = nullptr, *matrix = nullptr;
  for (const auto& [k, node] : root) {
    const std::string name(k.str());
    const toml::table** slot = name == "sweep" ? &sweep : name == "set" ? &set : name == "matrix" ? &matrix : nullptr;
    if (!slot)
      throw config_error(where(path, node.source()), node.is_table() ? "[" + name + "]" : name,
                         node.is_table() ? "" : render(node),
                         "unknown table (a sweep file has the tables [sweep], [set] and [matrix])");
    if (!node.is_table())
      throw config_error(where(path, node.source()), name, render(node),
                         "expected a table: write [" + name + "] and its keys below it");
    *slot = node.as_table();
  }

  // [sweep]: where the runs start from.
  const toml::node* base_node = nullptr;
  if (sweep) {
    for (const auto& leaf : leaves(*sweep)) {
      if (leaf.name != "base")
        throw config_error(where(path, leaf.node->source()), "sweep." + leaf.name, render(*leaf.node),
                           "unknown key (keys in [sweep]: base)");
      base_node = leaf.node;
    }
  }
  if (!base_node)
    throw config_error(path, "sweep.base", "", "missing: name the preset the runs start from, relative to the sweep "
                                               "file: [sweep] base = \"../preset.toml\"");
  const auto base_text = base_node->value_exact<std::string>();
  if (!base_text || base_text->empty())
    throw config_error(where(path, base_node->source()), "sweep.base", render(*base_node),
                       "expected the path of a preset (a string), relative to the sweep file");
  plan.base = fs::absolute(file.parent_path() / *base_text).lexically_normal();
  if (!fs::is_regular_file(plan.base))
    throw config_error(where(path, base_node->source()), "sweep.base", render(*base_node),
                       "expected a preset file, relative to the sweep file: " + plan.base.string() + " does not exist");
  (void)resolve(plan.base, {});  // the base alone: its own errors name the base file

  // [set]: fixed overrides, each checked at its line.
  if (set) {
    for (const auto& leaf : leaves(*set)) {
      const std::string src = where(path, leaf.node->source());
      const auto v = value_text(*leaf.node);
      if (!v)
        throw config_error(src, leaf.name, render(*leaf.node),
                           "expected one value: a number, string or boolean (lists of values belong in [matrix])");
      plan.fixed.push_back(leaf.name + "=" + v->toml);
      at_source(src, [&] { return resolve(plan.base, plan.fixed); });
    }
  }

  // [matrix]: the swept keys, each value checked at its line with the fixed overrides.
  if (matrix) {
    for (const auto& leaf : leaves(*matrix)) {
      const std::string src = where(path, leaf.node->source());
      const auto* list = leaf.node->as_array();
      if (!list)
        throw config_error(src, leaf.name, render(*leaf.node),
                           "expected a list of values, e.g. [0.1, 0.3] (a single value belongs in [set])");
      if (list->empty()) throw config_error(src, leaf.name, "[]", "expected at least one value");
      if (std::any_of(plan.fixed.begin(), plan.fixed.end(),
                      [&](const std::string& f) { return f.starts_with(leaf.name + "="); }))
        throw config_error(src, leaf.name, render(*leaf.node), "also in [set]: a key is either fixed or swept");
      SweepAxis axis{leaf.name, "", {}, {}};
      for (const auto& element : *list) {
        const std::string esrc = where(path, element.source());
        const auto v = value_text(element);
        if (!v)
          throw config_error(esrc, leaf.name, render(element), "expected a list of numbers, strings or booleans");
        if (std::find(axis.toml.begin(), axis.toml.end(), v->toml) != axis.toml.end())
          throw config_error(esrc, leaf.name, v->toml, "listed twice: give each value once");
        auto overrides = plan.fixed;
        overrides.push_back(leaf.name + "=" + v->toml);
        // An unknown key fails here too, with the configuration's own "did you mean" hint.
        at_source(esrc, [&] { return resolve(plan.base, overrides); });
        axis.toml.push_back(v->toml);
        axis.shown.push_back(v->shown);
      }
      plan.axes.push_back(std::move(axis));
    }
  }

  std::size_t total = 1;
  for (const auto& a : plan.axes) {
    total *= a.toml.size();
    if (total > kMaxRuns)
      throw config_error(path, "matrix", "", fmt::format("makes more than {} runs; sweep fewer values", kMaxRuns));
  }
  for (std::size_t index = 0; index < total; ++index) {
    SweepRun run;
    run.index = index;
    run.choice.resize(plan.axes.size());
    std::size_t rest = index;
    for (std::size_t a = plan.axes.size(); a-- > 0;) {  // the last axis varies fastest
      run.choice[a] = rest % plan.axes[a].toml.size();
      rest /= plan.axes[a].toml.size();
    }
    run.overrides = plan.fixed;
    for (std::size_t a = 0; a < plan.axes.size(); ++a)
      run.overrides.push_back(plan.axes[a].key + "=" + plan.axes[a].toml[run.choice[a]]);
    plan.runs.push_back(std::move(run));
  }
  name_runs(plan);
  // Every combination as a whole: cross-key checks may fail only for some of them.
  for (auto& run : plan.runs)
    run.resolved_toml = at_source(path + " (run " + run.name + ")", [&] { return resolve(plan.base, run.overrides); });
  return plan;
}

}  // namespace orogen
