#include "world/stage_hooks.hpp"

#include <algorithm>

#include "world/world.hpp"

namespace orogen {

void StageHooks::add(Stage stage, std::string name, Hook hook) {
  remove(name);
  lists_[index(stage)].push_back({std::move(name), std::move(hook), nullptr});
}

void StageHooks::remove(std::string_view name) {
  for (auto& list : lists_) std::erase_if(list, [&](const Named& h) { return h.name == name; });
}

std::vector<std::string> StageHooks::names(Stage stage) const {
  std::vector<std::string> out;
  for (const auto& h : lists_[index(stage)]) out.push_back(h.name);
  return out;
}

void StageHooks::run(Stage stage, World& world) const {
  for (const auto& h : lists_[index(stage)]) h.hook(world);
}

void StageHooks::add_pin(std::string name, Pin pin) {
  auto shared = std::make_shared<const Pin>(std::move(pin));
  add(Stage::AfterForces, std::move(name), [shared](World& world) { run_pin(*shared, world); });
  lists_[index(Stage::AfterForces)].back().pin = std::move(shared);
}

std::vector<const StageHooks::Pin*> StageHooks::pins() const {
  std::vector<const Pin*> out;
  for (const auto& h : lists_[index(Stage::AfterForces)])
    if (h.pin) out.push_back(h.pin.get());
  return out;
}

bool StageHooks::has_pins() const {
  const auto& list = lists_[index(Stage::AfterForces)];
  return std::any_of(list.begin(), list.end(), [](const Named& h) { return h.pin != nullptr; });
}

bool StageHooks::only_pins(Stage stage) const {
  return std::all_of(lists_[index(stage)].begin(), lists_[index(stage)].end(), [](const Named& h) { return h.pin != nullptr; });
}

void StageHooks::run_pin(const Pin& pin, World& world) {
  pin.prepare(world);
  world.edit_motion([&](MotionEdit& e) {
    for (const std::size_t wall : pin.walls())
      world.for_each_touching(wall, [&](std::size_t i) {
        pin.record(world, i);
        e.body_of(i, Motion::Kinematic);
      });
  });
}

}  // namespace orogen
