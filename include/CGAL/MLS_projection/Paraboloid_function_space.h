// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PARABOLOID_FUNCTION_SPACE_H
#define CGAL_MLS_PROJECTION_PARABOLOID_FUNCTION_SPACE_H

#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace MLS {
namespace internal {

/// The real roots of the depressed cubic \f$t^3 + pt + q = 0\f$ in closed form (one, or three
/// when the discriminant allows), written in `t`; returns their number. The hyperbolic and
/// trigonometric forms are used instead of Cardano's radicals: they involve no cancellation
/// (in particular for \f$|p| \gg |q|\f$) and no cube of `p`, so they do not overflow.
inline int depressed_cubic_real_roots(double p, double q, double t[3]) {
  if(p == 0.) {
    t[0] = std::cbrt(-q);
    return 1;
  }
  if(p > 0.) {
    t[0] = -2. * std::sqrt(p / 3.) * std::sinh(std::asinh(1.5 * q / p * std::sqrt(3. / p)) / 3.);
    return 1;
  }
  const double m = std::sqrt(-p / 3.);
  const double arg = 1.5 * q / p * std::sqrt(-3. / p); // cos(3 phi) in the trigonometric form
  if(std::abs(arg) <= 1. + 1e-12) {                    // three real roots (two may coincide)
    const double phi = std::acos(std::clamp(arg, -1., 1.)) / 3.;
    for(int k = 0; k < 3; ++k) t[k] = 2. * m * std::cos(phi - 2. * CGAL_PI * k / 3.);
    return 3;
  }
  t[0] = (q > 0 ? -2. : 2.) * m * std::cosh(std::acosh(std::abs(arg)) / 3.);
  return 1;
}

/// The stationary points of the squared distance from \f$(a, b)\f$ to the parabola
/// \f$z = k x^2\f$, i.e. the real roots of \f$2k^2x^3 + (1 - 2kb)x - a = 0\f$, each polished with
/// Newton steps; writes their abscissas to `x` and returns their number (1 to 3). The problem
/// is first scaled to \f$\max(|a|,|b|) = 1\f$, so that any magnitude of `k`, `a`, `b` is handled.
inline int parabola_stationary_points(double k, double a, double b, double x[3]) {
  const double L = std::max(std::abs(a), std::abs(b));
  if(k == 0. || L == 0. || !(L < HUGE_VAL)) { // the line, or the query at the vertex
    x[0] = (k == 0.) ? a : 0.;
    return 1;
  }
  const double K = k * L, A = a / L, B = b / L;
  const double c3 = 2. * K * K, c1 = 1. - 2. * K * B, c0 = -A;
  int n = 0;
  const double p = c1 / c3, q = c0 / c3;
  if(c3 > 0. && std::isfinite(p) && std::isfinite(q)) {
    n = depressed_cubic_real_roots(p, q, x);
  } else { // k = 0 or so small that the cubic term underflows: the linear equation.
    x[0] = (c1 != 0.) ? A / c1 : A;
    n = 1;
  }
  for(int i = 0; i < n; ++i) {
    double X = x[i];
    double g = (c3 * X * X + c1) * X + c0;
    for(int it = 0; it < 3 && g != 0.; ++it) {
      const double dg = 3. * c3 * X * X + c1;
      if(dg == 0.) break;
      const double Xn = X - g / dg;
      const double gn = (c3 * Xn * Xn + c1) * Xn + c0;
      if(!(std::abs(gn) < std::abs(g))) break;
      X = Xn;
      g = gn;
    }
    x[i] = X * L;
  }
  return n;
}

} // namespace internal

