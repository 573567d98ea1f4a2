// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PROJECTION_RESULT_H
#define CGAL_MLS_PROJECTION_PROJECTION_RESULT_H

#include <CGAL/MLS_projection/Projection_status.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The local reference frame \f$H\f$ of a projection: an origin \f$q\f$, a unit normal and
/// an orthonormal basis of the tangent hyperplane (one vector in 2D, two in 3D).
/// The coefficients of the local function are expressed in this frame.
template <class GeomTraits, int D>
struct Local_frame {
  using Point = typename internal::Kernel_types<GeomTraits, D>::Point;   ///< `Point_2` or `Point_3`
  using Vector = typename internal::Kernel_types<GeomTraits, D>::Vector; ///< `Vector_2` or `Vector_3`
  Point origin;                        ///< the origin \f$q\f$
  Vector normal;                       ///< the unit normal, the last axis of the frame
  std::array<Vector, D - 1> tangents;  ///< the first `D-1` axes, orthonormal, orthogonal to `normal`
};

/// \ingroup PkgMLSProjectionRef
/// Which operator made the local fit of a projection result, and so how its `coefficients` read.
enum class Local_fit_kind {
  /// No local fit: the projection failed.
  NONE,
  /// Levin's \f$\mathcal{P}_L\f$ (also the result of a `LEVIN_FALLBACK`): a member of the Levin
  /// operator's function space, the graph of a height function over the frame's tangent
  /// hyperplane, in the input's length unit.
  LEVIN,
  /// A closest-point operator (\f$\mathcal{P}_S\f$, \f$\mathcal{P}_E\f$, \f$\mathcal{P}_U\f$):
  /// a member of its function space in frame coordinates divided by its bandwidth \f$h\f$.
  CLOSEST_POINT
};

/// \ingroup PkgMLSProjectionRef
/// Everything a projection computes. When `status` is not a success (see `is_success()`),
/// `point` is the query itself and `normal` is the null vector: no field is ever NaN.
template <class GeomTraits, int D>
struct Projection_result {
  using FT = typename GeomTraits::FT;                                     ///< the kernel's number type
  using Point = typename internal::Kernel_types<GeomTraits, D>::Point;   ///< `Point_2` or `Point_3`
  using Vector = typename internal::Kernel_types<GeomTraits, D>::Vector; ///< `Vector_2` or `Vector_3`

  /// The projected point \f$P(r)\f$.
  Point point;
  /// The unit normal of the local function at `point`, oriented as documented by the operator.
  Vector normal;
  /// The local frame \f$H\f$ found by the optimisation.
  Local_frame<GeomTraits, D> frame;
  /// The parameters of the local function in `frame`, as documented by the function space.
  std::vector<double> coefficients;
  /// The operator that fitted `coefficients` (with `Mixed_projection`: `LEVIN` for its smooth
  /// space, `CLOSEST_POINT` for its sharp one).
  Local_fit_kind fit_kind = Local_fit_kind::NONE;
  /// The weighted mean squared residual of the final local fit (squared length units).
  double energy = 0;
  /// Iterations of the non-linear optimiser (summed over all starts and rounds).
  int iterations = 0;
  /// The number of input points in the final neighbourhood.
  std::size_t number_of_neighbors = 0;
  /// `true` when `point` lies on a feature (crease or apex) of the local function.
  bool is_on_feature = false;
  /// The crease direction when `is_on_feature` (null otherwise, and at an apex).
  Vector feature_direction = NULL_VECTOR;
  /// Whether the projection succeeded, and if not, why.
  Projection_status status = Projection_status::INVALID_QUERY;

  /// `true` when `status` is a success (`CONVERGED`, `NOT_CONVERGED` or `LEVIN_FALLBACK`).
  bool is_success() const { return MLS::is_success(status); }
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PROJECTION_RESULT_H
