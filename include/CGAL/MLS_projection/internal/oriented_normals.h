// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A consistently oriented normal field on a point set, for the sign of the implicit function:
// the input normals when there are some, otherwise normals estimated with CGAL's
// pca_estimate_normals and oriented along a minimum spanning forest of the neighbour graph.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_ORIENTED_NORMALS_H
#define CGAL_MLS_PROJECTION_INTERNAL_ORIENTED_NORMALS_H

#include <CGAL/MLS_projection/internal/Dimension.h>
#include <CGAL/MLS_projection/internal/Point_tree.h>

#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// What `estimate_oriented_normals()` did.
struct Oriented_normals_report {
  /// Points oriented along the spanning forest (in a tree of at least two points).
  std::size_t oriented_by_mst = 0;
  /// Points without a usable neighbour (trees of one point), oriented away from the centroid.
  std::size_t oriented_by_fallback = 0;
  /// Points whose estimated normal was not finite or null, replaced by the direction from the
  /// centroid (or +z when the point is the centroid).
  std::size_t replaced = 0;
  /// Trees of the spanning forest (the connected parts of the neighbour graph).
  std::size_t components = 0;
  /// Trees turned over by the outwardness test (step 3).
  std::size_t flipped_components = 0;
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
/// 2. Propagation along a minimum spanning forest of the graph joining each point to its `k`
///    nearest neighbours (edges at most twice as long as the shorter of the two points' distance
///    to their `k`-th neighbour, so that far outliers and separate objects are not joined). Along
///    an edge \f$e\f$ from \f$p_i\f$ to \f$p_j\f$, \f$n_j\f$ agrees with \f$n_i\f$ when
///    \f$R_e(n_i) \cdot n_j > 0\f$, with \f$R_e\f$ the reflection across the plane orthogonal to
///    \f$e\f$ (König and Gumhold's criterion: exact for two points of a circle), and the edge's
///    weight is \f$1 - |R_e(n_i) \cdot n_j| + (|\hat e \cdot n_i| + |\hat e \cdot n_j|)/2\f$: edges
///    along the surface come first, so that the two sides of a thin plate are joined around its
///    rim, and noise (which puts neighbours above one another, where \f$R_e\f$ reverses) does not
///    decide. Unlike the criterion \f$n_i \cdot n_j > 0\f$ of
///    `mst_orient_normals`, it orients across creases (where the normals are orthogonal) and across
///    thin plates (whose two sides have opposite normals along an edge parallel to them).
/// 3. Each tree is turned outward as a whole: its normals are flipped when
///    \f$\sum_i (p_i - c) \cdot n_i < 0\f$, with \f$c\f$ the centroid of the tree (for a closed surface,
///    the sum is proportional to \f$\oint (x - c) \cdot n\, dA = 3V > 0\f$ whatever \f$c\f$, but the
///    sampled sum is not: with \f$c\f$ far away, the small residue of \f$\sum_i n_i\f$ times the
///    distance outweighs it, as for two spheres \f$10^5\f$ apart and the centroid of both; for an
///    open patch, it orients it away from its centroid: outward for a convex cap). Trees of one
///    point are oriented away from the centroid of the input (the fall-back).
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

