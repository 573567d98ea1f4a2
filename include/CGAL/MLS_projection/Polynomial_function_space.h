// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_POLYNOMIAL_FUNCTION_SPACE_H
#define CGAL_MLS_PROJECTION_POLYNOMIAL_FUNCTION_SPACE_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctionSpaces
/// All polynomials of total degree at most 2 over the frame's tangent hyperplane:
/// \f$f(x) = c_0 + c_1 x + c_2 x^2\f$ in 2D and
/// \f$f(x,y) = c_0 + c_1 x + c_2 y + c_3 x^2 + c_4 xy + c_5 y^2\f$ in 3D, the classical second
/// phase of Levin's projection. The fit is a weighted linear least-squares problem on coordinates
/// scaled to unit spread, solved by Cholesky when well conditioned and else with a complete
/// orthogonal decomposition, so that a neighbourhood that does not determine every coefficient
/// (e.g. points on a line in 3D) gets the minimum-norm fit instead of a failure.
///
/// \cgalModels `MLSGraphFunctionSpace`
/// \tparam D the ambient dimension, 2 or 3
template <int D>
class Polynomial_function_space {
public:
  /// As described by the concept `MLSFunctionSpace`: the ambient dimension, the number of
  /// parameters of a member, their vector, and a point of the frame's tangent hyperplane.
  /// @{
  static constexpr int ambient_dimension = D;
  static constexpr int number_of_parameters = (D == 2) ? 3 : 6;
  using Parameters = Eigen::Matrix<double, number_of_parameters, 1>;
  using Vector = Eigen::Matrix<double, D, 1>; ///< a point or vector in frame coordinates
  using Domain_point = Eigen::Matrix<double, D - 1, 1>;
  /// @}

  /// The name of the space, `"polynomial"`.
  static const char* name() { return "polynomial"; }
  /// The number of coefficients: the fit needs as many points.
  static constexpr std::size_t minimum_number_of_points() { return number_of_parameters; }

  /// The weighted least-squares fit to `n` points in frame coordinates with weights `w`.
  Parameters fit(const Vector* p, const double* w, std::size_t n) const {
    using Matrix = Eigen::Matrix<double, number_of_parameters, number_of_parameters>;
    // Scale the domain to unit weighted spread for a well-conditioned system.
    double sw = 0, su = 0;
    for(std::size_t i = 0; i < n; ++i) {
      sw += w[i];
      su += w[i] * p[i].template head<D - 1>().squaredNorm();
    }
    const double s = (sw > 0 && su > 0) ? std::sqrt(su / sw) : 1.;
    Matrix A = Matrix::Zero();
    Parameters b = Parameters::Zero();
    for(std::size_t i = 0; i < n; ++i) {
      if(w[i] <= 0) continue;
      const Parameters m = basis(Domain_point(p[i].template head<D - 1>() / s));
      A.noalias() += w[i] * m * m.transpose();
      b.noalias() += w[i] * p[i][D - 1] * m;
    }
    // Cholesky when the system is well conditioned (the usual case), else the minimum-norm fit
    Parameters c;
    const Eigen::LDLT<Matrix> ldlt(A);
    const auto pivots = ldlt.vectorD();
    if(ldlt.info() == Eigen::Success && pivots.minCoeff() > 1e-10 * pivots.maxCoeff()) {
      c = ldlt.solve(b);
    } else {
      Eigen::CompleteOrthogonalDecomposition<Matrix> cod(A);
      cod.setThreshold(1e-10);
      c = cod.solve(b);
    }
    if(!c.allFinite()) c.setZero();
    // Undo the scaling: a coefficient of a monomial of degree d is divided by s^d.
    const double scale[3] = {1., 1. / s, 1. / (s * s)};
    for(int j = 0; j < number_of_parameters; ++j) c[j] *= scale[degree(j)];
    return c;
  }

  /// \f$f(u)\f$
  double height(const Parameters& c, const Domain_point& u) const { return c.dot(basis(u)); }

  /// \f$\nabla f(u)\f$
  Domain_point gradient(const Parameters& c, const Domain_point& u) const {
    Domain_point g;
    if constexpr(D == 2) {
      g[0] = c[1] + 2 * c[2] * u[0];
    } else {
      g[0] = c[1] + 2 * c[3] * u[0] + c[4] * u[1];
      g[1] = c[2] + c[4] * u[0] + 2 * c[5] * u[1];
    }
    return g;
  }

private:
  static Parameters basis(const Domain_point& u) {
    Parameters m;
    if constexpr(D == 2) {
      m << 1., u[0], u[0] * u[0];
    } else {
      m << 1., u[0], u[1], u[0] * u[0], u[0] * u[1], u[1] * u[1];
    }
    return m;
  }
  static int degree(int j) {
    if constexpr(D == 2) return j;
    else return j == 0 ? 0 : (j < 3 ? 1 : 2);
  }
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_POLYNOMIAL_FUNCTION_SPACE_H
