#pragma once
// Changes of motion flags (dynamic, or kinematic at a given velocity), batched:
// World::edit_motion hands one to the caller and, if anything changed, then places the member
// discs on their bodies and marks the neighbour list for a rebuild (the wall contacts list
// dynamic discs only) where a body turned dynamic or kinematic, so that no caller has to
// remember either.
#include <cstddef>

#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

class MotionEdit {
 public:
  MotionEdit(Discs& discs, Clusters& clusters) : d_(discs), c_(clusters) {}

  // Free disc i: dynamic, or kinematic moving at (vx, vy) without spin. Returns whether its
  // motion (or, kinematic, its velocity) changed. A member disc is refused (std::logic_error):
  // its cluster moves it.
  bool disc(std::size_t i, Motion m, double vx = 0, double vy = 0);
  // Cluster k and its member discs, likewise.
  bool cluster(std::size_t k, Motion m, double vx = 0, double vy = 0);
  // Disc i if it is free, else its whole cluster.
  bool body_of(std::size_t i, Motion m, double vx = 0, double vy = 0);
  // Whether body_of(i, m, vx, vy) would change nothing (it reads, never edits).
  static bool body_has(const Discs& discs, const Clusters& clusters, std::size_t i, Motion m, double vx = 0,
                       double vy = 0);

  // Whether anything changed; whether a body turned dynamic or kinematic (not only a
  // kinematic velocity), which changes the wall contacts' list.
  bool changed() const { return changed_; }
  bool motion_changed() const { return motion_changed_; }

 private:
  Discs& d_;
  Clusters& c_;
  bool changed_ = false;
  bool motion_changed_ = false;
};

}  // namespace orogen
