// The World's methods that change it and keep what depends on the change consistent, and its
// read access to the wall contacts (world.hpp, second part).
#include <fmt/format.h>

#include "world/world.hpp"

namespace orogen {

void World::set_contact_law(const ContactLaw& l) {
  law_ = l;
  invalidate_neighbors();
}

void World::set_walls(std::vector<Wall> w) {
  walls_ = std::move(w);
  invalidate_neighbors();
}

std::size_t World::wall_index(std::string_view name) const {
  std::string there;
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    if (walls_[k].name == name) return k;
    if (!there.empty()) there += ", ";
    there += walls_[k].name;
  }
  throw std::invalid_argument(
      fmt::format("no wall named '{}' in this world (walls: {})", name, there.empty() ? "none" : there));
}

void World::set_wall_velocity(std::string_view name, double vx, double vy) {
  Wall& w = walls_[wall_index(name)];
  w.vx = vx;
  w.vy = vy;
}

void World::set_wall_friction(std::string_view name, WallFriction friction, double mu) {
  Wall& w = walls_[wall_index(name)];
  w.friction = friction;
  w.mu = mu;
}

void World::set_wall_weakening(std::string_view name, const BaseWeakening& weakening) {
  set_weakening(walls_[wall_index(name)], weakening);
}

void World::set_wall_ends(std::string_view name, double ax, double ay, double bx, double by) {
  set_wall_ends(wall_index(name), ax, ay, bx, by);
}

void World::set_wall_ends(std::size_t index, double ax, double ay, double bx, double by) {
  Wall& w = walls_.at(index);
  w.ax = ax; w.ay = ay; w.bx = bx; w.by = by;
}

void World::enable_wall(std::string_view name, bool enabled) {
  Wall& w = walls_[wall_index(name)];
  if (w.enabled == enabled) return;
  w.enabled = enabled;
  invalidate_neighbors();
}

}  // namespace orogen
