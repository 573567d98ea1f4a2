// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The non-linear optimiser shared by all operators: Eigen's port of MINPACK's
// Levenberg-Marquardt (unsupported/Eigen/NonLinearOptimization), a trust-region method,
// with the caller's Jacobian when it has one, else a forward-difference one. Every MLS
// energy of the paper is a normalised weighted sum of squares, sum_i (w_i / W) r_i^2, so it
// is minimised as the sum of squares of the residuals sqrt(w_i / W) r_i, whose weights
// depend on the parameters.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H
#define CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace MLS {
namespace internal {

struct Minimizer_settings {
  double tolerance = 1e-12; // relative, on the parameters (MINPACK's xtol) and on the sum of squares (ftol)
  // When positive: also stop when the lowest sum of squares seen has improved by less than this
  // fraction over the last `stall_evaluations` evaluations (a minimum at the end of a long,
  // nearly flat valley, where MINPACK's tests would let the steps crawl along it).
  double stall_tolerance = 0;
  int stall_evaluations = 10;
  int max_evaluations = 400;
  double initial_step = 1.; // bound on the first step, in parameter units
  // Stop as soon as the sum of squares falls below this value (0: never): MINPACK's tests
  // are relative, and a zero-residual fit would otherwise spend its budget on rounding noise.
  double absolute_value = 0;
  // When `watched` is set (a quantity the residual function updates at every evaluation, e.g.
  // the point the caller returns) and `watch_tolerance` is positive: also stop when, over a
  // window of `watch_evaluations` improving evaluations (rejected trial steps do not count), the
  // watched quantity at the lowest sum of squares moved by less than `watch_tolerance` and that
  // sum fell by less than the fraction `watch_energy_tolerance`: the steps still lower the sum
  // but hardly change the answer.
  const Eigen::VectorXd* watched = nullptr;
  double watch_tolerance = 0;
  double watch_energy_tolerance = 1e-2;
  // ... or by less than this fraction of the root of that sum (the RMS residual when the residuals
  // are sqrt(w_i / W) r_i), when larger: on noisy data, the answer is not known better than the
  // noise allows, and the steps crawl along a flat valley long after it stopped changing.
  double watch_relative = 0;
  int watch_evaluations = 10;
  // With an analytic Jacobian: the scale of each parameter (MINPACK's `diag`: the largest norm
  // of its Jacobian column so far) is at least this fraction of the largest column norm.
  double scaling_floor = 0;
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
  // A negative return asks the optimiser to stop; `solution` then holds the best point.
  int operator()(const InputType& x, ValueType& r) const {
    (*f_)(x, r);
    const double value = r.squaredNorm();
    const bool improved = value < best_;
    if(improved) {
      best_ = value;
      solution = x;
      if(settings.watched) best_watched_ = *settings.watched;
      if(value < settings.absolute_value) return -1;
    }
    if(improved && settings.watch_tolerance > 0 && settings.watched && ++since_watch_mark_ >= settings.watch_evaluations) {
      if(watch_mark_.size() == best_watched_.size() && (best_watched_ - watch_mark_).norm() < watch_tolerance() &&
         best_ > watch_mark_value_ * (1. - settings.watch_energy_tolerance))
        return -1;
      watch_mark_ = best_watched_;
      watch_mark_value_ = best_;
      since_watch_mark_ = 0;
    }
    const double stall = settings.stall_tolerance;
    if(improved && value < mark_ * (1. - stall)) { // a real improvement: restart the window
      mark_ = value;
      since_mark_ = 0;
    } else if(stall > 0 && ++since_mark_ >= settings.stall_evaluations) {
      return -1;
    }
    return 0;
  }

  // The lowest sum of squares so far, at `solution`.
  double best() const { return best_; }

  // The watched quantity's tolerance at the lowest sum of squares so far.
  double watch_tolerance() const {
    return (std::max)(settings.watch_tolerance, settings.watch_relative * std::sqrt(best_));
  }

