// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEIGHBORHOOD_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEIGHBORHOOD_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// A sample is on the other side than `side` when its normal makes more than 120 degrees with it
/// and it lies more than a quarter of h behind the reference point (the manual's "Thin parts":
/// the normal alone drops a face of noisy concave creases).
constexpr double other_side_cosine = -0.5;
constexpr double other_side_depth = 0.25; // in units of h

/// The side of a query at `r` (`Neighborhood::side`) in a sample set with normals: the direction
/// of the sum of the normals of the 6 input points nearest to `r` (a vote, so that one wrong
/// normal does not turn a query to the other side), or zero when they cancel.
template <int D, class Samples>
Vec<D> side_at(const Samples& samples, const Vec<D>& r) {
  thread_local std::vector<std::size_t> idx;
  samples.k_nearest(r, 6, idx);
  Vec<D> s = Vec<D>::Zero();
  for(std::size_t i : idx) s += samples.local_normal(i);
  const double len = s.norm();
  return len > 1e-3 ? Vec<D>(s / len) : Vec<D>(Vec<D>::Zero());
}

/// The input points within `radius` of `centre`, copied contiguously (local coordinates).
/// An energy whose weights vanish beyond the support radius `s` of the weight function
/// is computed exactly from this set for every frame origin `q` with
/// `|q - centre| + s <= radius` (see `covers()`); operators gather again when `q` leaves it.
/// With a nonzero `side` (a unit normal) and input normals, the points on the other side of the
/// centre (`on_side()`) are left out (`Projection_options::one_sided`).
template <int D>
struct Neighborhood {
  std::vector<std::size_t> indices;
  std::vector<Vec<D>> points;
  Vec<D> centre = Vec<D>::Zero();
  double radius = 0;
  Vec<D> side = Vec<D>::Zero();
  double depth = 0; // `other_side_depth` in input units

  /// Whether the input point of index `i` is on this neighbourhood's side, seen from `ref`.
  template <class Samples>
  bool on_side(const Samples& samples, std::size_t i, const Vec<D>& ref) const {
    return !samples.has_normals() || !(samples.local_normal(i).dot(side) < other_side_cosine) ||
           !((samples.local_point(i) - ref).dot(side) < -depth);
  }

  template <class Samples>
  void gather(const Samples& samples, const Vec<D>& c, double r) {
    centre = c;
    radius = r;
    indices.clear();
    points.clear();
    samples.for_each_in_ball(c, r, [&](std::size_t i, const Vec<D>& p) {
      if(!on_side(samples, i, c)) return;
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
    ball.side = side;
    ball.depth = depth;
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

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEIGHBORHOOD_H
