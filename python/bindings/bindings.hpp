#pragma once
// The pieces of the `_orogen` extension module (python/orogen imports it), one file each:
// configuration, the world handle, the in-memory simulation, the run driver.
#include <pybind11/pybind11.h>

#include <memory>

#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "world/world.hpp"

namespace orogen::py {

namespace pyb = pybind11;

// A world seen from Python: the world and the experiment that drives it. A Simulation owns
// both (`owner` keeps it alive while the handle or a numpy view lives); a hook's handle is
// valid during the call only and is cleared after it, so a stale use raises instead of crashing.
struct WorldHandle {
  World* world = nullptr;
  const Experiment* experiment = nullptr;
  pyb::object owner;
  const Config* config = nullptr;  // the run's resolved configuration (world.config, world.h0)

  World& get() const;
};

// The command line's check of the environment variables that steer the engine (OMP_*,
// OROGEN_MIN_PARALLEL_ITEMS), raised as ConfigError before a run or a simulation starts.
void check_environment();

// A user's surface law (docs/surface.md) as the engine calls it: law(h, dx, x_lo, dt) returns
// the new heights, called with the GIL held; a wrong length is a ValueError.
SurfaceScript surface_script(pyb::function law);

void bind_config(pyb::module_& m);
void bind_world(pyb::module_& m);
void bind_simulation(pyb::module_& m);
void bind_run(pyb::module_& m);

}  // namespace orogen::py
