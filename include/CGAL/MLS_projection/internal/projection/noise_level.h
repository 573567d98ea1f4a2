// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The variance of the noise of a sample set, estimated at a scale small enough that coarse
// samplings of creased shapes keep points whose neighbourhoods lie on one smooth face, and the
// energy above which a quadratic fit does not explain the data.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NOISE_LEVEL_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NOISE_LEVEL_H

#include <CGAL/MLS_projection/internal/projection/weighted_pca.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The noise variance \f$\hat\sigma^2\f$ of `samples` (a `Sample_set`): at up to 512 input
/// points taken with a regular stride, the residual variance of the least-squares quadratic
/// height function (over the PCA frame) of its \f$k\f$ nearest input points (\f$k\f$ = 12 in 3D, 8 in
/// 2D; the quadratic has \f$m\f$ = 6 or 3 coefficients), with \f$k - m\f$ degrees of freedom; the first
/// quartile of these, divided by the first quartile of \f$\chi^2_{k-m}/(k-m)\f$ (its distribution
/// over a noisy smooth surface). The first quartile ignores the points whose neighbours straddle a
/// crease (on a box of 10 by 10 samples per face, more than a third have none), and the quadratic
/// takes the curvature of smooth parts out. 0 without noise.
template <class Samples>
double estimate_noise_variance(const Samples& samples) {
  constexpr int D = int(Samples::Local_point::RowsAtCompileTime), m = D == 3 ? 6 : 3;
  constexpr std::size_t k = D == 3 ? 12 : 8, probes = 512;
  // the first quartiles of chi^2_6 and chi^2_5 (Boost's quantile function returned NaN inside
  // mls_mesh, whose meshers change the FPU settings)
  constexpr double chi2_quartile = D == 3 ? 3.454598 : 2.674603;
  if(samples.size() <= k) return 0.;
  std::vector<double> residuals;
  std::vector<std::size_t> neighbors;
  std::vector<Vec<D>> points;
  const std::vector<double> weights(k, 1.);
  Eigen::Matrix<double, int(k), m> A;
  Eigen::Matrix<double, int(k), 1> z;
  const std::size_t stride = (std::max<std::size_t>)(1, samples.size() / probes);
  for(std::size_t i = 0; i < samples.size(); i += stride) {
    samples.k_nearest(samples.local_point(i), k, neighbors);
    if(neighbors.size() < k) continue;
    points.clear();
    for(std::size_t j : neighbors) points.push_back(samples.local_point(j));
    const Pca<D> pca = weighted_pca<D>(points, weights);
    if(!pca.valid || pca.is_degenerate()) continue;
    const double scale = std::sqrt(pca.eigenvalues[D - 1]); // conditions the columns
    for(std::size_t j = 0; j < k; ++j) {
      const Vec<D> local = pca.eigenvectors.transpose() * (points[j] - pca.centroid) / scale;
      z[j] = local[0];
      if constexpr(D == 3) A.row(j) << local[1] * local[1], local[1] * local[2], local[2] * local[2], local[1], local[2], 1.;
      else A.row(j) << local[1] * local[1], local[1], 1.;
    }
    const Eigen::Matrix<double, m, 1> c = A.colPivHouseholderQr().solve(z);
    const double rss = (A * c - z).squaredNorm() * scale * scale;
    if(std::isfinite(rss)) residuals.push_back(rss / double(k - m));
  }
  if(residuals.empty()) return 0.;
  const auto quartile = residuals.begin() + std::ptrdiff_t(residuals.size() / 4);
  std::nth_element(residuals.begin(), quartile, residuals.end());
  return *quartile / (chi2_quartile / double(k - m));
}

/// The energy (weighted mean squared residual) of \f$\mathcal{P}_L\f$'s quadratic above which it does
/// not explain the data, so that a sharp space may do better:
/// \f$\tau = \max\big((\rho h)^2, \kappa^2 \hat\sigma^2\big)\f$, \f$\rho = 0.01\f$ and
/// \f$\kappa^2\f$ = `kappa2`, one of the two margins below (see `Mixed_projection`).
inline double screening_threshold(double h, double noise_variance, double kappa2) {
  constexpr double rho = 0.01;
  return (std::max)((rho * h) * (rho * h), kappa2 * noise_variance);
}

/// \f$\kappa^2\f$ of `Mixed_projection` (manual, section "The Mixed Space").
inline constexpr double projection_noise_margin = 4.;
/// \f$\kappa^2\f$ of the seeds of `MLS_implicit_function`: lower, as a seed's fan also carries the
/// crease to the feature detection, and the function blends and checks the fits (manual, section
/// "Screening the Seeds by Levin's Operator").
inline constexpr double seed_noise_margin = 2.5;

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NOISE_LEVEL_H
