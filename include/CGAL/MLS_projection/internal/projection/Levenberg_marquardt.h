// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The non-linear least-squares optimiser of the closest-point operators: Levenberg-Marquardt on
// N parameters (N fixed at compile time, at most a dozen), fed with the Gauss-Newton system
// J^T J and J^T f of the m residuals f, which the caller accumulates point by point: no m x N
// Jacobian is stored and nothing is factorised but the N x N system. Every MLS energy of the
// paper is a normalised weighted sum of squares, sum_i (w_i / W) r_i^2, minimised as the sum of
// squares of the residuals sqrt(w_i / W) r_i, whose weights depend on the parameters.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVENBERG_MARQUARDT_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVENBERG_MARQUARDT_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace MLS {
namespace internal {

struct Minimizer_settings {
  // Stop when an accepted step lowers the sum of squares by less than this fraction, or is shorter
  // than this fraction of the parameters' norm (plus this value).
  double tolerance = 1e-12;
  // When positive: also stop when the lowest sum of squares seen has improved by less than this
  // fraction over the last `stall_evaluations` evaluations (a minimum at the end of a long,
  // nearly flat valley, where the steps would crawl along it).
  double stall_tolerance = 0;
  int stall_evaluations = 10;
  int max_evaluations = 400;
  // Steps are at most this long (parameter units, after the scaling below): the optimiser moves
  // to the minimum nearest to its start instead of jumping to a distant one.
  double max_step = 1.;
  // Stop as soon as the sum of squares falls below this value (0: never): the tests above are
  // relative, and a zero-residual fit would otherwise spend its budget on rounding noise.
  double absolute_value = 0;
  // When `watched` is set (a quantity the evaluation updates, e.g. the point the caller returns)
  // and `watch_tolerance` is positive: also stop when, over a window of `watch_evaluations`
  // improving evaluations, the watched quantity at the lowest sum of squares moved by less than
  // `watch_tolerance` and that sum fell by less than the fraction `watch_energy_tolerance`: the
  // steps still lower the sum but hardly change the answer.
  const Eigen::VectorXd* watched = nullptr;
  double watch_tolerance = 0;
  double watch_energy_tolerance = 1e-2;
  // ... or by less than this fraction of the root of that sum (the RMS residual when the residuals
  // are sqrt(w_i / W) r_i), when larger: on noisy data, the answer is not known better than the
  // noise allows, and the steps crawl along a flat valley long after it stopped changing.
  double watch_relative = 0;
  int watch_evaluations = 10;
  // The damping of each parameter is its diagonal entry of J^T J (Marquardt's scaling), at least
  // this fraction of the largest: a parameter that hardly moves the residuals would otherwise get
  // huge steps.
  double scaling_floor = 0;
};

template <int N>
struct Minimizer_report {
  Eigen::Matrix<double, N, 1> x;
  double value = 0; // sum of squared residuals at x
  int iterations = 0;  // accepted steps
  int evaluations = 0; // evaluations of the residuals (each with the Gauss-Newton system)
  bool converged = false;
};

/// Minimises the sum of squares computed by `evaluate(x, value, JtJ, Jtf)` (false where the
/// residuals are not defined: such a point is never accepted) from `x0`.
template <int N, class Evaluate>
Minimizer_report<N> levenberg_marquardt(const Evaluate& evaluate, const Eigen::Matrix<double, N, 1>& x0,
                                        const Minimizer_settings& settings) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  Minimizer_report<N> report;
  report.x = x0;
  report.value = std::numeric_limits<double>::infinity();
  double value = 0;
  Matrix JtJ;
  Vector Jtf;
  report.evaluations = 1;
  if(!evaluate(x0, value, JtJ, Jtf) || !std::isfinite(value)) return report;
  report.value = value;

  // the stop rules watching the evaluations (see Minimizer_settings)
  double stall_mark = value;
  int since_stall_mark = 0;
  Eigen::VectorXd watch_mark;
  double watch_mark_value = std::numeric_limits<double>::infinity();
  int since_watch_mark = 0;
  if(settings.watched) watch_mark = *settings.watched;
  watch_mark_value = value;
  // true when the improving evaluation of `v` ends the run
  const auto watch = [&](double v) {
    if(!(settings.watch_tolerance > 0) || !settings.watched || ++since_watch_mark < settings.watch_evaluations) return false;
    const double tolerance = (std::max)(settings.watch_tolerance, settings.watch_relative * std::sqrt(v));
    if(watch_mark.size() == settings.watched->size() && (*settings.watched - watch_mark).norm() < tolerance &&
       v > watch_mark_value * (1. - settings.watch_energy_tolerance))
      return true;
    watch_mark = *settings.watched;
    watch_mark_value = v;
    since_watch_mark = 0;
    return false;
  };

  double lambda = 1e-3, nu = 2;
  while(report.evaluations < settings.max_evaluations) {
    if(report.value <= settings.absolute_value) {
      report.converged = true;
      break;
    }
    Vector scale = JtJ.diagonal().cwiseMax(0.);
    const double largest = scale.maxCoeff();
    if(!(largest > 0)) { // no parameter moves the residuals: a stationary point
      report.converged = true;
      break;
    }
    scale = scale.cwiseMax((std::max)(settings.scaling_floor, 1e-30) * largest);
    Matrix A = JtJ;
    A.diagonal() += lambda * scale;
    Vector delta = -A.ldlt().solve(Jtf);
    if(!delta.allFinite()) break;
    // the step's length in the scaled norm, relative to the parameters' typical curvature
    const double length = std::sqrt(delta.cwiseProduct(scale).dot(delta) / largest);
    if(length > settings.max_step) delta *= settings.max_step / length;
    const Vector trial = report.x + delta;
    double trial_value = 0;
    Matrix trial_JtJ;
    Vector trial_Jtf;
    ++report.evaluations;
    const bool ok = evaluate(trial, trial_value, trial_JtJ, trial_Jtf) && std::isfinite(trial_value);
    const bool improved = ok && trial_value < report.value;
    if(!improved) {
      lambda *= nu;
      nu *= 2;
      if(lambda > 1e16) { // no step lowers the sum of squares: a minimum at this precision
        report.converged = true;
        break;
      }
      if(settings.stall_tolerance > 0 && ++since_stall_mark >= settings.stall_evaluations) {
        report.converged = true;
        break;
      }
      continue;
    }
    // accept, with Nielsen's update of the damping from the ratio of the actual to the predicted decrease
    const double predicted = -delta.dot(2. * Jtf + JtJ * delta);
    const double rho = predicted > 0 ? (report.value - trial_value) / predicted : 0.;
    lambda *= (std::max)(1. / 3., 1. - std::pow(2. * rho - 1., 3));
    lambda = (std::max)(lambda, 1e-12);
    nu = 2;
    const double decrease = report.value - trial_value;
    const double before = report.value;
    report.x = trial;
    report.value = trial_value;
    JtJ = trial_JtJ;
    Jtf = trial_Jtf;
    ++report.iterations;
    if(trial_value <= settings.absolute_value || decrease <= settings.tolerance * before ||
       delta.norm() <= settings.tolerance * (report.x.norm() + settings.tolerance)) {
      report.converged = true;
      break;
    }
    if(settings.stall_tolerance > 0) {
      if(trial_value < stall_mark * (1. - settings.stall_tolerance)) {
        stall_mark = trial_value;
        since_stall_mark = 0;
      } else if(++since_stall_mark >= settings.stall_evaluations) {
        report.converged = true;
        break;
      }
    }
    if(watch(trial_value)) {
      report.converged = true;
      break;
    }
  }
  return report;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVENBERG_MARQUARDT_H
