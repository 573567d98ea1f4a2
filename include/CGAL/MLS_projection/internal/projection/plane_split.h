// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Proposals of sharp features for the starts of the single-phase optimisation: the weighted
// neighbourhood is split into two (or, in 3D, three) hyperplanes by a few rounds of
// k-hyperplanes (assign each point to the nearest hyperplane, refit each by weighted PCA),
// from splits along the principal axes. Their intersection proposes a crease (two) or an apex
// (three) where a wedge fan can start.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_PLANE_SPLIT_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_PLANE_SPLIT_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>
#include <CGAL/MLS_projection/internal/projection/weighted_pca.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

template <int D>
struct Hyperplane {
  Vec<D> normal = Vec<D>::Zero();
  double offset = 0; // normal . x = offset
  Vec<D> centroid = Vec<D>::Zero(); // of the points assigned to it
  double distance(const Vec<D>& p) const { return normal.dot(p) - offset; }
};

template <int D, int K>
struct Plane_split {
  std::array<Hyperplane<D>, K> planes;
  double energy = std::numeric_limits<double>::infinity(); // weighted mean squared distance
  bool valid = false;
};

/// k-hyperplanes from the initial labels; returns the split and its energy. Each round fits
/// every hyperplane by the weighted PCA of its points (their moments summed in one pass), then
/// assigns every point to its nearest hyperplane.
template <int D, int K>
Plane_split<D, K> refine_split(const std::vector<Vec<D>>& p, const std::vector<double>& w, std::vector<int> label,
                               std::size_t minimum_per_plane) {
  Plane_split<D, K> split;
  for(int round = 0; round < 10; ++round) {
    std::array<double, K> W{};
    std::array<std::size_t, K> count{};
    std::array<Vec<D>, K> sum;
    std::array<Mat<D>, K> second;
    for(int k = 0; k < K; ++k) {
      sum[k].setZero();
      second[k].setZero();
    }
    // moments about the first point, for accuracy far from the origin
    const Vec<D> o = p.empty() ? Vec<D>::Zero() : p[0];
    for(std::size_t i = 0; i < p.size(); ++i) {
      if(!(w[i] > 0)) continue;
      const int k = label[i];
      const Vec<D> d = p[i] - o;
      W[k] += w[i];
      ++count[k];
      sum[k] += w[i] * d;
      second[k].noalias() += w[i] * d * d.transpose();
    }
    for(int k = 0; k < K; ++k) {
      if(count[k] < minimum_per_plane || !(W[k] > 0)) return split;
      const Vec<D> mean = sum[k] / W[k];
      const Mat<D> cov = second[k] / W[k] - mean * mean.transpose();
      Eigen::SelfAdjointEigenSolver<Mat<D>> solver;
      solver.computeDirect(cov);
      const Vec<D> normal = solver.eigenvectors().col(0);
      if(!normal.allFinite()) return split;
      split.planes[k].normal = normal;
      split.planes[k].centroid = o + mean;
      split.planes[k].offset = normal.dot(split.planes[k].centroid);
    }
    bool changed = false;
    double E = 0, Wt = 0;
    for(std::size_t i = 0; i < p.size(); ++i) {
      int best = 0;
      double bd = std::abs(split.planes[0].distance(p[i]));
      for(int k = 1; k < K; ++k) {
        const double d = std::abs(split.planes[k].distance(p[i]));
        if(d < bd) {
          bd = d;
          best = k;
        }
      }
      changed |= best != label[i];
      label[i] = best;
      E += w[i] * bd * bd;
      Wt += w[i];
    }
    split.energy = Wt > 0 ? E / Wt : split.energy;
    if(!changed) break;
  }
  split.valid = std::isfinite(split.energy);
  return split;
}

/// The best split of the weighted points `p` into two hyperplanes, from sign splits along each
/// principal axis of the weighted PCA `pca`. The minor axis matters too: across a wedge narrower
/// than about 70 degrees, whose bisector is the major axis, only it separates the two sides
/// (without it, P_U with the wedge space missed the apex of a 30-degree wedge by 1.4 h).
template <int D>
Plane_split<D, 2> split_in_two(const std::vector<Vec<D>>& p, const std::vector<double>& w, const Pca<D>& pca) {
  Plane_split<D, 2> best;
  std::vector<int> label(p.size());
  for(int axis = 0; axis < D; ++axis) {
    const Vec<D> a = pca.eigenvectors.col(axis);
    for(std::size_t i = 0; i < p.size(); ++i) label[i] = (p[i] - pca.centroid).dot(a) < 0 ? 0 : 1;
    const auto s = refine_split<D, 2>(p, w, label, D + 1);
    if(s.valid && s.energy < best.energy) best = s;
  }
  return best;
}

/// The best split of weighted 3D points into three planes, from 120-degree sectors around the
/// centroid in the PCA tangent plane, at three rotations.
inline Plane_split<3, 3> split_in_three(const std::vector<Vec<3>>& p, const std::vector<double>& w, const Pca<3>& pca) {
  Plane_split<3, 3> best;
  std::vector<int> label(p.size());
  const Vec<3> a = pca.eigenvectors.col(2), b = pca.eigenvectors.col(1);
  for(int rot = 0; rot < 3; ++rot) {
    const double phase = rot * (2 * CGAL_PI / 9);
    for(std::size_t i = 0; i < p.size(); ++i) {
      const Vec<3> d = p[i] - pca.centroid;
      double ang = std::atan2(d.dot(b), d.dot(a)) - phase;
      while(ang < 0) ang += 2 * CGAL_PI;
      while(ang >= 2 * CGAL_PI) ang -= 2 * CGAL_PI;
      label[i] = (std::min)(2, int(ang / (2 * CGAL_PI / 3)));
    }
    const auto s = refine_split<3, 3>(p, w, label, 4);
    if(s.valid && s.energy < best.energy) best = s;
  }
  return best;
}

/// The point of the intersection of the hyperplanes nearest to `r` (least squares; minimum-norm
/// correction from `r`). Returns false when the hyperplanes are nearly parallel.
template <int D, int K>
bool intersection_nearest(const std::array<Hyperplane<D>, K>& planes, const Vec<D>& r, Vec<D>& x) {
  Eigen::Matrix<double, K, D> A;
  Eigen::Matrix<double, K, 1> b;
  for(int k = 0; k < K; ++k) {
    A.row(k) = planes[k].normal.transpose();
    b[k] = planes[k].offset - planes[k].normal.dot(r);
  }
  Eigen::JacobiSVD<Eigen::Matrix<double, K, D>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto sv = svd.singularValues();
  if(!(sv[sv.size() - 1] > 0.17 * sv[0])) return false; // closer than ~10 degrees to parallel
  x = r + svd.solve(b);
  return x.allFinite();
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_PLANE_SPLIT_H
