#pragma once
// Named materials of a layered crust (docs/materials.md): each disc carries the index of its
// material, and the contact law takes its friction from the materials of the two discs, weakened
// by the slip the discs have accumulated, and its bonds (contact/bonds.hpp) from their bond
// properties. A world without materials (the thesis's one material, contact.mu everywhere) keeps
// no per-disc material state and runs the contact law exactly as before.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace orogen {

// The parallel bond a material makes between its touching discs (Potyondy and Cundall 2004, in
// 2-D: a beam of width 2 R = 2 lambda min(r_i, r_j) and unit depth). Strengths are stresses in
// rho g d (the lithostatic stress at depth z is about z times the packing's solid fraction).
struct BondProperties {
  double tensile_strength = 0;  // 0: the material makes no bonds
  double shear_strength = 0;
  double stiffness = 1;         // bond normal stiffness per unit area of bond, in contact.kn / d
  double radius_factor = 1;     // lambda
  double strength_scatter = 0;  // coefficient of variation of each bond's strengths (seeded normal, cut at 0)
  double gap = 0.05;            // pairs whose surfaces are at most this far apart bond [d]
  bool bonds() const { return tensile_strength > 0 || shear_strength > 0; }
};

struct Material {
  std::string name;
  double friction = 0.3;           // peak Coulomb coefficient
  double friction_residual = 0.3;  // after weakening_distance of slip
  double weakening_distance = 1;   // accumulated slip from peak to residual [d]
  double rolling_friction = 0;     // mu_r of its contacts (ContactLaw::rolling_friction)
  BondProperties bond;

  // Friction of a disc of this material that has slipped `slip` on its contacts: linear from
  // peak to residual over weakening_distance, then residual (branch-free).
  double friction_at(double slip) const {
    const double lost = std::min(1.0, slip / weakening_distance);
    return friction - (friction - friction_residual) * lost;
  }
};

// Friction of a contact between two discs of (weakened) frictions mu_i and mu_j: the weaker, so
// that a weak layer slides on its neighbours as it does within itself (PFC's rule).
inline double pair_friction(double mu_i, double mu_j) { return std::min(mu_i, mu_j); }
// The same rule for the rolling resistance of a contact between two materials.
inline double pair_rolling_friction(double mur_i, double mur_j) { return std::min(mur_i, mur_j); }

// One unit of the incoming section ([[layer.units]]), listed from the base up.
struct LayerUnit {
  std::size_t material = 0;  // index into MaterialTable::list
  double thickness = 0;      // [d]
};

// The materials of a world, by index (Discs::material), and the incoming section built of them.
// Empty: the thesis's single material.
struct MaterialTable {
  std::vector<Material> list;
  std::vector<LayerUnit> units;  // empty: the whole layer is material 0
  bool empty() const { return list.empty(); }
  std::size_t size() const { return list.size(); }
  // Whether any material makes bonds.
  bool any_bonds() const {
    return std::any_of(list.begin(), list.end(), [](const Material& m) { return m.bond.bonds(); });
  }
  // Whether any material resists rolling.
  bool any_rolling() const {
    return std::any_of(list.begin(), list.end(), [](const Material& m) { return m.rolling_friction > 0; });
  }
};

// The material of a disc whose centre is `height` above the layer's base: the unit that holds
// it; above the last unit's top (a section thinner than the layer), the last unit's.
inline std::size_t material_at_height(const std::vector<LayerUnit>& units, double height) {
  double top = 0;
  for (const auto& u : units) {
    top += u.thickness;
    if (height < top) return u.material;
  }
  return units.empty() ? 0 : units.back().material;
}

}  // namespace orogen
