#include "experiments/wedge_summary.hpp"

#include <cmath>
#include <limits>

#include "analysis/profile_fit.hpp"

namespace orogen {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kShapeFields = sizeof(WedgeShape) / sizeof(double);

double mean_finite(const std::vector<double>& v) {
  double sum = 0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) { sum += x; ++n; }
  return n > 0 ? sum / n : kNaN;
}

}  // namespace

std::vector<SummaryValue> WedgeHistory::summary(double fit_from) const {
  std::vector<double> log_s, log_h, alpha, beta;
  for (const WedgeShape& w : shapes_) {
    if (w.S < fit_from) continue;
    alpha.push_back(w.alpha);
    beta.push_back(w.beta);
    if (w.S > 0 && w.H > 0 && std::isfinite(w.H)) {
      log_s.push_back(std::log(w.S));
      log_h.push_back(std::log(w.H));
    }
  }
  const ProfileFit fit = fit_points(log_s, log_h);  // log H = log a + b log S
  const WedgeShape end = shapes_.empty() ? WedgeShape{kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN}
                                         : shapes_.back();
  return {{"S_final", "normalised convergence at the end [-]", end.S},
          {"H_final", "wedge height at the end [h0]", end.H},
          {"H_b", "exponent b of the least-squares power law H = a S^b (log-log, over the last three quarters of the run) [-]",
           fit.valid() ? fit.slope : kNaN},
          {"H_a", "prefactor a of that power law [h0]", fit.valid() ? std::exp(fit.intercept) : kNaN},
          {"H_r2", "R^2 of that fit in log-log space [-]", fit.valid() ? fit.r2 : kNaN},
          {"alpha_late_deg", "mean pro-wedge taper over the last three quarters of the run [deg]", mean_finite(alpha)},
          {"beta_late_deg", "mean retro-wedge taper over the last three quarters of the run [deg]", mean_finite(beta)},
          {"Dp_final", "pro deformation front at the end [h0]", end.Dp},
          {"Mp_final", "pro marker front at the end [h0]", end.Mp},
          {"Dr_final", "retro deformation front at the end [h0]", end.Dr},
          {"Mr_final", "retro marker front at the end [h0]", end.Mr},
          {"T_final", "peak position at the end [h0]", end.T},
          {"alpha_final_deg", "pro-wedge taper at the end [deg]", end.alpha},
          {"beta_final_deg", "retro-wedge taper at the end [deg]", end.beta}};
}

void WedgeHistory::save(ArchiveWriter& out, const std::string& prefix) const {
  std::vector<double> flat;
  flat.reserve(shapes_.size() * kShapeFields);
  for (const WedgeShape& w : shapes_)
    for (double v : {w.S, w.H, w.Dp, w.Mp, w.Dr, w.Mr, w.T, w.alpha, w.beta}) flat.push_back(v);
  out.put(prefix + ".history", flat);
}

void WedgeHistory::load(const ArchiveReader& in, const std::string& prefix) {
  shapes_.clear();
  if (!in.has(prefix + ".history")) return;
  std::vector<double> flat;
  in.get(prefix + ".history", flat);
  for (std::size_t k = 0; k + kShapeFields <= flat.size(); k += kShapeFields) {
    const double* f = flat.data() + k;
    shapes_.push_back({f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8]});
  }
}

}  // namespace orogen
