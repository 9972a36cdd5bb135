#include "commands/export_command.hpp"

#include <fmt/format.h>

#include <iostream>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot_export.hpp"
#include "io/snapshot_reader.hpp"
#include "run/run_folder.hpp"
#include "util/command_error.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// Bad input to export: exit 2, "error: export: ..." (report_error).
struct ExportInputError : BadInput {
  explicit ExportInputError(const std::string& message) : BadInput("export: " + message) {}
};

Snapshot read_output(const ExportCommandOptions& o, std::int64_t& k) {
  const fs::path h5 = o.dir / "snapshots.h5";
  if (!fs::is_regular_file(h5))
    throw ExportInputError(fmt::format("{} not found: {} holds no run; export takes the folder of a run", h5.string(),
                               o.dir.string()));
  std::optional<SnapshotReader> reader;
  try {
    reader.emplace(h5);
  } catch (const SnapshotFormatError& e) {
    throw ExportInputError(fmt::format("{} is not a snapshot file this orogen reads: {}", h5.string(), e.what()));
  } catch (const std::exception& e) {  // a damaged file: exit 1, as any file that cannot be read
    throw std::runtime_error(fmt::format("{} is not a readable orogen snapshot file: {}", h5.string(), e.what()));
  }
  const std::int64_t count = reader->count();
  if (count <= 0) throw ExportInputError(fmt::format("{} holds no outputs yet", h5.string()));
  k = o.output < 0 ? count - 1 : o.output;
  if (k >= count)
    throw ExportInputError(fmt::format("--output {}: out of range; {} has outputs 0 to {}", o.output, o.dir.string(), count - 1));
  return reader->read(k);
}

// The run's contact law and time step as LAMMPS's gran/hooke/history takes them: its dashpots
// per unit effective mass, that of two discs of diameter 1 (mass pi/4 each, density 1).
LammpsLaw lammps_law(const fs::path& run) {
  Config config = Config::load(run / "config.toml", {});
  World world;
  apply_engine_config(config, world);
  const ContactLaw& law = world.law();
  const double m_eff = std::numbers::pi / 8;
  const double gamma_n = law.gamma_n(m_eff, world.dt()) / m_eff;
  return {law.kn, law.ks, gamma_n, law.tangential_damping_ratio * gamma_n, law.mu, world.dt()};
}

}  // namespace

int export_command(const ExportCommandOptions& o) {
  try {
    if (o.output < -1) throw ExportInputError(fmt::format("--output {}: must be 0 or more (an output index)", o.output));
    if (o.to.empty()) throw ExportInputError("--to needs a file name");
    if (const std::string refusal = run_file_refusal("--to " + o.to.string(), o.to); !refusal.empty())
      throw ExportInputError(refusal);
    ExportFormat format;
    try {
      format = parse_export_format(o.format);
    } catch (const std::invalid_argument& e) {
      throw ExportInputError(e.what());
    }
    const fs::path input = fs::path(o.to.string() + ".in");  // a LAMMPS data file's ready input
    if (format == ExportFormat::LammpsData)
      if (const std::string refusal = run_file_refusal("--to " + o.to.string() + " (its input " + input.string() + ")",
                                                       input);
          !refusal.empty())
        throw ExportInputError(refusal);
    std::int64_t k = 0;
    const Snapshot s = read_output(o, k);
    write_file_atomically(o.to, export_snapshot(s, format, {o.dir.string(), k}));
    if (format == ExportFormat::LammpsData)
      write_file_atomically(input, lammps_input(s, lammps_law(o.dir), o.to.filename().string()));
    return 0;
  } catch (const std::exception& e) {
    return report_error(e, "export " + o.dir.string() + " to " + o.to.string());
  }
}

}  // namespace orogen