/// \ingroup PkgMLSProjectionFunctionSpaces
/// The paraboloids with their vertex at the frame's origin and their axis along its normal (in
/// 2D, parabolas): the quadratic function space of section 4.2 of the paper, in which the
/// closest-point projection is computed exactly (the space of the unified projection with smooth
/// priors). Not to be confused with `Polynomial_function_space`, all polynomials of total degree
/// at most 2, the graph space of Levin's projection.
///
/// - In 2D, \f$f(x) = k x^2\f$, one parameter \f$k\f$. The closest point of \f$(a, b)\f$ is a
///   real root of the cubic \f$2k^2x^3 + (1 - 2kb)x - a = 0\f$, solved in closed form
///   (trigonometric / hyperbolic form of the depressed cubic) and polished by Newton steps.
/// - In 3D, \f$f(x, y) = a x'^2 + b y'^2\f$ with \f$x' = x\cos\theta + y\sin\theta\f$ and
///   \f$y' = -x\sin\theta + y\cos\theta\f$: parameters \f$(a, b, \theta)\f$, the principal
///   curvatures (halved) and the angle of the first principal direction
///   \f$(\cos\theta, \sin\theta)\f$. The angle is the extra rotation parameter of the paper,
///   which makes the space closed under rotations of the frame about its normal. The closest
///   point is the unique root, in the interval where the Hessian of the Lagrangian is positive
///   semi-definite, of a monotone secular equation (equivalent to the paper's quintic, of which
///   it selects the right root), found by safeguarded Newton steps and polished in \f$(x, y)\f$.
///
/// Terms of degree at most 1 are left out: the unified operator moves the frame, which
/// generates them.
///
/// \cgalModels `MLSFunctionSpace`
/// \tparam D the ambient dimension, 2 or 3
template <int D>
class Paraboloid_function_space {
  static_assert(D == 2 || D == 3, "Paraboloid_function_space: D must be 2 or 3");

public:
  /// As described by the concept `MLSFunctionSpace`: the ambient dimension, the number of
  /// parameters of a member, their vector, and a point of the frame's tangent hyperplane.
  /// @{
  static constexpr int ambient_dimension = D;
  static constexpr int number_of_parameters = (D == 2) ? 1 : 3;
  using Parameters = Eigen::Matrix<double, number_of_parameters, 1>;
  using Vector = Eigen::Matrix<double, D, 1>; ///< a point or vector in frame coordinates
  using Domain_point = Eigen::Matrix<double, D - 1, 1>;
  /// @}

  /// The name of the space, `"paraboloid"`.
  static const char* name() { return "paraboloid"; }
  /// The number of parameters of the member plus those of the frame (\f$D\f$).
  static constexpr std::size_t minimum_number_of_points() { return number_of_parameters + D; }

  /// The member \f$f = 0\f$ (\f$\theta = 0\f$ in 3D).
  Parameters identity() const { return Parameters::Zero(); }

  /// The initial member: the quadratic part of the weighted least-squares fit by a full
  /// quadratic polynomial (`Polynomial_function_space<D>`); the lower-order terms are dropped
  /// since the operator also optimises the frame. In 3D, \f$(a, b, \theta)\f$ come from the
  /// eigen-decomposition of the Hessian \f$[[c_3, c_4/2], [c_4/2, c_5]]\f$.
  Parameters fit(const Vector* p, const double* w, std::size_t n) const {
    const auto c = Polynomial_function_space<D>().fit(p, w, n);
    Parameters r;
    if constexpr(D == 2) {
      r[0] = c[2];
    } else {
      const double h00 = c[3], h01 = 0.5 * c[4], h11 = c[5];
      const double theta = 0.5 * std::atan2(2. * h01, h00 - h11);
      const double ct = std::cos(theta), st = std::sin(theta);
      r[0] = h00 * ct * ct + 2. * h01 * ct * st + h11 * st * st;
      r[1] = h00 * st * st - 2. * h01 * ct * st + h11 * ct * ct;
      r[2] = theta;
    }
    if(!r.allFinite()) r.setZero();
    return r;
  }

  /// \f$f(u)\f$ (not required by the concept).
  double height(const Parameters& c, const Domain_point& u) const {
    if constexpr(D == 2) {
      return c[0] * u[0] * u[0];
    } else {
      const double ct = std::cos(c[2]), st = std::sin(c[2]);
      const double xr = ct * u[0] + st * u[1], yr = -st * u[0] + ct * u[1];
      return c[0] * xr * xr + c[1] * yr * yr;
    }
  }

  /// The largest curvature \f$2|k|\f$ (2D) or \f$2\max(|a|, |b|)\f$ (3D) of a plausible member, in
  /// units of \f$1/h\f$: 8 by default, a radius of curvature of at least \f$h/8\f$. Sharper
  /// members (needle-like parabolas threading noisy samples) are penalised by `regularization()`.
  double maximum_curvature = 8.;

