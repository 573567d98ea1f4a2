// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PLANE_FUNCTION_SPACE_H
#define CGAL_MLS_PROJECTION_PLANE_FUNCTION_SPACE_H

#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <cstddef>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctionSpaces
/// The trivial function space \f$\mathcal{F} = \{0\}\f$: the local surface is the frame's
/// hyperplane itself. With it, Levin's projection is the first phase alone
/// (the projection of the query onto the optimal plane).
///
/// \cgalModels `MLSGraphFunctionSpace`
/// \cgalModels `MLSFunctionSpace`
/// \tparam D the ambient dimension, 2 or 3
template <int D>
class Plane_function_space {
public:
  /// As described by the concept `MLSFunctionSpace`: the ambient dimension, the number of
  /// parameters of a member, their vector, and a point of the frame's tangent hyperplane.
  /// @{
  static constexpr int ambient_dimension = D;
  static constexpr int number_of_parameters = 0;
  using Parameters = Eigen::Matrix<double, 0, 1>;
  using Vector = Eigen::Matrix<double, D, 1>; ///< a point or vector in frame coordinates
  using Domain_point = Eigen::Matrix<double, D - 1, 1>;
  /// @}

  /// The name of the space, `"plane"`.
  static const char* name() { return "plane"; }
  /// The fewest neighbours a fit needs.
  static constexpr std::size_t minimum_number_of_points() { return D; }

  /// The member fitted to `n` points in frame coordinates (the first `D-1` coordinates in the
  /// tangent hyperplane, the last along the normal) with weights `w`: always \f$f = 0\f$.
  Parameters fit(const Vector*, const double*, std::size_t) const { return Parameters(); }
  /// \f$f(u)\f$
  double height(const Parameters&, const Domain_point&) const { return 0.; }
  /// \f$\nabla f(u)\f$
  Domain_point gradient(const Parameters&, const Domain_point&) const { return Domain_point::Zero(); }

  /// The only member, \f$f = 0\f$ (no parameters).
  Parameters identity() const { return Parameters(); }

  /// The orthogonal projection of `x` (frame coordinates) onto the hyperplane \f$x_D = 0\f$:
  /// normal \f$e_D\f$, signed distance \f$x_D\f$, never on a feature.
  Closest_point<D> closest_point(const Parameters&, const Vector& x) const {
    Closest_point<D> cp;
    cp.point = x;
    cp.point[D - 1] = 0.;
    cp.normal = Vector::Unit(D - 1);
    cp.signed_distance = x[D - 1];
    return cp;
  }

  /// The closest points of the `n` points `x` (no parameters, hence no gradients).
  void closest_points(const Parameters& c, const Vector* x, std::size_t n, Closest_point<D>* out,
                      Parameters*) const {
    for(std::size_t i = 0; i < n; ++i) out[i] = closest_point(c, x[i]);
  }

  /// The point of the graph above or below `x` (for `Single_phase_projection`): here the same
  /// as `closest_point()`.
  Closest_point<D> vertical_projection(const Parameters& c, const Vector& x) const {
    return closest_point(c, x);
  }
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PLANE_FUNCTION_SPACE_H
