// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Levin's phase-1 energy (equation 1 of the paper) with its gradient and Hessian in closed form,
// for Newton's method (Levin_projection::find_frame()).

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_ENERGY_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_ENERGY_H

#include <CGAL/MLS_projection/Weight_function.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The energy \f$E = \sum_i w_i z_i^2 / \sum_i w_i\f$ of the frame with unit normal `n` and origin
/// \f$r + s\,n\f$, for the points `y` given relative to \f$r\f$, with its gradient `g` and Hessian
/// `H` in the parameters \f$(a, s)\f$, \f$a\f$ the \f$D-1\f$ coordinates of the exponential map at
/// `n` in the basis `tangent_basis(n)` (at \f$a = 0\f$); `weight` is evaluated on squared lengths
/// in the units of `y` and `s`. False when no point has a positive weight.
///
/// With \f$\phi_i = y_i \cdot n\f$ and \f$e_i = (y_i \cdot b_j)_j\f$: \f$z_i = \phi_i - s\f$ (the
/// signed distance to the plane) and \f$D_i = |y_i|^2 - 2s\phi_i + s^2\f$ (the squared distance to
/// the origin, \f$w_i = \omega(D_i)\f$), whose derivatives are \f$\partial z = (e, -1)\f$,
/// \f$\partial^2 z = -\phi\f$ on the block of \f$a\f$, \f$\partial D = M\,\partial z\f$ with
/// \f$M = \mathrm{diag}(-2s, \dots, -2s, 2z)\f$, and \f$\partial^2 D\f$: \f$2s\phi\f$ on the block of
/// \f$a\f$, \f$-2e\f$ between \f$a\f$ and \f$s\f$, 2 for \f$s\f$. Then, with \f$N = \sum w z^2\f$ and
/// \f$W = \sum w\f$, \f$\partial E = (\partial N - E\,\partial W)/W\f$ and
/// \f$\partial^2 E = (\partial^2 N - E\,\partial^2 W - \partial E\,\partial W^T - \partial W\,\partial E^T)/W\f$.
/// The sums are accumulated per point as a few scalars times the products \f$e_j e_k\f$.
template <int D>
bool levin_energy(const std::vector<Vec<D>>& y, const Vec<D>& n, double s, const Weight_function& weight, double& E,
                  Eigen::Matrix<double, D, 1>& g, Eigen::Matrix<double, D, D>& H) {
  constexpr int m = D - 1; // angles
  const auto basis = tangent_basis<D>(n);
  double W = 0, N = 0;
  // HN and HW: the Hessians of N and W; gN and gW: the gradients
  Eigen::Matrix<double, D, D> HN = Eigen::Matrix<double, D, D>::Zero(), HW = HN;
  Eigen::Matrix<double, D, 1> gN = Eigen::Matrix<double, D, 1>::Zero(), gW = gN;
  for(const Vec<D>& yi : y) {
    const double phi = yi.dot(n), z = phi - s;
    double w, dw, ddw;
    if(!weight.evaluate(yi.squaredNorm() - 2. * s * phi + s * s, w, dw, ddw)) continue;
    std::array<double, m> e;
    for(int j = 0; j < m; ++j) e[j] = yi.dot(basis[j]);
    const double A = ddw * z * z, B = dw * z;
    // coefficients of dz_a dz_b in the Hessian of N: z^2 ddw M_a M_b + 2 z dw (M_a + M_b) + 2 w
    const double k_aa = 4. * s * s * A - 8. * s * B + 2. * w;
    const double k_as = -4. * s * z * A + 4. * (z - s) * B + 2. * w;
    const double k_ss = 4. * z * z * A + 8. * z * B + 2. * w;
    const double diag_N = 2. * s * phi * z * B - 2. * phi * z * w; // z^2 dw d2D + 2 w z d2z, block of a
    const double l_aa = 4. * s * s * ddw, l_as = 4. * s * z * ddw - 2. * dw;
    for(int j = 0; j < m; ++j) {
      for(int k = 0; k <= j; ++k) {
        HN(j, k) += k_aa * e[j] * e[k];
        HW(j, k) += l_aa * e[j] * e[k];
      }
      HN(j, j) += diag_N;
      HW(j, j) += 2. * s * phi * dw;
      HN(m, j) -= (k_as + 2. * z * B) * e[j];
      HW(m, j) += l_as * e[j];
      gN[j] += (2. * z * w - 2. * s * z * B) * e[j];
      gW[j] -= 2. * s * dw * e[j];
    }
    HN(m, m) += k_ss + 2. * z * B;
    HW(m, m) += 4. * z * z * ddw + 2. * dw;
    gN[m] -= 2. * z * z * B + 2. * z * w;
    gW[m] -= 2. * z * dw;
    W += w;
    N += w * z * z;
  }
  if(!(W > 0)) return false;
  HN = HN.template selfadjointView<Eigen::Lower>();
  HW = HW.template selfadjointView<Eigen::Lower>();
  E = N / W;
  g = (gN - E * gW) / W;
  H = (HN - E * HW - g * gW.transpose() - gW * g.transpose()) / W;
  return g.allFinite() && H.allFinite();
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_ENERGY_H
