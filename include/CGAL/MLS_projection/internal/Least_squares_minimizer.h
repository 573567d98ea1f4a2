// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The non-linear optimiser shared by all operators: Eigen's port of MINPACK's
// Levenberg-Marquardt (unsupported/Eigen/NonLinearOptimization), a trust-region method,
// with a forward-difference Jacobian. Every MLS energy of the paper is a normalised
// weighted sum of squares, sum_i (w_i / W) r_i^2, so it is minimised as the sum of
// squares of the residuals sqrt(w_i / W) r_i, whose weights depend on the parameters.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H
#define CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <utility>

namespace CGAL {
namespace MLS {
namespace internal {

struct Minimizer_settings {
  double tolerance = 1e-12;
  int max_evaluations = 400;
  double initial_step = 1.; // bound on the first step, in parameter units
};

struct Minimizer_report {
  Eigen::VectorXd x;
  double value = 0;  // sum of squared residuals at x
  int iterations = 0;
  int evaluations = 0;
  bool converged = false;
};

// Adapts a callable `residuals(x, r)` to the functor interface of Eigen's optimisers.
template <class ResidualFunction>
struct Residual_functor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  Residual_functor(const ResidualFunction* f, int inputs, int values) : f_(f), n_(inputs), m_(values) {}
  int inputs() const { return n_; }
  int values() const { return m_; }
  int operator()(const InputType& x, ValueType& r) const {
    (*f_)(x, r);
    return 0;
  }

  const ResidualFunction* f_;
  int n_, m_;
};

/// Minimises the sum of squares of the `m` residuals computed by `residuals(x, r)`
/// from the start `x0`. `m` must be at least the number of parameters.
template <class ResidualFunction>
Minimizer_report minimize_sum_of_squares(const ResidualFunction& residuals, int m, const Eigen::VectorXd& x0,
                                         const Minimizer_settings& settings) {
  using Functor = Eigen::NumericalDiff<Residual_functor<ResidualFunction>>;
  Functor functor(Residual_functor<ResidualFunction>(&residuals, int(x0.size()), m));
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  lm.parameters.ftol = settings.tolerance;
  lm.parameters.xtol = settings.tolerance;
  lm.parameters.maxfev = settings.max_evaluations;
  lm.parameters.factor = settings.initial_step;

  Minimizer_report report;
  report.x = x0;
  const Eigen::LevenbergMarquardtSpace::Status status = lm.minimize(report.x);
  report.iterations = int(lm.iter);
  report.evaluations = int(lm.nfev);
  report.converged = status != Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation &&
                     status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters &&
                     status != Eigen::LevenbergMarquardtSpace::UserAsked;
  Eigen::VectorXd r(m);
  residuals(report.x, r);
  report.value = r.squaredNorm();
  if(!report.x.allFinite()) {
    report.x = x0;
    report.converged = false;
    residuals(report.x, r);
    report.value = r.squaredNorm();
  }
  return report;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H
