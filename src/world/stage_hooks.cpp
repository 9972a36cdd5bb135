#include "world/stage_hooks.hpp"

#include <algorithm>

namespace orogen {

void StageHooks::add(Stage stage, std::string name, Hook hook) {
  remove(name);
  lists_[index(stage)].push_back({std::move(name), std::move(hook)});
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

}  // namespace orogen
