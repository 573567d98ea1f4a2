// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The sharp-feature polylines that Mesh_3 can protect on the surface f = 0: detected on the
// seeds' projections, those off the surface dropped, the others fitted to it.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_PROTECTED_POLYLINES_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_PROTECTED_POLYLINES_H

#include <CGAL/MLS_projection/detect_sharp_features.h>
#include <CGAL/MLS_projection/internal/projection/Levin_screened_projection.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The sharp-feature polylines (and the number of corners) to protect when meshing `function`:
/// `detect_sharp_features()` (its defaults) with the operator that projected the
/// seeds (screened by P_L, see `MLS_implicit_function`) on the seeds' results (project once, use
/// twice), for the operators that find creases; none for the others. `queries`: the helper and
/// relaxation points projected.
template <class ConcurrencyTag, class ImplicitFunction>
std::vector<std::vector<typename ImplicitFunction::Point_3>> feature_polylines(const ImplicitFunction& function,
                                                                               std::size_t& number_of_corners,
                                                                               std::size_t& queries) {
  number_of_corners = 0;
  queries = 0;
  using Projection = typename ImplicitFunction::Projection_type;
  if constexpr(finds_features<Projection>::value) {
    if(!function.has_seed_projection()) return {};
    auto features = detect_sharp_features<ConcurrencyTag>(function.seed_projection(), function.projected_seeds());
    number_of_corners = features.corners.size();
    queries = features.statistics.helper_queries + features.statistics.relaxation_queries;
    return std::move(features.polylines);
  }
  (void)function;
  return {};
}

/// Removes from `polylines` those the surface \f$f = 0\f$ does not pass through: the median of
/// \f$|f|\f$ over their vertices exceeds `facet_distance`. With them, Mesh_3's manifold refinement,
/// which cannot move the protected vertices, failed or went on without end. They occur where the
/// blended fits round a crease the operator finds sharp (noisy scans, whose seeds near the creases
/// keep P_L's fit). Returns the number removed.
template <class Point_3, class Function>
std::size_t drop_polylines_off_surface(std::vector<std::vector<Point_3>>& polylines, const Function& f,
                                       double facet_distance) {
  const std::size_t before = polylines.size();
  std::vector<double> off;
  polylines.erase(std::remove_if(polylines.begin(), polylines.end(),
                                 [&](const std::vector<Point_3>& line) {
                                   if(line.empty()) return true;
                                   off.clear();
                                   for(const Point_3& p : line) off.push_back(std::abs(CGAL::to_double(f(p))));
                                   std::nth_element(off.begin(), off.begin() + off.size() / 2, off.end());
                                   return !(off[off.size() / 2] <= facet_distance);
                                 }),
                  polylines.end());
  return before - polylines.size();
}

/// Removes from `polylines` the vertices where `keep(vertex)` is false, splitting the polylines
/// there; pieces of fewer than 2 vertices are dropped.
template <class Point_3, class Keep>
void cut_polylines(std::vector<std::vector<Point_3>>& polylines, const Keep& keep) {
  std::vector<std::vector<Point_3>> cut;
  for(const std::vector<Point_3>& line : polylines) {
    std::vector<Point_3> piece;
    for(const Point_3& p : line) {
      if(keep(p)) {
        piece.push_back(p);
        continue;
      }
      if(piece.size() >= 2) cut.push_back(std::move(piece));
      piece.clear();
    }
    if(piece.size() >= 2) cut.push_back(std::move(piece));
  }
  polylines = std::move(cut);
}

/// The point \f$p\f$ moved onto the surface \f$f = 0\f$ by Newton steps along the gradient of \f$f\f$
/// (central differences of step `step`), until \f$|f| \le\f$ `tolerance` (at most 8 steps, the
/// best point kept).
template <class Point_3, class Function>
Point_3 snap_to_surface(Point_3 p, const Function& f, double step, double tolerance) {
  using Vector_3 = typename Kernel_traits<Point_3>::Kernel::Vector_3;
  const auto value = [&f](const Point_3& q) { return CGAL::to_double(f(q)); };
  const double e = step;
  double v = value(p);
  Point_3 best = p;
  double best_v = std::abs(v);
  for(int it = 0; it < 8 && best_v > tolerance; ++it) {
    const Vector_3 g((value(p + Vector_3(e, 0, 0)) - value(p - Vector_3(e, 0, 0))) / (2 * e),
                     (value(p + Vector_3(0, e, 0)) - value(p - Vector_3(0, e, 0))) / (2 * e),
                     (value(p + Vector_3(0, 0, e)) - value(p - Vector_3(0, 0, e))) / (2 * e));
    const double g2 = CGAL::to_double(g.squared_length());
    if(!(g2 > 1e-12)) break;
    p = p - g * (v / g2);
    v = value(p);
    if(std::abs(v) < best_v) {
      best = p;
      best_v = std::abs(v);
    }
  }
  return best;
}

/// Fits the vertices of `polylines` to the surface \f$f = 0\f$: those further than `facet_distance`
/// from it (in \f$|f|\f$) are removed (`cut_polylines()`), and the others are moved onto it
/// (`snap_to_surface()`, step \f$10^{-3}\f$ facet distances). Mesh_3 centres its protecting balls
/// on the polylines and never moves them: next to a centre off the surface, its manifold refinement
/// could not make the surface a disk and looped without end. A vertex moves the same wherever it
/// occurs (corners, the ends of a closed polyline).
template <class Point_3, class Function>
void fit_polylines_to_surface(std::vector<std::vector<Point_3>>& polylines, const Function& f, double facet_distance,
                              double tolerance) {
  cut_polylines(polylines, [&](const Point_3& p) { return std::abs(CGAL::to_double(f(p))) <= facet_distance; });
  for(std::vector<Point_3>& line : polylines)
    for(Point_3& p : line) p = snap_to_surface(p, f, 1e-3 * facet_distance, tolerance);
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_PROTECTED_POLYLINES_H