  const ResidualFunction* f_;
  int n_, m_;
  Minimizer_settings settings;
  mutable Eigen::VectorXd solution;
  mutable double best_ = std::numeric_limits<double>::infinity(), mark_ = std::numeric_limits<double>::infinity();
  mutable int since_mark_ = 0;
  mutable Eigen::VectorXd best_watched_, watch_mark_;
  mutable double watch_mark_value_ = std::numeric_limits<double>::infinity();
  mutable int since_watch_mark_ = 0;
};

// Adds the analytic Jacobian `jacobian(x, J)` (m x n) to a residual functor.
template <class ResidualFunction, class JacobianFunction>
struct Residual_jacobian_functor : Residual_functor<ResidualFunction> {
  Residual_jacobian_functor(const ResidualFunction* f, const JacobianFunction* j, int inputs, int values)
    : Residual_functor<ResidualFunction>(f, inputs, values), j_(j) {}
  int df(const typename Residual_functor<ResidualFunction>::InputType& x,
         typename Residual_functor<ResidualFunction>::JacobianType& J) const {
    (*j_)(x, J);
    if(diag) {
      // MINPACK's scaling (mode 1), with the floor
      const Eigen::VectorXd norms = J.colwise().norm().transpose();
      const double floor = (std::max)(this->settings.scaling_floor * norms.maxCoeff(), 1e-300);
      for(Eigen::Index j = 0; j < norms.size(); ++j) {
        const double d = (std::max)(norms[j], floor);
        (*diag)[j] = first_df ? d : (std::max)((*diag)[j], d);
      }
      first_df = false;
    }
    return 0;
  }
  const JacobianFunction* j_;
  Eigen::VectorXd* diag = nullptr; // when set, MINPACK's external scaling, updated here
  mutable bool first_df = true;
};

// The problem of the m residuals presented to the optimiser as n + 1 residuals (n: the
// parameters; used for m > 2n + 1). MINPACK factorises its Jacobian at every iteration (a QR with
// column pivoting), which for the m x n Jacobians of the closest-point operators took about 40% of
// their time (user manual, "Linear algebra of an iteration"). The residuals handed to it are
// (|f|, 0, ..., 0), of the norm of the m residuals f; at each Jacobian, the m x n matrix J is
// replaced by R, the Cholesky factor of J^T J = R^T R (a QR of J when J^T J is not numerically
// positive definite), and the optimiser's residual vector by (z, e), z = R^-T J^T f and
// e^2 = |f|^2 - |z|^2. The linear least-squares problems min |J p + f| and min |R p + (z, e)|
// have the same solutions and residual norms, so the optimiser takes the same steps, up to
// rounding; the stop rules of Residual_functor see the m residuals.
template <class ResidualFunction, class JacobianFunction>
struct Normal_equations_functor : Residual_jacobian_functor<ResidualFunction, JacobianFunction> {
  using Base = Residual_jacobian_functor<ResidualFunction, JacobianFunction>;
  using typename Base::InputType;
  using typename Base::ValueType;
  using typename Base::JacobianType;

  Normal_equations_functor(const ResidualFunction* f, const JacobianFunction* j, int inputs, int values)
    : Base(f, j, inputs, inputs + 1), full_m_(values) {}

  int operator()(const InputType& x, ValueType& r) const {
    full_f_.resize(full_m_);
    const int status = Base::operator()(x, full_f_);
    f_at_ = x;
    r.setZero(this->n_ + 1);
    r[0] = full_f_.stableNorm();
    return status;
  }

  int df(const InputType& x, JacobianType& J) const {
    const Eigen::Index n = this->n_;
    if(f_at_.size() != x.size() || f_at_ != x) {
      full_f_.resize(full_m_);
      (*this->f_)(x, full_f_);
      f_at_ = x;
    }
    full_J_.resize(full_m_, n);
    Base::df(x, full_J_);
    G_.setZero(n, n);
    G_.template selfadjointView<Eigen::Lower>().rankUpdate(full_J_.transpose());
    Eigen::LLT<Eigen::MatrixXd> llt(G_);
    J.setZero(n + 1, n);
    Eigen::VectorXd z;
    if(llt.info() == Eigen::Success && llt.matrixLLT().diagonal().minCoeff() > 0) {
      J.topRows(n) = llt.matrixU();
      z = llt.matrixL().solve(full_J_.transpose() * full_f_);
    } else {
      Eigen::HouseholderQR<Eigen::MatrixXd> qr(full_J_);
      J.topRows(n) = qr.matrixQR().topRows(n).template triangularView<Eigen::Upper>();
      Eigen::VectorXd qtf = full_f_;
      qtf.applyOnTheLeft(qr.householderQ().adjoint());
      z = qtf.head(n);
    }
    const double f2 = full_f_.squaredNorm();
    fvec->head(n) = z;
    (*fvec)[n] = std::sqrt((std::max)(0., f2 - z.squaredNorm()));
    return 0;
  }

