// An experiment stepped from Python, in memory: the set-up of `orogen run` (engine keys, then
// the experiment's setup), then Experiment::advance step by step, so the world after n steps is
// the CLI run's world after n steps, bit for bit. Files are the run driver's job (run_bindings).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <omp.h>

#include <chrono>
#include <memory>
#include <filesystem>

#include "bindings.hpp"
#include "config/config.hpp"
#include "experiments/time_step_config.hpp"
#include "io/binary_archive.hpp"
#include "util/thread_tuner.hpp"
#include "world/world_archive.hpp"

namespace orogen::py {
namespace {

// The team a run of this configuration steps with, as `orogen run` sets it: run.threads, or
// every core for 0.
int team_size(const Config& c) {
  if (const int threads = c.get_int32("run.threads"); threads > 0) omp_set_num_threads(threads);
  return omp_get_max_threads();
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

class Simulation {
 public:
  explicit Simulation(Config config)
      : config_((check_environment(), std::move(config))), exp_(make_experiment(config_)),
        tuner_(config_.get_bool("run.adapt_threads") ? team_size(config_) : 1, config_.get_float("run.adapt_slice")) {
    apply_engine_config(config_, world_);
    exp_->setup(world_);
    start_ = left_ = std::chrono::steady_clock::now();  // the set-up is not timed
  }

  // Up to n steps; fewer once the experiment is done. The GIL is released while stepping. The
  // thread count is tuned as the CLI's run loop tunes it (util/thread_tuner.hpp): on a busy
  // machine one thread can be many times faster than a spinning team; results do not depend on it.
  std::uint64_t step(std::uint64_t n) {
    pyb::gil_scoped_release free;
    tuner_.exclude(seconds_since(left_));  // Python's time between calls is not stepping
    std::uint64_t k = 0;
    while (k < n && !done_) {
      if (exp_->advance(world_)) ++k;
      else done_ = true;
      const int threads = tuner_.threads();
      if (tuner_.after_step(static_cast<double>(world_.discs().size()), seconds_since(start_)) != threads)
        omp_set_num_threads(tuner_.threads());
    }
    left_ = std::chrono::steady_clock::now();
    return k;
  }

  // Steps until the experiment's scalar `key` (or "time") reaches `value`; false if it ended first.
  bool advance_to(const std::string& key, double value) {
    auto current = [&] {
      if (key == "time") return world_.time();
      for (const auto& [k, v] : exp_->scalars(world_))
        if (k == key) return v;
      throw pyb::key_error("advance_to: the experiment has no scalar '" + key + "' (it has time and its output scalars)");
    };
    while (current() < value) {
      if (step(1) == 0) return false;
      if (PyErr_CheckSignals() != 0) throw pyb::error_already_set();  // Ctrl-C between steps
    }
    return true;
  }

  // The world and the experiment's state, as a checkpoint holds them (world_archive.hpp).
  void save(const std::filesystem::path& file) {
    ArchiveWriter out;
    save_world(out, world_);
    exp_->save(out);
    out.put_string("python.config", config_.to_toml());
    out.finish(file);
  }
  void load(const std::filesystem::path& file) {
    const ArchiveReader in(file);
    if (in.has("python.config") && in.get_string("python.config") != config_.to_toml())
      throw pyb::value_error(file.string() + " was saved by a simulation of another configuration");
    World fresh;
    apply_engine_config(config_, fresh);
    load_world(in, fresh);
    world_ = std::move(fresh);
    exp_->load(in);
    exp_->attach(world_);  // hooks are not state
    done_ = false;
  }

  // A user's surface law (docs/surface.md): law(h, dx, x_lo, dt) returns the new heights of
  // the columns; called at each surface update with the GIL held, after the [surface] keys' laws.
  void set_surface_law(pyb::function law) {
    SurfaceScript script = surface_script(std::move(law));
    if (!exp_->set_surface_script(std::move(script)))
      throw pyb::value_error("this experiment has no surface processes (a wedge has; docs/surface.md)");
  }

  World& world() { return world_; }
  const Experiment& experiment() const { return *exp_; }
  const Config& config() const { return config_; }
  bool done() const { return done_; }

 private:
  Config config_;  // first: the experiment may keep references into it
  std::unique_ptr<Experiment> exp_;
  World world_;
  bool done_ = false;
  ThreadTuner tuner_;
  std::chrono::steady_clock::time_point start_, left_;  // the tuner's clock; when step() last returned
};

}  // namespace

SurfaceScript surface_script(pyb::function law) {
  // The engine copies its spec (and this function) without the GIL: the Python object is held
  // once, by a pointer whose last owner lets go of it under the GIL.
  const std::shared_ptr<pyb::function> held(new pyb::function(std::move(law)), [](pyb::function* f) {
    pyb::gil_scoped_acquire gil;
    delete f;
  });
  return [held](std::vector<double>& h, double dx, double x_lo, double dt) {
    pyb::gil_scoped_acquire gil;
    const pyb::array_t<double> heights(static_cast<pyb::ssize_t>(h.size()), h.data());
    const auto out =
        pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>::ensure((*held)(heights, dx, x_lo, dt));
    if (!out || out.ndim() != 1 || static_cast<std::size_t>(out.size()) != h.size())
      throw pyb::value_error("the surface law must return one height per column (" + std::to_string(h.size()) +
                             " numbers)");
    std::copy(out.data(), out.data() + h.size(), h.begin());
  };
}

void bind_simulation(pyb::module_& m) {
  pyb::class_<Simulation>(m, "Simulation")
      .def(pyb::init<Config>(), pyb::arg("config"))
      .def("check_setup", [](Simulation& s) { check_world_time_step(s.config(), s.world()); },
           "after a setup function: ConfigError if its discs make the time step unstable")
      .def("step", &Simulation::step, pyb::arg("n") = 1, "up to n steps; returns how many were taken")
      .def("advance_to", &Simulation::advance_to, pyb::arg("key"), pyb::arg("value"))
      .def("set_surface_law", &Simulation::set_surface_law, pyb::arg("law"),
           "law(h, dx, x_lo, dt) -> new heights, run at each surface update (docs/surface.md)")
      .def("save", &Simulation::save, pyb::arg("file"))
      .def("load", &Simulation::load, pyb::arg("file"))
      .def_property_readonly("done", &Simulation::done)
      .def_property_readonly("config_toml", [](const Simulation& s) { return s.config().to_toml(); })
      .def_property_readonly("world", [](pyb::object self) {
        auto& s = self.cast<Simulation&>();
        return WorldHandle{&s.world(), &s.experiment(), self, &s.config()};
      });
}

}  // namespace orogen::py
