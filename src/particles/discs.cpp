#include "particles/discs.hpp"

#include <numbers>

#include "util/soa.hpp"

namespace orogen {

std::size_t Discs::add(std::int64_t disc_id, double px, double py, double r) {
  const double m = std::numbers::pi * r * r;
  const double inertia = 0.5 * m * r * r;
  x.push_back(px); y.push_back(py); vx.push_back(0); vy.push_back(0);
  theta.push_back(0); omega.push_back(0);
  radius.push_back(r); mass.push_back(m); inv_mass.push_back(1.0 / m); inv_inertia.push_back(1.0 / inertia);
  id.push_back(disc_id); cluster_id.push_back(-1); cluster.push_back(kNoCluster);
  body_dx.push_back(0); body_dy.push_back(0);
  motion.push_back(static_cast<std::uint8_t>(Motion::Dynamic));
  x0.push_back(px); y0.push_back(py); depth0.push_back(0);
  if (has_materials) { material.push_back(0); slip.push_back(0); }
  return x.size() - 1;
}

void Discs::enable_materials() {
  has_materials = true;
  material.resize(size(), 0);
  slip.resize(size(), 0.0);
}

void Discs::permute(std::span<const std::uint32_t> order) { permute_arrays(*this, order); }

void Discs::compact(std::span<const std::uint8_t> keep) { compact_arrays(*this, keep); }

}  // namespace orogen
