// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_NEIGHBORHOOD_H
#define CGAL_MLS_PROJECTION_INTERNAL_NEIGHBORHOOD_H

#include <CGAL/MLS_projection/internal/Dimension.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The input points within `radius` of `centre`, copied contiguously (local coordinates).
/// An energy whose weights vanish beyond the support radius `s` of the weight function
/// is computed exactly from this set for every frame origin `q` with
/// `|q - centre| + s <= radius` (see `covers()`); operators gather again when `q` leaves it.
template <int D>
struct Neighborhood {
  std::vector<std::size_t> indices;
  std::vector<Vec<D>> points;
  Vec<D> centre = Vec<D>::Zero();
  double radius = 0;

  template <class Samples>
  void gather(const Samples& samples, const Vec<D>& c, double r) {
    centre = c;
    radius = r;
    indices.clear();
    points.clear();
    samples.for_each_in_ball(c, r, [&](std::size_t i, const Vec<D>& p) {
      indices.push_back(i);
      points.push_back(p);
    });
  }

  bool covers(const Vec<D>& q, double support) const { return (q - centre).norm() + support <= radius * (1 + 1e-12); }

  /// The points of this set within `r` of `c`, as if gathered there; needs `covers(c, r)`.
  Neighborhood within(const Vec<D>& c, double r) const {
    Neighborhood ball;
    ball.centre = c;
    ball.radius = r;
    for(std::size_t i = 0; i < points.size(); ++i) {
      if((points[i] - c).squaredNorm() > r * r) continue;
      ball.indices.push_back(indices[i]);
      ball.points.push_back(points[i]);
    }
    return ball;
  }

  std::size_t size() const { return points.size(); }
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_NEIGHBORHOOD_H
