#include "isostasy/plate_flexure.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace orogen {
namespace {

// Solves A w = q for the symmetric positive definite pentadiagonal A of the plate (rows
// c (1, -4, 6, -4, 1) + k on the diagonal, the rows cut at the ends: the clamped ghosts are
// zero) by banded Gaussian elimination without pivoting, which such a matrix does not need.
std::vector<double> solve_plate(std::span<const double> q, double c, double k) {
  const std::size_t n = q.size();
  // Row i holds A[i][i-2 .. i+2] in band[i][0 .. 4].
  std::vector<std::array<double, 5>> band(n);
  for (std::size_t i = 0; i < n; ++i) band[i] = {c, -4 * c, 6 * c + k, -4 * c, c};
  std::vector<double> w(q.begin(), q.end());
  // Forward elimination below the diagonal, two rows at a time.
  for (std::size_t i = 0; i < n; ++i) {
    const double pivot = band[i][2];
    for (std::size_t below = 1; below <= 2 && i + below < n; ++below) {
      auto& row = band[i + below];
      const double factor = row[2 - below] / pivot;
      if (factor == 0.0) continue;
      for (std::size_t j = 0; j + 2 - below < 5 && j < 3; ++j)  // columns i .. i+2 of row i
        row[2 - below + j] -= factor * band[i][2 + j];
      w[i + below] -= factor * w[i];
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    double sum = w[i];
    if (i + 1 < n) sum -= band[i][3] * w[i + 1];
    if (i + 2 < n) sum -= band[i][4] * w[i + 2];
    w[i] = sum / band[i][2];
  }
  return w;
}

}  // namespace

std::vector<double> plate_deflection(std::span<const double> load, double dx, double rigidity, double restoring) {
  if (!(restoring > 0)) throw std::invalid_argument("plate_deflection: the restoring force must be positive");
  if (!(rigidity >= 0)) throw std::invalid_argument("plate_deflection: the rigidity must be zero or positive");
  if (!(dx > 0)) throw std::invalid_argument("plate_deflection: the node spacing must be positive");
  if (rigidity == 0) {
    std::vector<double> w(load.begin(), load.end());
    for (double& v : w) v /= restoring;
    return w;
  }
  return solve_plate(load, rigidity / (dx * dx * dx * dx), restoring);
}

double flexural_parameter(double rigidity, double restoring) { return std::pow(4 * rigidity / restoring, 0.25); }

}  // namespace orogen
