// The registry of experiments: run.experiment names one. Each factory lives with its
// experiment (declared in its header); adding an experiment adds one row here.
#include <fmt/format.h>

#include <array>
#include <string_view>

#include "config/config.hpp"
#include "experiments/biaxial_experiment.hpp"
#include "experiments/experiment.hpp"
#include "experiments/packing_experiment.hpp"
#include "experiments/repose_experiment.hpp"
#include "experiments/scripted_experiment.hpp"
#include "experiments/singly_vergent_experiment.hpp"
#include "experiments/wedge_experiment.hpp"

namespace orogen {
namespace {

struct ExperimentEntry {
  std::string_view name;
  std::unique_ptr<Experiment> (*make)(const Config&);
};

constexpr std::array kExperiments{
    ExperimentEntry{"packing", make_packing_experiment},
    ExperimentEntry{"wedge", make_wedge_experiment},
    ExperimentEntry{"repose", make_repose_experiment},
    ExperimentEntry{"singly_vergent", make_singly_vergent_experiment},
    ExperimentEntry{"biaxial", make_biaxial_experiment},
    ExperimentEntry{"scripted", make_scripted_experiment},
};

}  // namespace

std::unique_ptr<Experiment> make_experiment(const Config& c) {
  const auto& name = c.get_string("run.experiment");
  std::string names;
  for (const auto& e : kExperiments) {
    if (e.name == name) return e.make(c);
    names += (names.empty() ? "" : ", ") + std::string(e.name);
  }
  throw config_error(c.source_of("run.experiment"), "run.experiment", name, "one of: " + names);
}

}  // namespace orogen
