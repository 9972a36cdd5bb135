#pragma once
// Named hooks an experiment runs inside a time step (World::advance), at fixed stages:
//   AfterForces       every pair and wall force of the step is summed (the wall contacts'
//                     touching flags are this step's), before any disc moves
//   AfterIntegration  the discs have moved, before the walls move and the clock advances
// Hooks run in the order they were added, on one thread, once per step; world.step and
// world.time are still those of the step's start. A hook is not state: an experiment adds its
// hooks again after a checkpoint is loaded (Experiment::attach), and whatever a hook depends
// on must be in the world or the experiment's checkpoint.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace orogen {

struct World;

enum class Stage : std::uint8_t { AfterForces = 0, AfterIntegration = 1 };
inline constexpr std::size_t kStageCount = 2;

class StageHooks {
 public:
  using Hook = std::function<void(World&)>;

  // A copy of a world starts with no hooks. Hooks belong to the experiment attached to the
  // original and act on its state (the wedge's hook records the ids it pins in the
  // experiment): a copy stepped with them would change the original's experiment. To step a
  // copy with hooks, attach an experiment to it (Experiment::attach). Moves keep the hooks.
  StageHooks() = default;
  StageHooks(const StageHooks&) {}
  StageHooks& operator=(const StageHooks&) {
    lists_ = {};
    return *this;
  }
  StageHooks(StageHooks&&) = default;
  StageHooks& operator=(StageHooks&&) = default;
  ~StageHooks() = default;

  // Adds `hook` at the end of `stage`'s list; a hook of the same name (at any stage) is
  // replaced, so that attaching an experiment twice runs its hooks once.
  void add(Stage stage, std::string name, Hook hook);
  void remove(std::string_view name);
  bool empty(Stage stage) const { return lists_[index(stage)].empty(); }
  std::vector<std::string> names(Stage stage) const;
  void run(Stage stage, World& world) const;

  // A hook of one kind, which a step over ranks can run where the discs are (parallel/rank_step):
  // after the forces, `prepare(world)` is called, then every body with a disc touching one of
  // `walls()` is held at rest (kinematic, zero velocity) and `record(world, disc)` is called for
  // each such disc. `recorded(world, disc)` says whether it was (a rank then skips a disc that is
  // recorded and at rest already).
  struct Pin {
    std::function<const std::vector<std::size_t>&()> walls;
    std::function<void(const World&)> prepare;
    std::function<void(const World&, std::size_t disc)> record;
    std::function<bool(const World&, std::size_t disc)> recorded;
  };
  void add_pin(std::string name, Pin pin);  // at Stage::AfterForces, as add()
  std::vector<const Pin*> pins() const;     // in the order they run
  bool has_pins() const;
  bool only_pins(Stage stage) const;        // every hook of `stage` is a pin (or there is none)
  // What the pin hook does in one process: records and holds every body touching its walls.
  static void run_pin(const Pin& pin, World& world);

 private:
  struct Named {
    std::string name;
    Hook hook;
    std::shared_ptr<const Pin> pin;  // set for a pin
  };
  static std::size_t index(Stage s) { return static_cast<std::size_t>(s); }
  std::array<std::vector<Named>, kStageCount> lists_;
};

}  // namespace orogen
