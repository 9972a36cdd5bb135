#include "run/run.hpp"

#include <fmt/format.h>

#include <cstdlib>

#include "io/vtp_writer.hpp"
#include "run/kept_files.hpp"
#include "run/bond_break_log.hpp"
#include "run/removal_log.hpp"
#include "world/world_archive.hpp"

namespace fs = std::filesystem;

namespace orogen {

SnapshotMetadata Run::metadata() const {
  SnapshotMetadata m;
  m.strings["experiment"] = config_.get_string("run.experiment");
  m.strings["orogen_version"] = OROGEN_VERSION;
  m.numbers["h0"] = exp_->h0();
  m.numbers["dt"] = world_.dt();
  m.numbers["x_split"] = exp_->x_split();
  m.strings["run_identity"] = identity_;
  m.strings[kConfigAttr] = config_.to_toml();
  if (!branch_from_.empty()) m.strings["branch_from"] = branch_from_;
  if (!world_.materials().empty()) {  // the names of the `material` dataset's indices, one per line
    std::string names;
    for (const auto& material : world_.materials().list) names += material.name + "\n";
    m.strings["materials_names"] = names;
  }
  return m;
}

std::vector<CsvSeries::Column> Run::csv_columns() const {
  std::vector<CsvSeries::Column> cols;
  for (const auto& c : exp_->columns()) cols.push_back({c.name, c.description});
  return cols;
}

std::vector<std::string> Run::preamble() const {
  return {fmt::format("Orogen {} series, experiment '{}': one row per output step", OROGEN_VERSION,
                      config_.get_string("run.experiment")),
          "lengths in units of the largest disc diameter d, time in sqrt(d/g); each column's unit in [] after its "
          "description",
          fmt::format("h0 = {} d (the layer thickness; the unit of a wedge's lengths)", exp_->h0())};
}

void Run::output() {
  world_.make_whole();  // over ranks: every copy holds the state of one process
  if (writes_files()) write_output_files();
  state_.output_times.push_back(world_.time());
  ++state_.outputs;
  last_output_step_ = world_.step();
  if (!branch_start_) exp_->after_output(world_);  // a branch's state has seen its output already
  branch_start_ = false;
  if (!writes_files()) return;
  if (write_vtp_) write_pvd_file();
  for (const auto& observer : observers_) observer(state_.outputs, false);
  // Test hook (--abort-after-outputs): die like a kill, with no cleanup.
  if (state_.outputs == abort_after_outputs_) std::_Exit(137);
}

void Run::write_output_files() {
  SnapshotFrame frame;
  frame.step = static_cast<std::int64_t>(world_.step());
  frame.time = world_.time();
  frame.discs = &world_.discs();
  for (auto& [name, value] : exp_->scalars(world_)) frame.attrs[name] = value;
  frame.fields = exp_->fields(world_);
  // A branch's output 0 repeats the source's output fields (their units and descriptions are the experiment's).
  for (auto& field : frame.fields)
    if (auto it = branch_fields_.find(field.name); it != branch_fields_.end()) field.values = it->second;
  branch_fields_.clear();
  for (const auto& w : world_.walls())
    if (w.enabled) frame.walls.push_back({w.ax, w.ay, w.bx, w.by});
  frame.groups = contact_output_groups(world_, contact_output_);
  snapshots_->append(frame);
  state_.vtp_digests.push_back(write_vtp_ ? write_vtp(dir_ / vtp_file_name(state_.outputs), frame) : 0);
  series_->add_row(exp_->measure(world_));
  write_event_logs();
}

// summary.csv: the series format with a single row, one column per result.
void Run::write_summary() {
  if (!writes_files()) return;
  const auto values = exp_->summary(world_);
  if (values.empty()) return;
  std::vector<CsvSeries::Column> cols;
  std::vector<double> row;
  for (const auto& v : values) {
    cols.push_back({v.name, v.description});
    row.push_back(v.value);
  }
  CsvSeries summary(dir_ / "summary.csv", std::move(cols),
                    {fmt::format("Orogen {} summary, experiment '{}': the results of the finished run", OROGEN_VERSION,
                                 config_.get_string("run.experiment"))});
  summary.add_row(std::move(row));
}

void Run::write_pvd_file() {
  std::vector<std::pair<double, std::string>> entries;
  for (std::int64_t k = 0; k < state_.outputs; ++k) entries.emplace_back(state_.output_times[k], vtp_file_name(k));
  write_pvd(dir_ / "run.pvd", entries);
}

void Run::write_event_logs() {
  write_removal_log(dir_ / "removals.csv", world_.removals(), world_.step());
  if (world_.materials().any_bonds())
    write_bond_break_log(dir_ / "bond_breaks.csv", world_.bonds().breaks, world_.bonds().size(), world_.step());
}

void Run::checkpoint() {
  world_.make_whole();
  if (!writes_files()) return;
  // The logs first: a kill between the two leaves rows after the old checkpoint, which a resume
  // accepts; the other order would leave a checkpoint whose removals the file lacks. An output
  // of this step has written them already.
  if (world_.step() != last_output_step_) write_event_logs();
  ArchiveWriter out;
  save_world(out, world_);
  exp_->save(out);
  out.put_scalar("run.outputs", state_.outputs);
  out.put("run.output_times", state_.output_times);
  out.put("run.vtp_digests", state_.vtp_digests);
  out.put_scalar("run.series_digest", series_->digest(static_cast<std::size_t>(state_.outputs)));
  out.put_scalar<std::uint8_t>("run.finished", state_.finished ? 1 : 0);
  out.put_scalar("run.last_output_step", last_output_step_);
  out.put_scalar("run.output_base", output_base_);
  out.put_string("run.branch_from", branch_from_);
  out.put_string("run.identity", identity_);
  out.put_string("run.config", config_.to_toml());
  out.finish(dir_ / "checkpoint.bin");
}

}  // namespace orogen
