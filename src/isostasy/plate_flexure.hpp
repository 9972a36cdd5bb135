#pragma once
// The deflection of the base under a load (issue 40, docs/isostasy.md): local (Airy) or of a
// thin elastic plate over a fluid mantle, D w'''' + k w = q, on nodes dx apart. w is positive
// downward, q the load per unit length beyond the reference state and k = rho_m g the mantle's
// restoring force per unit length and deflection.
#include <span>
#include <vector>

namespace orogen {

// D = 0: Airy, w = q / k at each node. D > 0: the plate, its fourth derivative by central
// differences and the plate clamped just beyond both ends (w = 0 on two nodes past each end;
// a caller wants the ends several flexural parameters from any load). Throws
// std::invalid_argument for k <= 0, D < 0, dx <= 0.
std::vector<double> plate_deflection(std::span<const double> load, double dx, double rigidity, double restoring);

// The flexural parameter alpha = (4 D / k)^(1/4): the length over which the plate spreads a
// load (the first zero of a line load's deflection is at 3 pi alpha / 4, its forebulge at pi alpha).
double flexural_parameter(double rigidity, double restoring);

}  // namespace orogen
