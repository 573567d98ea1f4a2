// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_CLOSEST_POINT_H
#define CGAL_MLS_PROJECTION_CLOSEST_POINT_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctionSpaces
/// The closest-point projection \f$C_f(x)\f$ of a point \f$x\f$ onto a member \f$f\f$ of a
/// function space (a model of `MLSFunctionSpace`), everything in frame coordinates: the first
/// `D-1` coordinates in the frame's tangent hyperplane, the last along its normal \f$e_D\f$.
///
/// \tparam D the ambient dimension, 2 or 3
template <int D>
struct Closest_point {
  /// A point or vector in frame coordinates.
  using Vector = Eigen::Matrix<double, D, 1>;
  /// The closest point of \f$x\f$ on the graph (or fan) of \f$f\f$.
  Vector point;
  /// The unit normal of \f$f\f$ at `point`, on the "up" side (the side of \f$+e_D\f$ for a
  /// graph). At a point on a feature, the normalised sum of the normals of the adjacent faces.
  Vector normal;
  /// \f$+|x - \mathrm{point}|\f$ when \f$(x - \mathrm{point})\cdot\mathrm{normal} > 0\f$, else
  /// \f$-|x - \mathrm{point}|\f$: continuous across the surface, the residual of the unified operator.
  double signed_distance = 0;
  /// `true` when `point` lies on a crease or at the apex of \f$f\f$ (a \f$C^0\f$ feature).
  bool is_on_feature = false;
  /// The unit direction of the crease through `point` (3D, on a crease, or at an apex that lies
  /// on a crease, as that of a fan whose faces lie in two planes); zero at a corner, at smooth
  /// points and in 2D.
  Vector direction = Vector::Zero();
};

namespace internal {

/// Fills `signed_distance` of `cp` for the query `x` from `cp.point` and `cp.normal`.
template <int D>
inline void set_signed_distance(Closest_point<D>& cp, const Vec<D>& x) {
  const Vec<D> d = x - cp.point;
  const double len = d.norm();
  cp.signed_distance = (d.dot(cp.normal) < 0) ? -len : len;
}

} // namespace internal

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_CLOSEST_POINT_H
