#pragma once
// Discs in structure-of-arrays form: the particles every force loop runs over.
// Array positions change when the arrays are re-ordered in space or compacted after a
// removal; `id` is the stable name of a disc for its whole life.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace orogen {

// How a disc moves. Dynamic discs follow forces; kinematic discs move with an imposed
// velocity (fixed discs are kinematic at rest) but still feel and exert contact forces.
enum class Motion : std::uint8_t { Dynamic = 0, Kinematic = 1 };

constexpr std::int32_t kNoCluster = -1;

struct Discs {
  // State.
  std::vector<double> x, y, vx, vy, theta, omega;
  // Geometry and inertia (a disc of radius r has mass pi r^2 and inertia m r^2 / 2).
  std::vector<double> radius, mass, inv_mass, inv_inertia;
  // Identity: stable disc id, stable cluster id (-1 for a free disc) and the index of the
  // cluster in Clusters (kNoCluster for a free disc; kept valid by the owner of both arrays).
  std::vector<std::int64_t> id, cluster_id;
  std::vector<std::int32_t> cluster;
  // Offset of the disc centre from its cluster's centre of mass, in the body frame.
  std::vector<double> body_dx, body_dy;
  std::vector<std::uint8_t> motion;
  // Initial position after settling and initial depth below the settled surface.
  std::vector<double> x0, y0, depth0;
  // Only in a world of named materials (contact/materials.hpp; empty otherwise, and then in
  // no checkpoint or snapshot): the index of the disc's material and the frictional slip it
  // has accumulated on its contacts, which weakens its friction.
  std::vector<std::uint8_t> material;
  std::vector<double> slip;
  bool has_materials = false;  // whether add() gives new discs a material (index 0) and slip

  std::size_t size() const { return x.size(); }
  // The arrays above that only a world of materials has.
  static bool optional_array(std::string_view name) { return name == "material" || name == "slip"; }
  // Gives every disc material 0 and no slip, and new discs the same (World::set_materials).
  void enable_materials();

  // Calls f(name, vector&) for every per-disc array, in a fixed order. Re-ordering,
  // compaction, checkpoints and snapshots all go through this one list.
  template <class F>
  void for_each_array(F&& f) {
    f("x", x); f("y", y); f("vx", vx); f("vy", vy); f("theta", theta); f("omega", omega);
    f("radius", radius); f("mass", mass); f("inv_mass", inv_mass); f("inv_inertia", inv_inertia);
    f("id", id); f("cluster_id", cluster_id); f("cluster", cluster);
    f("body_dx", body_dx); f("body_dy", body_dy); f("motion", motion);
    f("x0", x0); f("y0", y0); f("depth0", depth0);
    f("material", material); f("slip", slip);
  }  // The same list for reading (a const world's arrays).
  template <class F>
  void for_each_array(F&& f) const {
    const_cast<std::remove_const_t<std::remove_pointer_t<decltype(this)>>&>(*this).for_each_array(
        [&](auto name, auto& v) { f(name, std::as_const(v)); });
  }


  // Appends a free, dynamic disc at rest and returns its index.
  std::size_t add(std::int64_t disc_id, double px, double py, double r);

  // Re-orders every array so that new index k holds old index order[k].
  void permute(std::span<const std::uint32_t> order);

  // Keeps only the discs whose keep flag is set, preserving their order.
  void compact(std::span<const std::uint8_t> keep);

  bool is_dynamic(std::size_t i) const { return motion[i] == static_cast<std::uint8_t>(Motion::Dynamic); }
};

}  // namespace orogen
