#pragma once
// Critical taper of a dry, non-cohesive Coulomb wedge (Dahlen 1984; MODEL §9): the surface
// slope alpha at which a wedge of bulk internal friction angle phi on a base of friction angle
// phi_b, dipping at beta, is everywhere at failure. Angles in radians.
#include <stdexcept>

namespace orogen {

struct CriticalTaperError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Solves alpha + beta = psi_b - psi_0 with psi_b = (asin(sin phi_b / sin phi) - phi_b) / 2 and
// psi_0 = (asin(sin alpha / sin phi) - alpha) / 2 by bisection on (-phi, phi), where the
// left side minus the right grows monotonically. Throws CriticalTaperError (naming the
// values) when the base is not weaker than the wedge (phi_b >= phi) or the angles are out of
// range, and when no taper in (-phi, phi) satisfies the condition.
double critical_taper(double phi, double phi_b, double beta = 0.0);

}  // namespace orogen