  /// A dimensionless penalty, zero for members whose curvature is at most
  /// `maximum_curvature / h`, growing linearly beyond (added to the energy by the operators):
  /// the norm of the excesses of the principal curvatures (a smooth function of both).
  double regularization(const Parameters& c, double h) const {
    const double ea = (std::max)(0., 2. * std::abs(c[0]) * h - maximum_curvature);
    if constexpr(D == 2) return ea;
    const double eb = (std::max)(0., 2. * std::abs(c[1]) * h - maximum_curvature);
    return std::sqrt(ea * ea + eb * eb);
  }

  /// The point \f$(u, f(u))\f$ of the graph above or below `x = (u, z)`, with its normal
  /// (for `Single_phase_projection`).
  Closest_point<D> vertical_projection(const Parameters& c, const Vector& x) const {
    Closest_point<D> cp;
    const Domain_point u = x.template head<D - 1>();
    cp.point << u, height(c, u);
    Vector g;
    if constexpr(D == 2) {
      g << -2. * c[0] * u[0], 1.;
    } else {
      const double ct = std::cos(c[2]), st = std::sin(c[2]);
      const double xr = ct * u[0] + st * u[1], yr = -st * u[0] + ct * u[1];
      const double gx = 2. * c[0] * xr, gy = 2. * c[1] * yr; // gradient in the rotated axes
      g << -(ct * gx - st * gy), -(st * gx + ct * gy), 1.;
    }
    cp.normal = g.normalized();
    internal::set_signed_distance(cp, x);
    return cp;
  }

  /// The closest point of `x` (frame coordinates) on the graph of the member `c`.
  Closest_point<D> closest_point(const Parameters& c, const Vector& x) const {
    if constexpr(D == 2) return closest_point_2(c[0], x);
    else return closest_point_3(c[0], c[1], c[2], x);
  }

  /// The closest points of the `n` points `x` on the member `c` and, when `gradients` is not
  /// null, the derivatives of their signed distances with respect to \f$c\f$: by the envelope
  /// theorem, \f$-g \cdot \partial S/\partial c\f$ at the closest point \f$S\f$, with
  /// \f$g = (x - S)/d\f$ (the normal when \f$d = 0\f$).
  void closest_points(const Parameters& c, const Vector* x, std::size_t n, Closest_point<D>* out,
                      Parameters* gradients) const {
    const double theta = D == 3 ? c[D == 3 ? 2 : 0] : 0.; // the angle of the principal axes (3D)
    const double ct = std::cos(theta), st = std::sin(theta);
    for(std::size_t i = 0; i < n; ++i) {
      out[i] = closest_point(c, x[i]);
      if(!gradients) continue;
      const Closest_point<D>& cp = out[i];
      Vector g = cp.normal;
      if(std::abs(cp.signed_distance) > 0.) g = (x[i] - cp.point) / cp.signed_distance;
      const Vector& S = cp.point;
      if constexpr(D == 2) {
        gradients[i][0] = -g[1] * S[0] * S[0];
      } else {
        const double xr = ct * S[0] + st * S[1], yr = -st * S[0] + ct * S[1];
        gradients[i][0] = -g[2] * xr * xr;
        gradients[i][1] = -g[2] * yr * yr;
        gradients[i][2] = -(g[1] * S[0] - g[0] * S[1]); // the surface turns about e_3
      }
    }
  }

private:
  static Closest_point<2> closest_point_2(double k, const internal::Vec<2>& x) {
    double roots[3];
    const int n = internal::parabola_stationary_points(k, x[0], x[1], roots);
    double best = HUGE_VAL, bx = x[0];
    for(int i = 0; i < n; ++i) {
      const double u = roots[i], dz = k * u * u - x[1], e = (u - x[0]) * (u - x[0]) + dz * dz;
      if(e < best) {
        best = e;
        bx = u;
      }
    }
    if(!std::isfinite(best)) bx = x[0]; // never reached for finite input; keeps the output finite
    Closest_point<2> cp;
    cp.point = internal::Vec<2>(bx, k * bx * bx);
    cp.normal = internal::Vec<2>(-2. * k * bx, 1.).normalized();
    internal::set_signed_distance(cp, x);
    return cp;
  }

  // Squared distance, in scaled coordinates, from (P, Q, R) to (X, Y, A X^2 + B Y^2).
  static double energy(double A, double B, double P, double Q, double R, double X, double Y) {
    const double S = A * X * X + B * Y * Y - R;
    return (X - P) * (X - P) + (Y - Q) * (Y - Q) + S * S;
  }

