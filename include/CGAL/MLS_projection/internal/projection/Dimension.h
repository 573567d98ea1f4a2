// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Dimension-generic helpers: Eigen types in dimension D (2 or 3), the
// kernel's point and vector types, and conversions between them.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_DIMENSION_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_DIMENSION_H

#include <CGAL/number_utils.h>
#include <Eigen/Dense>

#include <array>
#include <cmath>

namespace CGAL {
namespace MLS {
namespace internal {

template <int D> using Vec = Eigen::Matrix<double, D, 1>;
template <int D> using Mat = Eigen::Matrix<double, D, D>;

/// The kernel's point and vector types in dimension `D`, and conversions to Eigen.
template <class GeomTraits, int D> struct Kernel_types;

template <class GeomTraits> struct Kernel_types<GeomTraits, 2> {
  using Point = typename GeomTraits::Point_2;
  using Vector = typename GeomTraits::Vector_2;
  static Vec<2> to_eigen(const Point& p) { return Vec<2>(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }
  static Vec<2> to_eigen(const Vector& v) { return Vec<2>(CGAL::to_double(v.x()), CGAL::to_double(v.y())); }
  static Point to_point(const Vec<2>& v) { return Point(v[0], v[1]); }
  static Vector to_vector(const Vec<2>& v) { return Vector(v[0], v[1]); }
};

template <class GeomTraits> struct Kernel_types<GeomTraits, 3> {
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  static Vec<3> to_eigen(const Point& p) {
    return Vec<3>(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  static Vec<3> to_eigen(const Vector& v) {
    return Vec<3>(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
  }
  static Point to_point(const Vec<3>& v) { return Point(v[0], v[1], v[2]); }
  static Vector to_vector(const Vec<3>& v) { return Vector(v[0], v[1], v[2]); }
};

/// An orthonormal basis of the hyperplane orthogonal to the unit vector `n`
/// (one vector in 2D, two in 3D), chosen deterministically from `n` alone.
template <int D> std::array<Vec<D>, D - 1> tangent_basis(const Vec<D>& n);

template <> inline std::array<Vec<2>, 1> tangent_basis<2>(const Vec<2>& n) { return {Vec<2>(-n[1], n[0])}; }

template <> inline std::array<Vec<3>, 2> tangent_basis<3>(const Vec<3>& n) {
  int axis = 0;
  if(std::abs(n[1]) < std::abs(n[axis])) axis = 1;
  if(std::abs(n[2]) < std::abs(n[axis])) axis = 2;
  Vec<3> a = Vec<3>::Zero();
  a[axis] = 1.;
  Vec<3> e1 = n.cross(a).normalized();
  Vec<3> e2 = n.cross(e1);
  return {e1, e2};
}

/// The unit vector reached from the unit vector `n0` by the exponential map of
/// the sphere at `n0` with tangent coordinates `a` in the basis `basis`:
/// `cos|a| n0 + sin|a| (a / |a|)`. Smooth, and covers every direction with |a| <= pi.
template <int D, class Params>
Vec<D> exp_map(const Vec<D>& n0, const std::array<Vec<D>, D - 1>& basis, const Params& a) {
  Vec<D> t = Vec<D>::Zero();
  double len2 = 0;
  for(int j = 0; j < D - 1; ++j) {
    t += a[j] * basis[j];
    len2 += a[j] * a[j];
  }
  const double len = std::sqrt(len2);
  if(len < 1e-12) return (n0 + t).normalized();
  return std::cos(len) * n0 + (std::sin(len) / len) * t;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_DIMENSION_H
