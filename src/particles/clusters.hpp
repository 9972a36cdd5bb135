#pragma once
// Rigid clusters: bodies made of several discs held together permanently (the stiff-bond
// limit of the thesis's 3-disc clusters). A body carries the pose and momentum; its discs
// follow the body's pose, and their contact forces are summed onto the body every step.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "particles/discs.hpp"

namespace orogen {

constexpr int kMaxClusterSize = 3;

struct Clusters {
  std::vector<double> x, y, theta, vx, vy, omega;  // centre of mass pose and velocity
  // cos and sin of the pose's rotation, advanced with theta by a small rotation each step (no
  // trigonometry in the time step); they place the member discs, theta is what is reported.
  std::vector<double> rot_c, rot_s;
  std::vector<double> fx, fy, torque;
  std::vector<double> mass, inv_mass, inv_inertia;
  std::vector<std::int64_t> id;
  std::vector<std::uint8_t> motion;
  // Disc indices of the members (-1 past the end); kept valid when discs are re-ordered.
  std::vector<std::array<std::int32_t, kMaxClusterSize>> members;

  std::size_t size() const { return x.size(); }

  template <class F>
  void for_each_array(F&& f) {
    f("x", x); f("y", y); f("theta", theta); f("vx", vx); f("vy", vy); f("omega", omega);
    f("rot_c", rot_c); f("rot_s", rot_s);
    f("fx", fx); f("fy", fy); f("torque", torque);
    f("mass", mass); f("inv_mass", inv_mass); f("inv_inertia", inv_inertia);
    f("id", id); f("motion", motion); f("members", members);
  }  // The same list for reading (a const world's arrays).
  template <class F>
  void for_each_array(F&& f) const {
    const_cast<std::remove_const_t<std::remove_pointer_t<decltype(this)>>&>(*this).for_each_array(
        [&](auto name, auto& v) { f(name, std::as_const(v)); });
  }


  void compact(std::span<const std::uint8_t> keep);
};

// Joins the given discs (already placed in the world) into one rigid body: computes the
// centre of mass, the parallel-axis moment of inertia and each disc's body-frame offset.
// Returns the new cluster's index.
std::size_t make_cluster(Clusters& clusters, Discs& discs, std::span<const std::size_t> disc_indices,
                         std::int64_t cluster_id);

// Re-orders the bodies in the order of their first disc in the disc arrays, so that after a
// spatial sort of the discs the per-step body loops walk the discs almost in memory order
// (and threads split the bodies where they split the discs). Discs::cluster must still hold
// the bodies' current indices; call relink_clusters after.
void order_clusters_by_discs(Clusters& clusters, const Discs& discs);

// Rebuilds Clusters::members and Discs::cluster after discs were re-ordered or compacted.
void relink_clusters(Clusters& clusters, Discs& discs);

// Places member discs at the pose of their bodies and gives them the body's rigid velocity.
// With reference positions (by disc index), returns the largest distance of a member disc
// from its reference (0 without).
double update_cluster_discs(const Clusters& clusters, Discs& discs, const double* x_ref = nullptr,
                            const double* y_ref = nullptr);

// The same for bodies [first, last) on the calling thread alone; returns the largest *squared*
// distance (0 without references).
double place_cluster_discs(const Clusters& clusters, Discs& discs, std::ptrdiff_t first, std::ptrdiff_t last,
                           const double* x_ref, const double* y_ref);

}  // namespace orogen