  int full_m_;
  Eigen::VectorXd* fvec = nullptr; // the optimiser's residual vector, replaced at each Jacobian
  mutable Eigen::VectorXd full_f_, f_at_;
  mutable Eigen::MatrixXd full_J_, G_;
};

template <class F, class = void> struct has_fvec : std::false_type {};
template <class F> struct has_fvec<F, std::void_t<decltype(std::declval<F&>().fvec)>> : std::true_type {};

template <class F, class = void> struct has_scaling : std::false_type {};
template <class F> struct has_scaling<F, std::void_t<decltype(std::declval<F&>().diag)>> : std::true_type {};

template <class Functor, class ResidualFunction>
Minimizer_report run_levenberg_marquardt(Functor& functor, const ResidualFunction& residuals, int m,
                                         const Eigen::VectorXd& x0, const Minimizer_settings& settings) {
  functor.settings = settings;
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  if constexpr(has_scaling<Functor>::value) {
    if(settings.scaling_floor > 0) {
      lm.useExternalScaling = true;
      lm.diag = Eigen::VectorXd::Ones(x0.size()); // replaced at the first Jacobian
      functor.diag = &lm.diag;
    }
  }
  if constexpr(has_fvec<Functor>::value) functor.fvec = &lm.fvec;
  lm.parameters.ftol = settings.tolerance;
  lm.parameters.xtol = settings.tolerance;
  lm.parameters.maxfev = settings.max_evaluations;
  lm.parameters.factor = settings.initial_step;

  Minimizer_report report;
  report.x = x0;
  const Eigen::LevenbergMarquardtSpace::Status status = lm.minimize(report.x);
  report.iterations = int(lm.iter);
  report.evaluations = int(lm.nfev);
  const bool stopped = status == Eigen::LevenbergMarquardtSpace::UserAsked && functor.solution.size() == x0.size();
  if(stopped) report.x = functor.solution;
  report.converged = stopped || (status != Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation &&
                                      status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters &&
                                      status != Eigen::LevenbergMarquardtSpace::UserAsked);
  // The sum of squares at x, without evaluating it again: the functor's lowest when it stopped
  // the optimiser, else that of the optimiser's residuals, which are x's (MINPACK keeps a trial
  // point's residuals only when it takes the point), unless it rejected its input before any.
  bool evaluate = status == Eigen::LevenbergMarquardtSpace::ImproperInputParameters;
  if(stopped) report.value = functor.best();
  else if(!evaluate) report.value = lm.fvec.squaredNorm();
  if(!report.x.allFinite()) {
    report.x = x0;
    report.converged = false;
    evaluate = true;
  }
  if(evaluate) {
    Eigen::VectorXd r(m);
    residuals(report.x, r);
    report.value = r.squaredNorm();
  }
  return report;
}

/// Minimises the sum of squares of the `m` residuals computed by `residuals(x, r)`
/// from the start `x0`, with a forward-difference Jacobian. `m` must be at least the number
/// of parameters.
template <class ResidualFunction>
Minimizer_report minimize_sum_of_squares(const ResidualFunction& residuals, int m, const Eigen::VectorXd& x0,
                                         const Minimizer_settings& settings) {
  using Functor = Eigen::NumericalDiff<Residual_functor<ResidualFunction>>;
  Functor functor(Residual_functor<ResidualFunction>(&residuals, int(x0.size()), m));
  return run_levenberg_marquardt(functor, residuals, m, x0, settings);
}

/// The same with the Jacobian computed by `jacobian(x, J)` (an m x n matrix); the optimiser
/// sees n + 1 residuals when m > 2n + 1 (see `Normal_equations_functor`).
template <class ResidualFunction, class JacobianFunction>
Minimizer_report minimize_sum_of_squares(const ResidualFunction& residuals, const JacobianFunction& jacobian, int m,
                                         const Eigen::VectorXd& x0, const Minimizer_settings& settings) {
  if(m > 2 * x0.size() + 1) {
    Normal_equations_functor<ResidualFunction, JacobianFunction> functor(&residuals, &jacobian, int(x0.size()), m);
    return run_levenberg_marquardt(functor, residuals, m, x0, settings);
  }
  Residual_jacobian_functor<ResidualFunction, JacobianFunction> functor(&residuals, &jacobian, int(x0.size()), m);
  return run_levenberg_marquardt(functor, residuals, m, x0, settings);
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_LEAST_SQUARES_MINIMIZER_H
