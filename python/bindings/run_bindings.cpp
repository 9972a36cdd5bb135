// `orogen run` from Python: the CLI's own driver (run/runner.cpp), so the files, the bits,
// the checkpoints, --resume and the progress line are the CLI's. A Python callable may run
// between steps, every N steps; the engine steps at full speed (without the GIL) in between.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "run/runner.hpp"

namespace orogen::py {
namespace {

struct RunResult {
  int exit_code = 0;
  std::optional<pyb::error_already_set> error;  // what the hook raised (the run stopped there)
};

// Calls fn(world) with a handle valid during the call only; a kept handle must not outlive it.
template <class Fn>
auto call_with_world(Fn&& fn, World& w, const Experiment& e, const Config& c) {
  pyb::object handle = pyb::cast(WorldHandle{&w, &e, pyb::none(), &c});
  struct Clear {
    pyb::object& h;
    ~Clear() { h.cast<WorldHandle&>().world = nullptr; }
  } clear{handle};
  return fn(handle);
}

RunResult run(std::optional<std::filesystem::path> config, std::vector<std::string> overrides,
              std::filesystem::path out, int threads, bool resume, std::string from, pyb::object hook,
              std::uint64_t every, pyb::object setup, pyb::object surface_law) {
  RunOptions opt;
  if (!surface_law.is_none()) opt.surface_law = surface_script(surface_law.cast<pyb::function>());
  opt.config = std::move(config);
  opt.overrides = std::move(overrides);
  opt.out = std::move(out);
  opt.threads = threads;
  opt.resume = resume;
  opt.from = std::move(from);
  RunResult result;
  if (!hook.is_none()) {
    opt.between_every = every;
    opt.between_steps = [&hook, &result](World& w, const Experiment& e, const Config& c) {
      pyb::gil_scoped_acquire gil;
      try {
        return call_with_world([&hook](pyb::object h) { return bool(pyb::bool_(hook(h))); }, w, e, c);
      } catch (pyb::error_already_set& err) {
        result.error = std::move(err);  // stop with a checkpoint, re-raised in Python
        return true;
      }
    };
  }
  if (!setup.is_none()) {
    opt.before_first_output = [&setup, &result](World& w, const Experiment& e, const Config& c) {
      pyb::gil_scoped_acquire gil;
      try {
        call_with_world([&setup](pyb::object h) { setup(h); }, w, e, c);
      } catch (pyb::error_already_set& err) {
        const std::string what = err.what();
        result.error = std::move(err);  // re-raised in Python; the folder is released as after any failed set-up
        throw std::runtime_error("the setup function raised: " + what);
      }
    };
  }
  {
    pyb::gil_scoped_release free;
    result.exit_code = run_command(opt);
  }
  return result;
}

}  // namespace

void bind_run(pyb::module_& m) {
  m.attr("STOPPED_BY_HOOK") = kStoppedByHook;
  m.def(
      "run",
      [](std::optional<std::filesystem::path> config, std::vector<std::string> overrides, std::filesystem::path out,
         int threads, bool resume, std::string from, pyb::object hook, std::uint64_t every, pyb::object setup,
         pyb::object surface_law) {
        check_environment();
        RunResult r = run(std::move(config), std::move(overrides), std::move(out), threads, resume, std::move(from),
                          std::move(hook), every, std::move(setup), std::move(surface_law));
        if (r.error) throw std::move(*r.error);
        return r.exit_code;
      },
      pyb::arg("config"), pyb::arg("overrides"), pyb::arg("out"), pyb::arg("threads") = -1,
      pyb::arg("resume") = false, pyb::arg("from_") = "", pyb::arg("hook") = pyb::none(), pyb::arg("every") = 0,
      pyb::arg("setup") = pyb::none(), pyb::arg("surface_law") = pyb::none(),
      "runs as `orogen run` does; returns its exit code (0 done, 1 I/O, 2 bad input, 3 unstable, 4 stopped by "
      "the hook, 128+signal); setup(world) is called once before output 0 of a run that starts from its set-up; "
      "surface_law(h, dx, x_lo, dt) -> new heights at each surface update (docs/surface.md)");
}

}  // namespace orogen::py
