#include "world/motion_edit.hpp"

#include <stdexcept>
#include <string>

namespace orogen {
namespace {

constexpr auto kKinematic = static_cast<std::uint8_t>(Motion::Kinematic);

// Whether a body with this motion and velocity must change to (m, vx, vy); a dynamic body's
// velocity is its own.
bool differs(std::uint8_t motion, double vx, double vy, Motion m, double new_vx, double new_vy) {
  if (motion != static_cast<std::uint8_t>(m)) return true;
  return m == Motion::Kinematic && (vx != new_vx || vy != new_vy);
}

}  // namespace

bool MotionEdit::disc(std::size_t i, Motion m, double vx, double vy) {
  if (d_.cluster[i] >= 0)
    throw std::logic_error("MotionEdit::disc: disc " + std::to_string(d_.id[i]) + " belongs to a cluster");
  if (!differs(d_.motion[i], d_.vx[i], d_.vy[i], m, vx, vy)) return false;
  motion_changed_ |= d_.motion[i] != static_cast<std::uint8_t>(m);
  d_.motion[i] = static_cast<std::uint8_t>(m);
  if (d_.motion[i] == kKinematic) { d_.vx[i] = vx; d_.vy[i] = vy; d_.omega[i] = 0; }
  changed_ = true;
  return true;
}

bool MotionEdit::cluster(std::size_t k, Motion m, double vx, double vy) {
  if (!differs(c_.motion[k], c_.vx[k], c_.vy[k], m, vx, vy)) return false;
  motion_changed_ |= c_.motion[k] != static_cast<std::uint8_t>(m);
  c_.motion[k] = static_cast<std::uint8_t>(m);
  if (c_.motion[k] == kKinematic) { c_.vx[k] = vx; c_.vy[k] = vy; c_.omega[k] = 0; }
  for (auto i : c_.members[k])
    if (i >= 0) d_.motion[static_cast<std::size_t>(i)] = c_.motion[k];
  changed_ = true;
  return true;
}

bool MotionEdit::body_has(const Discs& d, const Clusters& c, std::size_t i, Motion m, double vx, double vy) {
  const auto k = d.cluster[i];
  if (k < 0) return !differs(d.motion[i], d.vx[i], d.vy[i], m, vx, vy);
  const auto b = static_cast<std::size_t>(k);
  return !differs(c.motion[b], c.vx[b], c.vy[b], m, vx, vy);
}

bool MotionEdit::body_of(std::size_t i, Motion m, double vx, double vy) {
  const auto k = d_.cluster[i];
  return k >= 0 ? cluster(static_cast<std::size_t>(k), m, vx, vy) : disc(i, m, vx, vy);
}

}  // namespace orogen
