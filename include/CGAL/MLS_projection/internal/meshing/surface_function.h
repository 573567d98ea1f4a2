// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The implicit function as Mesh_3 meshes a closed surface: checked closed inside its bounding
// sphere, positive beyond it, with short segments across the surface for the initial points.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_SURFACE_FUNCTION_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_SURFACE_FUNCTION_H

#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// Whether `f` is positive at 256 points spread evenly over the sphere (Fibonacci lattice):
/// the surface \f$f = 0\f$ is then closed inside it. It is not when the data bound no volume
/// (coplanar points, an open scan): the region \f$f < 0\f$ then reaches the sphere, and Mesh_3
/// would refine the intersection of the surface with the sphere without end.
template <class Point_3, class Function>
bool is_positive_on_sphere(const Function& f, const Point_3& centre, double radius) {
  const int n = 256;
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  for(int i = 0; i < n; ++i) {
    const double z = 1. - (2. * i + 1.) / n, r = std::sqrt((std::max)(0., 1. - z * z)), t = golden * i;
    const Point_3 p(CGAL::to_double(centre.x()) + radius * r * std::cos(t), CGAL::to_double(centre.y()) + radius * r * std::sin(t),
                    CGAL::to_double(centre.z()) + radius * z);
    if(!(f(p) > 0)) return false;
  }
  return true;
}

/// Why the surface \f$f = 0\f$ of `function` (an `MLS_implicit_function`) is not a closed surface
/// inside its bounding sphere, or `nullptr` when it is.
template <class ImplicitFunction>
const char* closed_surface_failure(const ImplicitFunction& function) {
  using Point_3 = typename ImplicitFunction::Point_3;
  if(!function.is_valid()) return "no implicit function (too few seeds could be projected: degenerate data)";
  const auto f = [&function](const Point_3& p) { return CGAL::to_double(function(p)); };
  const auto sphere = function.bounding_sphere();
  if(!is_positive_on_sphere(f, sphere.center(), std::sqrt(CGAL::to_double(sphere.squared_radius()))))
    return "the surface is not closed (its inside reaches the bounding sphere: the points bound no volume, e.g. "
           "coplanar points or an open scan, or the sides of a thin part were not told apart)";
  if(!(f(function.get_inner_point()) < 0)) return "the implicit function has no inside";
  return nullptr;
}

/// `q` as a point of another kernel.
template <class Point_3, class Q>
Point_3 point_as(const Q& q) {
  return Point_3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
}

/// \f$\max(f(p), |p - c| - R)\f$ for the bounding sphere of `f` (an `MLS_implicit_function`), of
/// centre \f$c\f$ and radius \f$R\f$, at points of the meshers' kernel (`Point_3`), without
/// evaluating \f$f\f$ beyond the sphere (the points far out are many, and far from every seed).
/// Mesh_3 also evaluates points far outside it (the circumcentres of the initial triangulation's
/// cells), where the far value, signed by the nearest seed's normal, may change sign wherever two
/// seeds with different normals are about equally far (e.g. on the axis of a bore, beyond the
/// solid), which would grow spurious surface there.
template <class Point_3, class ImplicitFunction>
std::function<double(const Point_3&)> clamped_to_sphere(const ImplicitFunction& f) {
  using Function_point = typename ImplicitFunction::Point_3;
  const auto sphere = f.bounding_sphere();
  const double cx = CGAL::to_double(sphere.center().x()), cy = CGAL::to_double(sphere.center().y()),
               cz = CGAL::to_double(sphere.center().z()), radius = std::sqrt(CGAL::to_double(sphere.squared_radius()));
  return [f, cx, cy, cz, radius](const Point_3& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    const double outside = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz)) - radius;
    if(outside > 0) return outside;
    return (std::max)(CGAL::to_double(f(Function_point(x, y, z))), outside);
  };
}

/// Segments across the surface at up to 128 of the `seeds` (results with a point and an outward
/// normal \f$n\f$), evenly spread in their order: from \f$p - b\,n\f$ (`below`) to \f$p + a\,n\f$
/// (`above`), and to \f$p - k\,n\f$ when `back` \f$k > 0\f$, as points of the meshers' kernel.
/// Mesh_3's initial points are their intersections with the surface.
template <class Point_3, class Result>
std::vector<std::pair<Point_3, Point_3>> surface_probes(const std::vector<Result>& seeds, double below, double above,
                                                        double back = 0) {
  std::vector<std::pair<Point_3, Point_3>> probes;
  const std::size_t stride = (std::max<std::size_t>)(1, seeds.size() / 128);
  for(std::size_t i = 0; i < seeds.size(); i += stride) {
    const auto& p = seeds[i].point;
    const auto& n = seeds[i].normal;
    const Point_3 start = point_as<Point_3>(p - n * below);
    probes.emplace_back(start, point_as<Point_3>(p + n * above));
    if(back > 0) probes.emplace_back(start, point_as<Point_3>(p - n * back));
  }
  return probes;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_SURFACE_FUNCTION_H
