// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_WEIGHTED_PCA_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_WEIGHTED_PCA_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <Eigen/Eigenvalues>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

template <int D>
struct Pca {
  Vec<D> centroid = Vec<D>::Zero();
  Vec<D> eigenvalues = Vec<D>::Zero();   // ascending
  Mat<D> eigenvectors = Mat<D>::Identity(); // columns, matching `eigenvalues`
  bool valid = false;

  Vec<D> minor_axis() const { return eigenvectors.col(0); }
  /// The neighbourhood spans no hyperplane: all points equal, or (in 3D) collinear.
  bool is_degenerate() const {
    const double largest = eigenvalues[D - 1];
    if(!(largest > 0)) return true;
    return D == 3 && eigenvalues[1] <= 1e-10 * largest;
  }
};

/// The weighted principal component analysis of the points `p` with weights `w`.
template <int D>
Pca<D> weighted_pca(const std::vector<Vec<D>>& p, const std::vector<double>& w) {
  Pca<D> pca;
  double sw = 0;
  for(std::size_t i = 0; i < p.size(); ++i) {
    pca.centroid += w[i] * p[i];
    sw += w[i];
  }
  if(!(sw > 0)) return pca;
  pca.centroid /= sw;
  Mat<D> cov = Mat<D>::Zero();
  for(std::size_t i = 0; i < p.size(); ++i) {
    const Vec<D> d = p[i] - pca.centroid;
    cov.noalias() += w[i] * d * d.transpose();
  }
  cov /= sw;
  Eigen::SelfAdjointEigenSolver<Mat<D>> solver(cov);
  if(solver.info() != Eigen::Success) return pca;
  pca.eigenvalues = solver.eigenvalues();
  pca.eigenvectors = solver.eigenvectors();
  pca.valid = pca.eigenvalues.allFinite() && pca.eigenvectors.allFinite();
  return pca;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_WEIGHTED_PCA_H
