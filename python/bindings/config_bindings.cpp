// Configuration: the CLI's Config::load (a TOML file plus "section.key=value" overrides, the
// same strict checks), so Python and `orogen run` accept and refuse the same configurations.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "config/config.hpp"
#include "experiments/experiment.hpp"

namespace orogen::py {

void bind_config(pyb::module_& m) {
  pyb::class_<Config>(m, "Config")
      .def_static("load", &Config::load, pyb::arg("file"), pyb::arg("overrides"),
                  "A TOML file (or None) and section.key=value overrides, checked as `orogen run` checks them")
      .def("to_toml", &Config::to_toml, "the resolved configuration, every key, as config.toml holds it")
      .def("check_experiment", [](const Config& c) { (void)make_experiment(c); },
           "the experiment's cross-key checks (ConfigError), as `orogen run` makes them before writing anything")
      .def("source_of", &Config::source_of, pyb::arg("key"));
}

}  // namespace orogen::py
