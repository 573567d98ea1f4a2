// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A local frame as optimised by the single-phase operators: an origin q and a rotation
// R = R0 * exp(w) whose last column is the frame normal and whose first D-1 columns span the
// tangent hyperplane. The tilt w (D-1 angles: about the tangent axes) is smooth everywhere and
// transports the tangent axes with the normal, so the parameters of the local function keep
// their meaning while the frame turns.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_FRAME_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_FRAME_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <Eigen/Geometry>

#include <cmath>

namespace CGAL {
namespace MLS {
namespace internal {

template <int D>
struct Frame {
  Vec<D> origin = Vec<D>::Zero();
  Mat<D> axes = Mat<D>::Identity(); // columns: tangents, then the normal

  Vec<D> normal() const { return axes.col(D - 1); }
  Vec<D> to_frame(const Vec<D>& p) const { return axes.transpose() * (p - origin); }
  Vec<D> to_local(const Vec<D>& y) const { return origin + axes * y; }
  Vec<D> vector_to_local(const Vec<D>& v) const { return axes * v; }

  /// The frame with origin `q` and normal `n`, tangents from `tangent_basis`.
  static Frame from_normal(const Vec<D>& q, const Vec<D>& n) {
    Frame f;
    f.origin = q;
    const auto t = tangent_basis<D>(n);
    for(int j = 0; j < D - 1; ++j) f.axes.col(j) = t[j];
    f.axes.col(D - 1) = n;
    return f;
  }

  /// This frame tilted by the angles `w` (about its tangent axes) and moved by `offset`.
  template <class Angles>
  Frame moved(const Vec<D>& offset, const Angles& w) const {
    Frame f;
    f.origin = origin + offset;
    if constexpr(D == 2) {
      const double c = std::cos(w[0]), s = std::sin(w[0]);
      Mat<2> rot;
      rot << c, -s, s, c;
      f.axes = axes * rot;
    } else {
      // rotation vector in frame coordinates: about the first and second tangent axes
      const Vec<3> v(w[0], w[1], 0.);
      const double angle = v.norm();
      f.axes = angle > 0 ? Mat<3>(axes * Eigen::AngleAxisd(angle, v / angle).toRotationMatrix()) : axes;
    }
    return f;
  }
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_FRAME_H