  static void gradient(double A, double B, double P, double Q, double R, double X, double Y, double& g0, double& g1) {
    const double S = A * X * X + B * Y * Y - R;
    g0 = (X - P) + 2. * A * X * S;
    g1 = (Y - Q) + 2. * B * Y * S;
  }

  // Newton's method on the unconstrained problem min_(X,Y) energy, with step halving so that
  // the energy never increases; stops at a point where the Hessian is not positive definite.
  // Close to the minimum, where energy differences drown in rounding (a very sharp ridge), a
  // step is also accepted when it reduces the gradient without raising the energy noticeably.
  static double polish(double A, double B, double P, double Q, double R, double& X, double& Y) {
    double E = energy(A, B, P, Q, R, X, Y);
    for(int it = 0; it < 8; ++it) {
      const double S = A * X * X + B * Y * Y - R;
      double g0, g1;
      gradient(A, B, P, Q, R, X, Y, g0, g1);
      const double h00 = 1. + 2. * A * S + 4. * A * A * X * X, h11 = 1. + 2. * B * S + 4. * B * B * Y * Y;
      const double h01 = 4. * A * B * X * Y;
      const double det = h00 * h11 - h01 * h01;
      if(!(h00 > 0. && det > 0.)) break;
      double dX = -(h11 * g0 - h01 * g1) / det, dY = -(h00 * g1 - h01 * g0) / det;
      if(!(std::abs(dX) + std::abs(dY) > 1e-17 * (1. + std::abs(X) + std::abs(Y)))) break;
      const bool small = std::abs(dX) + std::abs(dY) < 1e-6 * (1. + std::abs(X) + std::abs(Y));
      bool improved = false;
      for(int h = 0; h < 4; ++h, dX *= 0.5, dY *= 0.5) {
        const double En = energy(A, B, P, Q, R, X + dX, Y + dY);
        bool accept = En <= E;
        if(!accept && small && En <= E * (1. + 1e-12) + 1e-300) {
          double n0, n1;
          gradient(A, B, P, Q, R, X + dX, Y + dY, n0, n1);
          accept = n0 * n0 + n1 * n1 < g0 * g0 + g1 * g1;
        }
        if(accept) {
          X += dX;
          Y += dY;
          E = En;
          improved = true;
          break;
        }
      }
      if(!improved) break;
    }
    return E;
  }