  // centroid: the origin of the local coordinates below, for null normals and the fall-back
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
  std::vector<Vec<3>> p(n), m(n); // points relative to the centroid, unit normals
  for(std::size_t i = 0; i < n; ++i) {
    Item& it = items[i];
    if(is_usable(it.second)) {
      it.second = it.second / std::sqrt(CGAL::to_double(it.second.squared_length()));
    } else {
      it.second = from_centroid(it.first);
      ++report.replaced;
    }
    const Vector d = it.first - centroid;
    p[i] = Vec<3>(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z()));
    m[i] = Vec<3>(CGAL::to_double(it.second.x()), CGAL::to_double(it.second.y()), CGAL::to_double(it.second.z()));
  }

  // 2. the graph's edges, by increasing weight (ties by index: deterministic)
  struct Edge {
    float weight;
    std::uint32_t i, j;
    bool flips;
  };
  std::vector<Edge> edges;
  {
    const Point_tree<3> tree(p);
    std::vector<std::pair<double, std::size_t>> near;
    std::vector<double> reach(n); // squared distance to the k-th neighbour
    for(std::size_t i = 0; i < n; ++i) {
      tree.k_nearest(p[i], std::size_t(k) + 1, near); // the point itself comes first
      reach[i] = near.empty() ? 0. : near.back().first;
    }
    if(!step(0.45)) return report;
    edges.reserve(n * k / 2 + n);
    for(std::size_t i = 0; i < n; ++i) {
      tree.k_nearest(p[i], std::size_t(k) + 1, near);
      for(const auto& [d2, j] : near) {
        // each edge once: from the smaller index when both ends have the other as a neighbour
        if(j == i || !(d2 > 0) || d2 > 4. * (std::min)(reach[i], reach[j]) || (d2 <= reach[j] && j < i)) continue;
        const Vec<3> e = (p[j] - p[i]) / std::sqrt(d2);
        const double agreement = m[i].dot(m[j]) - 2. * m[i].dot(e) * m[j].dot(e); // R_e(n_i) . n_j
        const double across = 0.5 * (std::abs(m[i].dot(e)) + std::abs(m[j].dot(e))); // 0 along the surface
        edges.push_back({float(1. - std::abs(agreement) + across), std::uint32_t((std::min)(i, j)),
                         std::uint32_t((std::max)(i, j)), agreement < 0});
      }
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return std::tie(a.weight, a.i, a.j) < std::tie(b.weight, b.i, b.j);
  });
  if(!step(0.6)) return report;

  // Kruskal's spanning forest, then a traversal of each tree from its smallest index
  std::vector<std::size_t> rank(n), parent(n);
  boost::disjoint_sets<std::size_t*, std::size_t*> sets(rank.data(), parent.data());
  for(std::size_t i = 0; i < n; ++i) sets.make_set(i);
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> forest(n);
  for(const Edge& e : edges) {
    const std::size_t a = sets.find_set(e.i), b = sets.find_set(e.j);
    if(a == b) continue;
    sets.link(a, b);
    forest[e.i].emplace_back(e.j, e.flips);
    forest[e.j].emplace_back(e.i, e.flips);
  }
  std::vector<int> sign(n, 0);
  std::vector<std::uint32_t> tree_of(n), stack;
  std::vector<double> outwardness; // per tree: sum of (p - c) . n, c the tree's centroid
  std::vector<std::size_t> tree_size;
  for(std::size_t root = 0; root < n; ++root) {
    if(sign[root] != 0) continue;
    const auto t = std::uint32_t(outwardness.size());
    outwardness.push_back(0.);
    tree_size.push_back(0);
    Vec<3> point_sum = Vec<3>::Zero(), normal_sum = Vec<3>::Zero();
    sign[root] = 1;
    stack.assign(1, std::uint32_t(root));
    while(!stack.empty()) {
      const std::uint32_t i = stack.back();
      stack.pop_back();
      tree_of[i] = t;
      ++tree_size[t];
      outwardness[t] += sign[i] * p[i].dot(m[i]);
      point_sum += p[i];
      normal_sum += sign[i] * m[i];
      for(const auto& [j, flips] : forest[i])
        if(sign[j] == 0) {
          sign[j] = flips ? -sign[i] : sign[i];
          stack.push_back(j);
        }
    }
    outwardness[t] -= (point_sum / double(tree_size[t])).dot(normal_sum);
  }
  if(!step(0.95)) return report;

  // 3. each tree outward; trees of one point away from the centroid
  report.components = outwardness.size();
  for(std::size_t t = 0; t < outwardness.size(); ++t)
    report.flipped_components += (tree_size[t] > 1 && outwardness[t] < 0) ? 1 : 0;
  normals.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t t = tree_of[i];
    Vector v = items[i].second;
    if(tree_size[t] > 1) {
      if(sign[i] * (outwardness[t] < 0 ? -1 : 1) < 0) v = -v;
      ++report.oriented_by_mst;
    } else {
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
