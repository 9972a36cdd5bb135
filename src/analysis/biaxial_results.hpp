#pragma once
// Results of a biaxial test from its output rows during shearing: the mobilised friction angle
// phi = asin((s1 - s3) / (s1 + s3)) at its peak and in the residual (large-strain) state, the
// dilatancy at the peak, and how well the confining stress was held.
#include <vector>

namespace orogen {

// One output step while shearing. Strains from the start of shearing: axial shortening
// (H0 - H) / H0, and area change (A - A0) / A0, positive when the sample dilates.
struct BiaxialRow {
  double axial_strain = 0, vol_strain = 0;
  double sigma1 = 0, sigma3 = 0;  // axial and confining stress, compression positive
};

struct BiaxialResults {
  double phi_peak = 0;        // largest mobilised friction angle [rad]
  double strain_at_peak = 0;  // axial strain where it was reached
  double phi_residual = 0;    // mean mobilised angle over the residual rows [rad] (NaN: none)
  int residual_rows = 0;
  double dilatancy_peak = 0;  // d vol_strain / d axial_strain around the peak
  double psi_peak = 0;        // dilatancy angle at the peak [rad]
  double sigma3_mean = 0;     // mean confining stress while shearing
  double sigma3_max_dev = 0;  // largest |sigma3 - target| / target over the rows
};

// Mobilised friction angle [rad] of a principal stress pair (NaN unless s1 + s3 > 0).
double mobilised_friction(double sigma1, double sigma3);

// Plane-strain dilatancy angle [rad] from D = d vol_strain / d axial_strain:
// sin psi = -d eps_v / (d eps_1 - d eps_3) with compression-positive strains, = D / (2 + D).
double dilatancy_angle(double dilatancy);

// Residual rows: axial strain at least residual_from * strain_end. The dilatancy at the peak is
// the least-squares slope over the two rows either side of it. Throws std::invalid_argument
// without rows.
BiaxialResults analyse_biaxial(const std::vector<BiaxialRow>& rows, double strain_end, double residual_from,
                               double sigma3_target);

// Critical taper [rad] of a dry, non-cohesive wedge on a flat base (Dahlen; critical_taper)
// for bulk friction angle phi and basal friction coefficient mu_b; NaN when there is none
// (phi_b >= phi: the wedge fails internally before its base slides).
double critical_taper_or_nan(double phi, double mu_b);

}  // namespace orogen
