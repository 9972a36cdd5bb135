// The `_orogen` extension module: the engine's exceptions as named Python ones, then each part.
#include "bindings.hpp"

#include "config/config.hpp"
#include "config/schema.hpp"
#include "util/omp_environment.hpp"
#include "util/parallel.hpp"

namespace orogen::py {

void check_environment() {
  for (const std::string& error : {parallel_environment_error(), omp_environment_error(kMaxThreads)})
    if (!error.empty()) throw ConfigError(error);
}

PYBIND11_MODULE(_orogen, m) {
  m.doc() = "Orogen's engine (C++); use it through the `orogen` package";
  m.attr("version") = OROGEN_VERSION;
  // A bad key, type or value: the CLI's exit code 2, here a named exception with the CLI's message.
  pyb::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);
  // The simulation blew up (the CLI's exit code 3).
  pyb::register_exception<InstabilityError>(m, "InstabilityError", PyExc_RuntimeError);
  bind_config(m);
  bind_world(m);
  bind_simulation(m);
  bind_run(m);
}

}  // namespace orogen::py
