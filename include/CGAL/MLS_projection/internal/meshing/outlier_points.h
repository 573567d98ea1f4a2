// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The outliers of a scan: the points that lie apart from the others or off their local surface.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTLIER_POINTS_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTLIER_POINTS_H

#include <CGAL/MLS_projection/internal/projection/Point_tree.h>

#include <CGAL/for_each.h>

#include <Eigen/Eigenvalues>

#include <boost/range/irange.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// Flags the outliers of `points`, of two kinds.
/// - Isolated points: with \f$d(p)\f$ the root-mean-square distance from \f$p\f$ to its 6 nearest
///   other points, \f$p\f$ is isolated when \f$d(p)\f$ exceeds 3 times the median of \f$d\f$ over
///   those 6 neighbours (a point off a surface among its samples), or 4 times its median \f$\bar d\f$
///   over all points (a point among other outliers). A region sampled more than 4 times as sparsely
///   as the median (16 times fewer points per area) is flagged too.
/// - Points off their local surface: with the plane fitted (principal component analysis) to the
///   20 nearest other points of \f$p\f$, \f$p\f$ is flagged when its distance to the plane exceeds
///   both \f$\bar d\f$ (about the spacing) and 3 times the 90th percentile of the distances of those
///   points to the plane. An outlier within a few spacings of the surface is not isolated (its
///   neighbours are the surface's samples, a few spacings away) but is off their plane; a sample of
///   a surface with Gaussian noise \f$\sigma\f$ is not, short of \f$4.9\sigma\f$ (3 times the 90th
///   percentile of \f$|N(0, \sigma)|\f$); nor is a sample at a crease, at a corner or on a thin
///   plate: some of its neighbours are as far from their plane.
///
/// The flags do not depend on the threads.
template <class ConcurrencyTag>
std::vector<bool> outlier_points(const std::vector<Vec<3>>& points) {
  constexpr std::size_t k = 6, k_plane = 20;
  const std::size_t n = points.size();
  std::vector<bool> outlier(n, false);
  if(n <= 2 * k) return outlier;
  const Point_tree<3> tree(points);
  std::vector<double> d(n), off(n, 0.);
  std::vector<std::array<std::size_t, k>> neighbors(n);
  CGAL::for_each<ConcurrencyTag>(boost::irange<std::size_t>(0, n), [&](std::size_t i) {
    thread_local std::vector<std::pair<double, std::size_t>> found;
    thread_local std::vector<double> residuals;
    tree.k_nearest(points[i], k_plane + 1, found);
    found.erase(std::remove_if(found.begin(), found.end(), [i](const auto& f) { return f.second == i; }), found.end());
    double sum = 0;
    Vec<3> centroid = Vec<3>::Zero();
    for(std::size_t j = 0; j < found.size(); ++j) {
      if(j < k) {
        sum += found[j].first;
        neighbors[i][j] = found[j].second;
      }
      centroid += points[found[j].second];
    }
    d[i] = std::sqrt(sum / double(k));
    // the distance to the neighbours' plane where it exceeds 3 times the 90th percentile of theirs
    centroid /= double(found.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const auto& f : found) covariance += (points[f.second] - centroid) * (points[f.second] - centroid).transpose();
    const Vec<3> normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
    residuals.clear();
    for(const auto& f : found) residuals.push_back(std::abs((points[f.second] - centroid).dot(normal)));
    const std::size_t q = residuals.size() * 9 / 10;
    std::nth_element(residuals.begin(), residuals.begin() + q, residuals.end());
    const double distance = std::abs((points[i] - centroid).dot(normal));
    off[i] = distance > 3. * residuals[q] ? distance : 0.;
    return true;
  });
  std::vector<double> sorted(d);
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double global = sorted[n / 2];
  for(std::size_t i = 0; i < n; ++i) {
    std::array<double, k> around;
    for(std::size_t j = 0; j < k; ++j) around[j] = d[neighbors[i][j]];
    std::nth_element(around.begin(), around.begin() + k / 2, around.end());
    const double reference = (std::min)(around[k / 2], 4. / 3. * global);
    outlier[i] = (reference > 0 && d[i] > 3. * reference) // not among duplicates
                 || off[i] > global;
  }
  return outlier;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTLIER_POINTS_H