  static Closest_point<3> closest_point_3(double a, double b, double theta, const internal::Vec<3>& x) {
    const double ct = std::cos(theta), st = std::sin(theta);
    const double p = ct * x[0] + st * x[1], q = -st * x[0] + ct * x[1], r = x[2];
    // Scale to max(|p|, |q|, |r|) = 1: the polynomial coefficients are then of moderate size
    // whatever the units, and all thresholds below are relative.
    const double L = std::max({std::abs(p), std::abs(q), std::abs(r)});
    Closest_point<3> cp;
    if(L == 0. || !(L < HUGE_VAL)) { // x is the origin, which lies on every member
      cp.point = internal::Vec<3>::Zero();
      cp.normal = internal::Vec<3>::UnitZ();
      return cp;
    }
    const double A = a * L, B = b * L, P = p / L, Q = q / L, R = r / L;

    // Candidates (X, Y): the vertical projection, the root of the secular equation, the ends.
    constexpr int max_candidates = 4;
    double cx[max_candidates], cy[max_candidates];
    int nc = 0;
    auto add = [&](double X, double Y) {
      if(nc < max_candidates && std::isfinite(X) && std::isfinite(Y)) {
        cx[nc] = X;
        cy[nc] = Y;
        ++nc;
      }
    };
    add(P, Q); // the vertical projection, always a valid start
    // The global minimum (the distance to a quadric; Moré 1993, no duality gap for one
    // quadratic constraint): with s = f - R, stationarity gives X = P / (1 + 2As),
    // Y = Q / (1 + 2Bs), and the closest point is the root of
    //   g(s) = A X(s)^2 + B Y(s)^2 - R - s
    // in the interval I where 1 + 2As > 0 and 1 + 2Bs > 0 (the multipliers for which the
    // Hessian of the Lagrangian is positive semi-definite). On I, g is strictly decreasing, so
    // the root is unique and found by Newton's method safeguarded by bisection. When P (or Q)
    // vanishes, g may stay negative on I: the minimum is then at the end of I, on the circle
    // (ellipse) of points equidistant from the query (a query near the axis of a paraboloid,
    // beyond its centre of curvature), from the constraint s + R = A X^2 + B Y^2.
    // (The paper finds all roots of the equivalent quintic from its companion matrix; this
    // root is the one it selects, at a fraction of the cost.)
    {
      const double M = std::abs(A) + std::abs(B) + 2.; // |s| <= |x - vertical projection|
      double lo = -M, hi = M;
      double lo_end = -HUGE_VAL, hi_end = HUGE_VAL; // the ends of I
      if(A > 0) lo_end = std::max(lo_end, -0.5 / A);
      if(B > 0) lo_end = std::max(lo_end, -0.5 / B);
      if(A < 0) hi_end = std::min(hi_end, -0.5 / A);
      if(B < 0) hi_end = std::min(hi_end, -0.5 / B);
      lo = std::max(lo, lo_end);
      hi = std::min(hi, hi_end);
      const auto g = [&](double s, double& dg) {
        const double d1 = 1. + 2. * A * s, d2 = 1. + 2. * B * s;
        const double X = P / d1, Y = Q / d2;
        dg = -4. * A * A * X * X / d1 - 4. * B * B * Y * Y / d2 - 1.;
        return A * X * X + B * Y * Y - R - s;
      };
      double dg;
      double s = 0.;
      double gs = g(s, dg);
      if(gs < 0) hi = s;
      else lo = s;
      for(int it = 0; it < 100 && hi - lo > 1e-16 * (1. + std::abs(s)); ++it) {
        double sn = s - gs / dg;
        if(!(sn > lo && sn < hi)) sn = 0.5 * (lo + hi); // Newton left the bracket: bisect
        s = sn;
        gs = g(s, dg);
        if(gs == 0.) break;
        if(gs < 0) hi = s;
        else lo = s;
        if(!std::isfinite(gs)) break;
      }
      const double d1 = 1. + 2. * A * s, d2 = 1. + 2. * B * s;
      if(d1 > 0. && d2 > 0.) add(P / d1, Q / d2);
      // The ends of I, for the degenerate case (P or Q (nearly) zero).
      for(const double e : {lo_end, hi_end}) {
        if(!std::isfinite(e)) continue;
        const bool on_a = (A != 0.) && (e == -0.5 / A);
        const double da = 1. + 2. * A * e, db = 1. + 2. * B * e;
        if(on_a) {
          const double Y = (db != 0.) ? Q / db : 0.;
          const double Xc = std::sqrt(std::max(0., (e + R - B * Y * Y) / A));
          add(P < 0 ? -Xc : Xc, Y);
        } else {
          const double X = (da != 0.) ? P / da : 0.;
          const double Yc = std::sqrt(std::max(0., (e + R - A * X * X) / B));
          add(X, Q < 0 ? -Yc : Yc);
        }
      }
    }
    // Polish the two best candidates, keep the better.
    int i0 = -1, i1 = -1;
    double e0 = HUGE_VAL, e1 = HUGE_VAL;
    for(int i = 0; i < nc; ++i) {
      const double e = energy(A, B, P, Q, R, cx[i], cy[i]);
      if(e < e0) {
        i1 = i0; e1 = e0;
        i0 = i; e0 = e;
      } else if(e < e1) {
        i1 = i; e1 = e;
      }
    }
    double X = cx[i0], Y = cy[i0];
    e0 = polish(A, B, P, Q, R, X, Y);
    if(i1 >= 0) {
      double X1 = cx[i1], Y1 = cy[i1];
      if(polish(A, B, P, Q, R, X1, Y1) < e0) {
        X = X1;
        Y = Y1;
      }
    }
    const double xr = X * L, yr = Y * L;
    const double gx = 2. * A * X, gy = 2. * B * Y; // gradient of f in the rotated frame
    cp.point = internal::Vec<3>(ct * xr - st * yr, st * xr + ct * yr, (A * X * X + B * Y * Y) * L);
    cp.normal = internal::Vec<3>(-(ct * gx - st * gy), -(st * gx + ct * gy), 1.).normalized();
    internal::set_signed_distance(cp, x);
    return cp;
  }
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PARABOLOID_FUNCTION_SPACE_H
