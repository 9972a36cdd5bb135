#include "contact/contact_law.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace orogen {

namespace {
constexpr double kTableStep = 0.01;  // in omega0 dt
constexpr int kTableSize = 101;      // covers omega0 dt up to 1 (the stable limit is ~0.63)
}  // namespace

namespace {
// Table position of omega0 dt: entry k and the interpolation weight of entry k + 1.
std::pair<int, double> table_position(double kn, double m_eff, double dt) {
  const double omega0 = std::sqrt(kn / m_eff);
  const double u = std::min(omega0 * dt / kTableStep, kTableSize - 1.0);
  const int k = std::min(static_cast<int>(u), kTableSize - 2);
  return {k, u - k};
}
}  // namespace

double ContactLaw::zeta_entry(int k) const {
  if (table_e_ != restitution) {
    // Entries are filled on first use: a run only touches the few near its omega0 dt.
    zeta_table_.assign(kTableSize, -1.0);
    table_e_ = restitution;
  }
  if (zeta_table_[k] < 0)
    zeta_table_[k] = k == 0 ? damping_ratio_for_restitution(restitution)
                            : discrete_damping_ratio(restitution, k * kTableStep);
  return zeta_table_[k];
}

void ContactLaw::prepare_damping(double m_lo, double m_hi, double dt) const {
  if (damping == NormalDamping::PerMass) return;
  // Larger masses sit lower in the table (omega0 dt falls with mass).
  const int k_lo = table_position(kn, m_hi, dt).first, k_hi = table_position(kn, m_lo, dt).first;
  for (int k = k_lo; k <= k_hi + 1; ++k) zeta_entry(k);
}

double ContactLaw::gamma_n(double m_eff, double dt) const {
  if (damping == NormalDamping::PerMass) return damping_rate * m_eff;
  const auto [k, f] = table_position(kn, m_eff, dt);
  const double zeta = (1 - f) * zeta_entry(k) + f * zeta_entry(k + 1);
  return 2.0 * zeta * std::sqrt(kn * m_eff);
}

namespace {
// Unit mass, unit approach speed, omega0 = 1, step h; the first step in contact starts with
// overlap phase * h.
double discrete_rebound(double zeta, double h, double phase) {
  double delta = phase * h, rate = 1.0;  // overlap and its rate
  for (int s = 0; s < 1000000; ++s) {
    double f = 0;
    if (delta > 0) f = std::max(0.0, delta + 2.0 * zeta * rate);
    rate -= f * h;
    delta += rate * h;
    if (delta <= 0 && rate < 0) return -rate;
  }
  return 0.0;
}
}  // namespace

double discrete_restitution(double zeta, double h) {
  // Averaged over where within a step the discs first touch.
  constexpr int kPhases = 8;
  double sum = 0;
  for (int k = 0; k < kPhases; ++k) sum += discrete_rebound(zeta, h, (k + 0.5) / kPhases);
  return sum / kPhases;
}

double discrete_damping_ratio(double e, double h) {
  if (!(e >= kMinRestitution && e <= 1))
    throw std::invalid_argument("restitution must be in [0.14, 1] (the no-pull dashpot cannot dissipate more)");
  // Restitution falls with zeta until the explicit dashpot itself turns unstable (zeta h of
  // order 1/2); search below that turning point. A restitution lower than this step can give
  // is clamped to the most dissipative stable value.
  double hi = 0.02;
  while (hi < 4.0 && discrete_restitution(hi + 0.02, h) < discrete_restitution(hi, h)) hi += 0.02;
  double lo = 0.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (discrete_restitution(mid, h) > e) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// For delta(t) = A exp(-zeta w0 t) sin(wd t), the force k delta + gamma delta' vanishes when
// tan(wd t) = -2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2).
double contact_duration(double zeta, double omega0) {
  const double s = std::sqrt(1.0 - zeta * zeta);
  const double wd = omega0 * s;
  const double phase = std::atan2(2.0 * zeta * s, 1.0 - 2.0 * zeta * zeta);
  return (std::numbers::pi - phase) / wd;
}

double restitution_for_damping_ratio(double zeta) {
  if (zeta <= 0) return 1.0;
  const double s = std::sqrt(1.0 - zeta * zeta);
  const double t = contact_duration(zeta, 1.0);  // omega0 = 1: e is scale free
  const double wd = s;
  // delta'(t) / v0 = exp(-zeta t) (cos(wd t) - zeta/s sin(wd t))
  const double rate = std::exp(-zeta * t) * (std::cos(wd * t) - zeta / s * std::sin(wd * t));
  return -rate;
}

double damping_ratio_for_restitution(double e) {
  if (!(e >= kMinRestitution && e <= 1))
    throw std::invalid_argument("restitution must be in [0.14, 1] (the no-pull dashpot cannot dissipate more)");
  if (e == 1.0) return 0.0;
  // restitution_for_damping_ratio falls monotonically on [0, 1).
  double lo = 0.0, hi = kMaxDampingRatio;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (restitution_for_damping_ratio(mid) > e) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace orogen
