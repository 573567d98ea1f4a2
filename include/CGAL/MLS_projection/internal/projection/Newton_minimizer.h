// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Newton's method, damped as Levenberg-Marquardt, for smooth energies of a few parameters
// whose gradient and Hessian are known in closed form (Levin's phase 1): quadratic convergence
// near a minimum, fixed-size linear algebra, one evaluation per iteration.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEWTON_MINIMIZER_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEWTON_MINIMIZER_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace MLS {
namespace internal {

struct Newton_settings {
  // Stop after a step shorter than this (in the parameters' units), taken without evaluating the
  // energy after it when it is a pure Newton step: the convergence is quadratic, so the error left
  // is about its square.
  double step_tolerance = 1e-6;
  // ... or when an accepted step lowers the energy by less than this fraction.
  double energy_tolerance = 1e-15;
  // ... or when the energy falls below this value (an exact fit).
  double absolute_energy = 0;
  int max_evaluations = 400;
  // Steps longer than this are shortened to it (a trust region): the minimiser moves to the
  // minimum nearest to the start instead of jumping to a distant one.
  double max_step = 0.5;
};

struct Newton_report {
  int iterations = 0;  // accepted steps
  int evaluations = 0; // evaluations of the energy (with its derivatives)
  bool converged = false;
  bool valid = false;  // the start could be evaluated
  double energy = 0;
};

/// Minimises the energy `evaluate(x, E, g, H)` (writes the energy, its gradient and Hessian in
/// the N local parameters at `x`; false where it is not defined) from `x`, moving by
/// `x = retract(x, delta)` (a step `delta` of the local parameters; the parameters are local to
/// each iterate, as an exponential map is). Damping: the Newton system is solved with
/// `H + lambda * s * I` (s the largest diagonal entry of `|H|`), `lambda` raised until the
/// matrix is positive definite and the step lowers the energy, lowered after each success.
template <int N, class State, class Evaluate, class Retract>
Newton_report minimize_newton(State& x, const Evaluate& evaluate, const Retract& retract, const Newton_settings& settings) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  Newton_report report;
  double E = 0;
  Vector g;
  Matrix H;
  report.evaluations = 1;
  if(!evaluate(x, E, g, H) || !std::isfinite(E)) return report;
  report.valid = true;
  report.energy = E;
  double lambda = 0;
  while(report.evaluations < settings.max_evaluations) {
    if(E <= settings.absolute_energy) {
      report.converged = true;
      break;
    }
    const double scale = (std::max)(H.diagonal().cwiseAbs().maxCoeff(), 1e-300);
    Matrix A = H;
    A.diagonal().array() += lambda * scale;
    const Eigen::LDLT<Matrix> ldlt(A);
    if(ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) {
      lambda = (std::max)(8. * lambda, 1e-6);
      if(lambda > 1e12) break;
      continue;
    }
    Vector delta = -ldlt.solve(g);
    if(!delta.allFinite()) break;
    const double length = delta.norm();
    if(length > settings.max_step) delta *= settings.max_step / length;
    if(lambda == 0 && delta.norm() <= settings.step_tolerance) {
      // a Newton step this short leaves an error of about its square: taken without evaluating
      x = retract(x, delta);
      ++report.iterations;
      report.converged = true;
      break;
    }
    State trial = retract(x, delta);
    double Et = 0;
    Vector gt;
    Matrix Ht;
    ++report.evaluations;
    const bool ok = evaluate(trial, Et, gt, Ht) && std::isfinite(Et);
    const bool small = delta.norm() <= settings.step_tolerance;
    // a step within the rounding of the energy counts as a descent when it is short
    if(ok && (Et < E || (small && Et <= E * (1 + 1e-13)))) {
      const double decrease = E - Et;
      x = trial;
      E = Et;
      g = gt;
      H = Ht;
      ++report.iterations;
      lambda = lambda > 1e-9 ? lambda / 4 : 0.;
      if(small || decrease <= settings.energy_tolerance * (E + decrease)) {
        report.converged = true;
        break;
      }
    } else {
      lambda = (std::max)(8. * lambda, 1e-6);
      if(lambda > 1e12) { // no descent direction left at this precision: a minimum
        report.converged = true;
        break;
      }
    }
  }
  report.energy = E;
  return report;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_NEWTON_MINIMIZER_H
