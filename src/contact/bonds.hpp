#pragma once
// Cohesive bonds between discs (docs/materials.md): a 2-D parallel bond (Potyondy and Cundall
// 2004) of width 2 R and unit depth, acting beside the pair's ordinary frictional contact, which
// it leaves alone. It carries a normal force, a shear force and a moment, each grown from zero
// at its creation by the relative motion of the two discs (the incremental form); it breaks,
// for good, when the largest tensile stress of the beam reaches its tensile strength (mode
// tension) or the mean shear stress its shear strength (mode shear). A broken bond is logged
// and gone; the contact goes on as any other.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "particles/disc_force.hpp"
#include "particles/discs.hpp"

namespace orogen {

enum class BondBreakMode : std::uint8_t { Tension = 0, Shear = 1 };

// One breakage, for the log (bond_breaks.csv) and the checkpoint.
struct BondBreak {
  std::uint64_t step = 0;
  double time = 0;
  std::int64_t id_a = 0, id_b = 0;  // stable ids of the two discs, id_a < id_b
  double x = 0, y = 0;              // midpoint between the two centres
  BondBreakMode mode = BondBreakMode::Tension;
};

// The bonds, acting ones first, each part in the order of their discs' indices after each list
// build (prepare_bond_scratch; the order their forces are added: part of the bitwise result).
struct Bonds {
  std::vector<std::int64_t> id_a, id_b;         // stable ids (the key; id_a < id_b)
  std::vector<std::uint32_t> a, b;              // disc indices, remapped after each list build
  std::vector<double> kn, ks;                   // stiffness per unit area (normal, shear) [m g / d^3]
  std::vector<double> radius;                   // half width R [d]
  std::vector<double> tensile, shear;           // strengths [rho g d]
  std::vector<double> fn, fs, moment;           // normal force (tension > 0), shear force, moment on b
  std::vector<BondBreak> breaks;                // every breakage so far

  std::size_t size() const { return id_a.size(); }
  // Per-bond arrays for the checkpoint and compaction (breaks apart).
  template <class F>
  void for_each_array(F&& f) {
    f("id_a", id_a); f("id_b", id_b); f("a", a); f("b", b); f("kn", kn); f("ks", ks); f("radius", radius);
    f("tensile", tensile); f("shear", shear); f("fn", fn); f("fs", fs); f("moment", moment);
  }
};

// A new bond's properties, before its state (all zero at creation).
struct BondSpec {
  double kn, ks, radius, tensile, shear;
};
void add_bond(Bonds& bonds, std::int64_t id_a, std::int64_t id_b, std::uint32_t a, std::uint32_t b, const BondSpec& s);

// One bond's step: new normal and shear force and moment from the discs' relative motion, the
// force on b (on a the opposite), the torques, and whether (and how) it broke.
struct BondLane {
  double fn, fs, moment;
  double fx, fy, torque_a, torque_b;
  int broken;  // 0 held, 1 + BondBreakMode: broke in tension (1) or shear (2); tension first
};

// Disc b at (dx, dy) from disc a, relative velocity (dvx, dvy), spins wa, wb, radii ra, rb.
// Without divisions but one (the stage's cost is in them): the stress tests are multiplied
// through by A R, using I = (2R)^3 / 12, so R A / I = 3 / R.
inline BondLane bond_lane(double dx, double dy, double ra, double rb, double dvx, double dvy, double wa, double wb,
                          double kn, double ks, double radius, double tensile, double shear, double fn_old,
                          double fs_old, double m_old, double dt) {
  const double inv = 1.0 / std::sqrt(dx * dx + dy * dy);
  const double nx = dx * inv, ny = dy * inv;
  const double tx = -ny, ty = nx;
  const double vn = dvx * nx + dvy * ny;                       // > 0 opening
  const double vt = dvx * tx + dvy * ty - (wa * ra + wb * rb);  // as the contact's (MODEL §3)
  const double area = 2 * radius;                               // unit depth
  const double inertia = area * area * area / 12;
  const double fn = fn_old + kn * area * vn * dt;               // tension positive
  const double fs = fs_old - ks * area * vt * dt;               // along t, on b
  const double moment = m_old - kn * inertia * (wb - wa) * dt;  // on b
  // sigma = F_n / A + |M| R / I >= tensile, and tau = |F_s| / A >= shear, times A R:
  const int tension = fn * radius + 3 * std::fabs(moment) >= tensile * area * radius;
  const int sheared = std::fabs(fs) >= shear * area;
  // Force on b: the normal force pulls it back towards a, the shear force along t; the shear
  // force acts at the contact point (torque -r fs on each disc, as the contact's). Arithmetic,
  // not branches: the stage runs this in the lanes of a vector loop.
  return {fn, fs, moment, -fn * nx + fs * tx, -fn * ny + fs * ty, -ra * fs - moment, -rb * fs + moment,
          tension + 2 * ((1 - tension) & sheared)};
}

// Per-step scratch of the bond stage: each acting bond's force and torques and whether it broke.
struct BondScratch {
  std::vector<double> fx, fy, torque_a, torque_b;
  std::vector<std::int64_t> broken;  // BondLane::broken; as wide as a double: one vector type
  std::size_t acting = 0;            // the bonds [0, acting) have a dynamic disc (bond_activity)
  std::uint64_t activity_build = ~std::uint64_t{0};  // the list build `acting` was found for
};

// Puts the bonds that act (a dynamic disc: a bond of two kinematic discs, the incoming slab or
// pinned discs, is left as it is, as the pair list leaves their contact out) first, each part in
// the order of its discs' indices, which the list build keeps in cell order (the stage then reads
// the discs from cache; in the order they were made it ran 1.7x slower on the layered main
// wedge), and sizes the scratch to them. Done again after each list build (`build`; motion
// flags change only with one: World::edit_motion). The order follows the discs' alone: the same
// for any thread count and after a resume.
void prepare_bond_scratch(Bonds& bonds, const Discs& discs, std::uint64_t build, BondScratch& scratch);

// The acting bonds [begin, end) of this step (within [0, scratch.acting)): their new state into
// `bonds`, their forces into `scratch`. Bonds are independent: any split between threads gives
// the same bits.
void bond_forces_range(Bonds& bonds, const Discs& discs, double dt, BondScratch& scratch, std::size_t begin,
                       std::size_t end);

// The same for the acting bonds `which` alone (a rank's, in a step over ranks: parallel/rank_step.cpp).
void bond_forces_of(Bonds& bonds, const Discs& discs, double dt, BondScratch& scratch,
                    std::span<const std::uint32_t> which);

// On one thread, in bond order (so the sums do not depend on the thread count): adds the
// forces of the acting bonds that held onto the discs' sums, logs the broken ones (step, time)
// and removes them.
void apply_bond_forces(Bonds& bonds, const Discs& discs, BondScratch& scratch, DiscForce* forces,
                       std::uint64_t step, double time);

// Sets each bond's disc indices from the stable ids (after the discs were re-ordered, removed or
// added); a bond whose disc is gone (eroded, left the model) goes with it, unlogged: it did not
// break. `index_of_id` maps stable id to index, -1 for none.
void remap_bonds(Bonds& bonds, const std::vector<std::int64_t>& index_of_id);

}  // namespace orogen
