#include "analysis/biaxial_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/critical_taper.hpp"

namespace orogen {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double mobilised_friction(double s1, double s3) {
  if (!(s1 + s3 > 0)) return kNaN;
  return std::asin(std::clamp((s1 - s3) / (s1 + s3), -1.0, 1.0));
}

double dilatancy_angle(double D) {
  if (!std::isfinite(D) || 2 + D <= 0) return kNaN;
  return std::asin(std::clamp(D / (2 + D), -1.0, 1.0));
}

BiaxialResults analyse_biaxial(const std::vector<BiaxialRow>& rows, double strain_end, double residual_from,
                               double sigma3_target) {
  if (rows.empty()) throw std::invalid_argument("analyse_biaxial: no rows");
  BiaxialResults r;
  std::size_t peak = 0;
  double residual_sum = 0, s3_sum = 0;
  r.phi_peak = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double phi = mobilised_friction(rows[k].sigma1, rows[k].sigma3);
    if (phi > r.phi_peak) {
      r.phi_peak = phi;
      peak = k;
    }
    if (rows[k].axial_strain >= residual_from * strain_end && std::isfinite(phi)) {
      residual_sum += phi;
      ++r.residual_rows;
    }
    s3_sum += rows[k].sigma3;
    r.sigma3_max_dev = std::max(r.sigma3_max_dev, std::fabs(rows[k].sigma3 - sigma3_target) / sigma3_target);
  }
  if (!std::isfinite(r.phi_peak)) r.phi_peak = kNaN;
  r.strain_at_peak = rows[peak].axial_strain;
  r.phi_residual = r.residual_rows ? residual_sum / r.residual_rows : kNaN;
  r.sigma3_mean = s3_sum / static_cast<double>(rows.size());
  // Slope of vol_strain against axial strain over the rows around the peak.
  const std::size_t lo = peak >= 2 ? peak - 2 : 0, hi = std::min(rows.size() - 1, peak + 2);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = lo; k <= hi; ++k) {
    const double x = rows[k].axial_strain, y = rows[k].vol_strain;
    n += 1; sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const double den = n * sxx - sx * sx;
  r.dilatancy_peak = den > 0 ? (n * sxy - sx * sy) / den : kNaN;
  r.psi_peak = dilatancy_angle(r.dilatancy_peak);
  return r;
}

double critical_taper_or_nan(double phi, double mu_b) {
  if (!std::isfinite(phi)) return kNaN;
  try {
    return critical_taper(phi, std::atan(mu_b), 0.0);
  } catch (const CriticalTaperError&) {
    return kNaN;
  }
}

}  // namespace orogen
