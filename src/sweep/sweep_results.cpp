#include "sweep/sweep_results.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "io/atomic_file.hpp"
#include "io/csv_series.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

struct Column {
  std::string name, description;
  bool numeric = true;  // right-aligned in Markdown
};

// One cell as results.csv writes it (exact) and as results.md shows it (rounded); empty: no value.
struct Cell {
  std::string exact, shown;
};

Cell number_cell(double x) {
  // Whole numbers (counts, steps) in full; the rest to 4 significant digits for reading.
  const bool whole = std::isfinite(x) && std::fabs(x) < 1e15 && std::floor(x) == x;
  return {fmt::format("{}", x), whole ? fmt::format("{:.0f}", x) : fmt::format("{:.4g}", x)};
}

Cell text_cell(const std::string& s) { return {s, s}; }

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string md_field(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "\\|";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out;
}

struct Table {
  std::vector<Column> columns;
  std::vector<std::vector<Cell>> rows;

  std::size_t column(const std::string& name, const std::string& description) {
    for (std::size_t j = 0; j < columns.size(); ++j)
      if (columns[j].name == name) return j;
    columns.push_back({name, description});
    for (auto& r : rows) r.resize(columns.size());
    return columns.size() - 1;
  }
};

Table build_table(const fs::path& out_dir, const SweepPlan& plan, const std::vector<SweepOutcome>& outcomes,
                  bool with_render) {
  Table t;
  t.columns.push_back({"name", "the run's folder under runs/ (index, then the swept values)", false});
  for (const auto& a : plan.axes) {
    bool numeric = true;
    for (const auto& v : a.toml) numeric = numeric && (v.empty() || v.front() != '"') && v != "true" && v != "false";
    t.columns.push_back({a.key, "swept configuration key", numeric});
  }
  t.columns.push_back({"exit_status", "of `orogen run`: 0 finished, 2 bad input, 3 unstable, 128+N killed by signal "
                                      "N; empty: not run (yet)"});
  if (with_render)
    t.columns.push_back({"render_status", "of `orogen render` (the first that failed): 0 drawn; empty: not drawn"});
  const std::size_t fixed = t.columns.size();
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const auto& run = plan.runs[i];
    std::vector<Cell> row(fixed);
    row[0] = text_cell(run.name);
    for (std::size_t a = 0; a < plan.axes.size(); ++a) row[1 + a] = text_cell(plan.axes[a].shown[run.choice[a]]);
    const auto& o = outcomes[i];
    if (o.exit_status) row[1 + plan.axes.size()] = text_cell(std::to_string(*o.exit_status));
    if (with_render && o.render_status) row[2 + plan.axes.size()] = text_cell(std::to_string(*o.render_status));
    t.rows.push_back(std::move(row));
    const fs::path summary = out_dir / "runs" / run.name / "summary.csv";
    if (o.exit_status != 0 || !fs::exists(summary)) continue;
    try {
      const CsvSeries s = CsvSeries::load(summary);
      if (s.rows().empty()) continue;
      for (std::size_t j = 0; j < s.columns().size(); ++j) {
        const std::size_t col = t.column(s.columns()[j].name, s.columns()[j].description);
        t.rows.back().resize(t.columns.size());
        t.rows.back()[col] = number_cell(s.rows()[0][j]);
      }
    } catch (const std::exception&) {
      // An unreadable summary leaves its cells empty; the run's own files say more.
    }
  }
  // Last, so that the long text of a failure does not push the numbers out of sight.
  const std::size_t error = t.column("error", "a failed run or render: the last line of its log (logs/NAME.log)");
  t.columns[error].numeric = false;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    t.rows[i].resize(t.columns.size());
    t.rows[i][error] = text_cell(outcomes[i].error);
  }
  return t;
}

std::string to_csv(const Table& t, const SweepPlan& plan) {
  std::string out = fmt::format("# Orogen {} sweep results: one row per run of {} (base {})\n", OROGEN_VERSION,
                                plan.file.string(), plan.base.string());
  for (const auto& c : t.columns) out += fmt::format("# {}: {}\n", c.name, c.description);
  for (std::size_t j = 0; j < t.columns.size(); ++j) {
    if (j) out += ',';
    out += csv_field(t.columns[j].name);
  }
  out += '\n';
  for (const auto& r : t.rows) {
    for (std::size_t j = 0; j < r.size(); ++j) {
      if (j) out += ',';
      out += csv_field(r[j].exact);
    }
    out += '\n';
  }
  return out;
}

std::string to_markdown(const Table& t, const SweepPlan& plan, const std::vector<SweepOutcome>& outcomes) {
  std::size_t ok = 0, failed = 0;
  for (const auto& o : outcomes) {
    if (!o.exit_status) continue;
    ++(*o.exit_status == 0 ? ok : failed);
  }
  std::string out = "# Sweep results\n\n";
  out += fmt::format("Sweep file `{}`, base preset `{}`: {} run{}, {} finished, {} failed, {} not run (yet).\n\n",
                     plan.file.string(), plan.base.string(), plan.runs.size(), plan.runs.size() == 1 ? "" : "s", ok, failed,
                     plan.runs.size() - ok - failed);
  std::string header = "|", rule = "|";
  for (const auto& c : t.columns) {
    header += fmt::format(" {} |", md_field(c.name));
    rule += c.numeric ? "---:|" : "---|";
  }
  out += header + "\n" + rule + "\n";
  for (const auto& r : t.rows) {
    out += "|";
    for (const auto& cell : r) out += fmt::format(" {} |", md_field(cell.shown));
    out += "\n";
  }
  out += "\nNumbers are rounded to 4 significant digits here; `results.csv` has them exactly.\n\n";
  for (const auto& c : t.columns) out += fmt::format("- `{}`: {}\n", c.name, md_field(c.description));
  return out;
}

}  // namespace

void write_sweep_results(const fs::path& out_dir, const SweepPlan& plan, const std::vector<SweepOutcome>& outcomes,
                         bool with_render) {
  const Table t = build_table(out_dir, plan, outcomes, with_render);
  write_file_atomically(out_dir / "results.csv", to_csv(t, plan));
  write_file_atomically(out_dir / "results.md", to_markdown(t, plan, outcomes));
}

}  // namespace orogen
