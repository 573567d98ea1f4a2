// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A consistently oriented normal field on a point set, for the sign of the implicit function:
// the input normals when there are some, otherwise normals estimated with CGAL's
// pca_estimate_normals and oriented with mst_orient_normals, with a documented fall-back for the points the MST cannot orient.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_ORIENTED_NORMALS_H
#define CGAL_MLS_PROJECTION_INTERNAL_ORIENTED_NORMALS_H

#include <CGAL/MLS_projection/internal/Dimension.h>

#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// What `estimate_oriented_normals()` did.
struct Oriented_normals_report {
  /// Points oriented by `mst_orient_normals` (all rounds).
  std::size_t oriented_by_mst = 0;
  /// Points left unoriented by every MST round, oriented away from the centroid (the fall-back).
  std::size_t oriented_by_fallback = 0;
  /// Points whose estimated normal was not finite or null, replaced by the direction from the
  /// centroid (or +z when the point is the centroid).
  std::size_t replaced = 0;
  /// Rounds of `mst_orient_normals` run.
  int rounds = 0;
  /// `false` when cancelled by the callback.
  bool completed = true;
};

/// Estimates unit normals of `points` and orients them consistently; returns one normal per point
/// in `normals` (same order).
///
/// 1. `pca_estimate_normals` with `k` neighbours (the normals only orient the implicit function,
///    for which a plane fit suffices; CGAL 5.5's `jet_estimate_normals` crashes on neighbourhoods
///    of coincident points); a normal that is not finite (coincident or collinear neighbours)
///    is replaced by the direction from the centroid.
/// 2. `mst_orient_normals` with `k` neighbours orients the connected component of the
///    Riemannian graph that holds the highest point (its normal is turned up). The points it
///    leaves unoriented (other components: several objects, or sparse parts) get new rounds
///    on the unoriented points alone, up to 16 rounds, each orienting the component holding the
///    highest remaining point; a round that orients nothing ends the loop.
/// 3. Fall-back: the points still unoriented are oriented away from the centroid of the input
///    (right for a convex object, at worst a flipped patch; never a crash).
///
/// `progress` (may be empty) receives fractions in [0, 1]; returning `false` cancels
/// (`completed` is then `false` and `normals` is left empty).
template <class ConcurrencyTag, class GeomTraits>
Oriented_normals_report estimate_oriented_normals(const std::vector<typename GeomTraits::Point_3>& points,
                                                  std::vector<typename GeomTraits::Vector_3>& normals, unsigned int k,
                                                  const std::function<bool(double)>& progress = {}) {
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  using Item = std::pair<Point, Vector>;
  using Point_map = CGAL::First_of_pair_property_map<Item>;
  using Normal_map = CGAL::Second_of_pair_property_map<Item>;
  Oriented_normals_report report;
  normals.clear();
  const std::size_t n = points.size();
  if(n == 0) return report;
  k = (std::max)(k, 3u);
  const auto step = [&](double f) {
    if(progress && !progress(f)) {
      report.completed = false;
      normals.clear();
      return false;
    }
    return true;
  };

  // centroid, for the replacement of null normals and the fall-back orientation
  double cx = 0, cy = 0, cz = 0;
  for(const Point& p : points) {
    cx += CGAL::to_double(p.x());
    cy += CGAL::to_double(p.y());
    cz += CGAL::to_double(p.z());
  }
  const Point centroid(cx / double(n), cy / double(n), cz / double(n));
  const auto from_centroid = [&](const Point& p) {
    Vector v = p - centroid;
    const double len = std::sqrt(CGAL::to_double(v.squared_length()));
    return len > 0 ? Vector(v / len) : Vector(0, 0, 1);
  };
  const auto is_usable = [](const Vector& v) {
    const double x = CGAL::to_double(v.x()), y = CGAL::to_double(v.y()), z = CGAL::to_double(v.z());
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && (x * x + y * y + z * z) > 1e-20;
  };

  // 1. estimation: PCA. The normals only orient (the geometry comes from the projection), for
  // which a plane fit suffices; CGAL 5.5's jet_estimate_normals crashes (an SVD of NaNs) on
  // neighbourhoods of coincident or collinear points, which PCA survives (arbitrary normal).
  std::vector<Item> items(n);
  for(std::size_t i = 0; i < n; ++i) items[i] = Item(points[i], Vector(0, 0, 0));
  const unsigned int kk = static_cast<unsigned int>((std::min<std::size_t>)(k, n > 1 ? n - 1 : 1));
  if(n >= 3 && kk >= 2) {
    CGAL::pca_estimate_normals<ConcurrencyTag>(
      items, kk, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).geom_traits(GeomTraits()));
  }
  if(!step(0.35)) return report;
  for(Item& it : items) {
    if(is_usable(it.second)) {
      it.second = it.second / std::sqrt(CGAL::to_double(it.second.squared_length()));
    } else {
      it.second = from_centroid(it.first);
      ++report.replaced;
    }
  }

  // 2. orientation: MST rounds on the points not yet oriented. mst_orient_normals reorders its
  // range, so each item carries its index.
  using Indexed = std::tuple<Point, Vector, std::size_t>;
  using Indexed_point_map = CGAL::Nth_of_tuple_property_map<0, Indexed>;
  using Indexed_normal_map = CGAL::Nth_of_tuple_property_map<1, Indexed>;
  std::vector<bool> oriented(n, false);
  std::vector<Indexed> remaining(n);
  for(std::size_t i = 0; i < n; ++i) remaining[i] = Indexed(items[i].first, items[i].second, i);
  const unsigned int mst_k = static_cast<unsigned int>((std::min<std::size_t>)(k, n > 1 ? n - 1 : 1));
  for(int round = 0; round < 16 && remaining.size() >= 3 && mst_k >= 2; ++round) {
    ++report.rounds;
    auto first_unoriented = CGAL::mst_orient_normals(
      remaining, mst_k, CGAL::parameters::point_map(Indexed_point_map()).normal_map(Indexed_normal_map()).geom_traits(GeomTraits()));
    std::size_t done = 0;
    for(auto it = remaining.begin(); it != first_unoriented; ++it, ++done) {
      items[std::get<2>(*it)].second = std::get<1>(*it);
      oriented[std::get<2>(*it)] = true;
    }
    report.oriented_by_mst += done;
    remaining.erase(remaining.begin(), first_unoriented);
    if(!step(0.35 + 0.6 * double(report.oriented_by_mst) / double(n))) return report;
    if(done == 0) break;
  }

  // 3. fall-back for the rest
  normals.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    Vector v = items[i].second;
    if(!oriented[i]) {
      if(v * from_centroid(items[i].first) < 0) v = -v;
      ++report.oriented_by_fallback;
    }
    normals[i] = v;
  }
  if(!step(1.)) return report;
  return report;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_ORIENTED_NORMALS_H
