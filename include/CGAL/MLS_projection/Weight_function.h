// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_WEIGHT_FUNCTION_H
#define CGAL_MLS_PROJECTION_WEIGHT_FUNCTION_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The kinds of weight function \f$\omega\f$ of the MLS energies.
enum class Weight_kind {
  /// \f$\omega(d) = (1 - d^2/R^2)^4\f$ for \f$d < R\f$, 0 beyond, with \f$R = \sqrt{6}\,h\f$ (the
  /// default): the same second moment as the Gaussian \f$e^{-d^2/h^2}\f$, so the same effective
  /// width and averaging of noise, over 2.7 times fewer points than the Gaussian cut at \f$4h\f$;
  /// smooth, without an exponential or a square root, and compactly supported, which makes
  /// members of the function space exactly reproducible (user manual, "Weights and Their Support").
  POLYNOMIAL,
  /// \f$\omega(d) = e^{-d^2/h^2}\f$, truncated at \f$4h\f$ (where the weight is below
  /// \f$10^{-6}\f$ of its maximum).
  GAUSSIAN,
  /// Wendland's \f$C^2\f$ function \f$\omega(d) = (1-d/R)^4 (4d/R+1)\f$ for \f$d < R\f$, 0 beyond,
  /// with support radius \f$R = 2.5h\f$. Compact support makes members of the function space
  /// exactly reproducible.
  WENDLAND
};

/// \ingroup PkgMLSProjectionRef
/// A radial weight function with bandwidth `h`, evaluated on squared distances.
/// Cheap to copy; all members are `const`.
class Weight_function {
public:
  /// The support radius of a weight of kind `kind`, in units of \f$h\f$.
  static constexpr double support(Weight_kind kind) {
    return kind == Weight_kind::POLYNOMIAL ? 2.449489742783178 /* sqrt(6) */ : kind == Weight_kind::GAUSSIAN ? 4. : 2.5;
  }

  /// \pre `h > 0`
  Weight_function(Weight_kind kind, double h)
    : kind_(kind), h_(h), inv_h2_(1. / (h * h)), radius_(support(kind) * h), inv_r_(1. / radius_) {
    CGAL_precondition(h > 0);
  }

  /// The kind of weight function.
  Weight_kind kind() const { return kind_; }
  /// The bandwidth \f$h\f$.
  double bandwidth() const { return h_; }
  /// The weight is zero beyond this distance.
  double support_radius() const { return radius_; }

  /// The weight of a point at squared distance `d2`.
  double operator()(double d2) const {
    if(d2 >= radius_ * radius_) return 0.;
    if(kind_ == Weight_kind::POLYNOMIAL) {
      const double s = 1. - d2 * inv_r_ * inv_r_, s2 = s * s;
      return s2 * s2;
    }
    if(kind_ == Weight_kind::GAUSSIAN) return std::exp(-d2 * inv_h2_);
    const double t = std::sqrt(d2) * inv_r_;
    const double s = 1. - t;
    const double s2 = s * s;
    return s2 * s2 * (4. * t + 1.);
  }

  /// The derivative of the weight with respect to the squared distance, at `d2`.
  double derivative(double d2) const {
    if(d2 >= radius_ * radius_) return 0.;
    if(kind_ == Weight_kind::POLYNOMIAL) {
      const double i2 = inv_r_ * inv_r_, s = 1. - d2 * i2;
      return -4. * s * s * s * i2;
    }
    if(kind_ == Weight_kind::GAUSSIAN) return -inv_h2_ * std::exp(-d2 * inv_h2_);
    const double s = 1. - std::sqrt(d2) * inv_r_; // d/d(d2) of (1-t)^4 (4t+1) = -10 (1-t)^3 / R^2
    return -10. * s * s * s * inv_r_ * inv_r_;
  }

  /// The same, given the weight `w` at `d2` (`w == (*this)(d2)`): the Gaussian's derivative is
  /// then computed without a second exponential.
  double derivative(double d2, double w) const {
    if(kind_ == Weight_kind::GAUSSIAN) return d2 >= radius_ * radius_ ? 0. : -inv_h2_ * w;
    return derivative(d2);
  }

  /// The weight `w` at the squared distance `d2` and its first and second derivatives `dw`,
  /// `ddw` with respect to `d2`; `false` (and nothing written) beyond the support. Wendland's
  /// weight, a function of \f$d\f$, has a second derivative in \f$d^2\f$ that grows as
  /// \f$1/d\f$ near 0: it is bounded there at its value at \f$d = 10^{-3} R\f$.
  bool evaluate(double d2, double& w, double& dw, double& ddw) const {
    if(!(d2 < radius_ * radius_)) return false;
    switch(kind_) {
    case Weight_kind::POLYNOMIAL: {
      const double i2 = inv_r_ * inv_r_, s = 1. - d2 * i2, s2 = s * s;
      w = s2 * s2;
      dw = -4. * s * s2 * i2;
      ddw = 12. * s2 * i2 * i2;
      return true;
    }
    case Weight_kind::GAUSSIAN:
      w = std::exp(-d2 * inv_h2_);
      dw = -inv_h2_ * w;
      ddw = inv_h2_ * inv_h2_ * w;
      return true;
    case Weight_kind::WENDLAND: {
      const double d = std::sqrt(d2), t = d * inv_r_, s = 1. - t, s2 = s * s;
      w = s2 * s2 * (4. * t + 1.);
      dw = -10. * s * s2 * inv_r_ * inv_r_;
      ddw = 15. * s2 * inv_r_ * inv_r_ * inv_r_ / (std::max)(d, 1e-3 * radius_);
      return true;
    }
    }
    return false;
  }

private:
  Weight_kind kind_;
  double h_, inv_h2_, radius_, inv_r_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_WEIGHT_FUNCTION_H
