// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A consistently oriented normal field on a point set, for the sign of the implicit function:
// the input normals when there are some, otherwise normals estimated with CGAL's
// pca_estimate_normals and oriented along a minimum spanning forest of the neighbour graph, with
// the votes of the free space around the points.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_ORIENTED_NORMALS_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_ORIENTED_NORMALS_H

#include <CGAL/MLS_projection/Normal_orientation_report.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>
#include <CGAL/MLS_projection/internal/projection/Point_tree.h>
#include <CGAL/MLS_projection/internal/meshing/outside_votes.h>

#include <CGAL/for_each.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/range/irange.hpp>

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

/// The neighbours of the PCA normals and of the orientation's graph when the samples carry no
/// normals (manual, section "The Implicit Function: Local Fits").
inline constexpr unsigned int normal_neighbors = 18;

/// Estimates unit normals of `points` and orients them consistently; returns one normal per point
/// in `normals` (same order).
///
/// 1. `pca_estimate_normals` with `k` neighbours (the normals only orient the implicit function,
///    for which a plane fit suffices; CGAL 5.5's `jet_estimate_normals` crashes on neighbourhoods
///    of coincident points); a normal that is not finite (coincident or collinear neighbours)
///    is replaced by the direction from the centroid.
/// 2. Votes of the space around the points (`outside_votes()`): +1 or -1 where the free space
///    along the normal's two directions tells the outside from the inside, 0 where it does not.
/// 3. Propagation along a minimum spanning forest of the graph joining each point to its `k`
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
///    Kruskal's algorithm skips the edges that would join two parts of the forest whose sums of
///    votes, oriented along the edge, have opposite signs: near a knife edge, where the two faces
///    lie within a spacing of each other and share their PCA normal, an edge along the surface
///    joins the two faces as if they were one sheet, and would turn one of them inside out.
///    With `split_by_votes` false, no edge is skipped: the votes of an open scan see the inside
///    of the scanned object through the opening, and split a face into trees turned opposite ways.
/// 4. Each tree is turned outward as a whole: by the sign of the sum of its votes, or where that
///    is 0, by \f$\sum_i (p_i - c) \cdot n_i\f$, with \f$c\f$ the centroid of the tree (for a
///    closed surface, the sum is proportional to \f$\oint (x - c) \cdot n\, dA = 3V > 0\f$ whatever
///    \f$c\f$, but the sampled sum is not: with \f$c\f$ far away, the small residue of
///    \f$\sum_i n_i\f$ times the distance outweighs it, as for two spheres \f$10^5\f$ apart and the
///    centroid of both; for an open patch, it orients it away from its centroid: outward for a
///    convex cap). Trees of one point are oriented away from the centroid of the input (the
///    fall-back).
///
/// `progress` (may be empty) receives fractions in [0, 1]; returning `false` cancels
/// (`completed` is then `false` and `normals` is left empty).
template <class ConcurrencyTag, class GeomTraits>
Normal_orientation_report estimate_oriented_normals(const std::vector<typename GeomTraits::Point_3>& points,
                                                  std::vector<typename GeomTraits::Vector_3>& normals, unsigned int k,
                                                  const std::function<bool(double)>& progress = {},
                                                  bool split_by_votes = true) {
  using Point = typename GeomTraits::Point_3;
  using Vector = typename GeomTraits::Vector_3;
  using Item = std::pair<Point, Vector>;
  using Point_map = CGAL::First_of_pair_property_map<Item>;
  using Normal_map = CGAL::Second_of_pair_property_map<Item>;
  Normal_orientation_report report;
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

  // 3. the graph's edges, by increasing weight (ties by index: deterministic)
  struct Edge {
    float weight;
    std::uint32_t i, j;
    bool flips;
  };
  std::vector<Edge> edges;
  std::vector<double> reach(n); // squared distance to the k-th neighbour
  {
    // the k nearest of each point (the point itself first), searched once, in parallel
    const std::size_t kn = (std::min)(std::size_t(k) + 1, n);
    std::vector<std::uint32_t> near(n * kn), count(n);
    const Point_tree<3> tree(p);
    CGAL::for_each<ConcurrencyTag>(boost::irange<std::size_t>(0, n), [&](std::size_t i) {
      thread_local std::vector<std::pair<double, std::size_t>> found;
      tree.k_nearest(p[i], kn, found);
      for(std::size_t j = 0; j < found.size(); ++j) near[i * kn + j] = std::uint32_t(found[j].second);
      count[i] = std::uint32_t(found.size());
      reach[i] = found.empty() ? 0. : found.back().first;
      return true;
    });
    if(!step(0.45)) return report;
    edges.reserve(n * k / 2 + n);
    for(std::size_t i = 0; i < n; ++i) {
      for(std::size_t c = 0; c < count[i]; ++c) {
        const std::size_t j = near[i * kn + c];
        const double d2 = (p[j] - p[i]).squaredNorm(); // as the tree computed it
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

  // 2. the votes (after the edges: they take the spacing from the median distance r to the k-th
  // neighbour, pi r^2 = k spacing^2 on a surface)
  std::vector<std::int8_t> votes;
  {
    std::vector<double> r(reach);
    std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
    votes = outside_votes(p, m, std::sqrt(r[r.size() / 2] * 3.14159265358979 / double(k)));
  }
  if(!step(0.7)) return report;

  // Kruskal's spanning forest, without the edges that would join two parts whose votes disagree
  // (with split_by_votes);
  // union-find with parities (a point flipped relative to its parent), each root holding the sum
  // of its part's votes in its own frame
  std::vector<std::uint32_t> up(n);
  std::vector<std::uint8_t> parity(n, 0), height(n, 0);
  std::vector<int> vote_sum(n);
  for(std::size_t i = 0; i < n; ++i) {
    up[i] = std::uint32_t(i);
    vote_sum[i] = votes[i];
  }
  const auto find = [&](std::uint32_t i) {
    std::uint8_t flip = 0;
    std::uint32_t root = i;
    while(up[root] != root) {
      flip ^= parity[root];
      root = up[root];
    }
    for(std::uint8_t f = flip; up[i] != root;) { // path compression, parities kept
      const std::uint32_t next = up[i];
      const std::uint8_t pf = parity[i];
      up[i] = root;
      parity[i] = f;
      f ^= pf;
      i = next;
    }
    return std::make_pair(root, flip);
  };
  std::vector<std::vector<std::pair<std::uint32_t, bool>>> forest(n);
  for(const Edge& e : edges) {
    const auto [a, fa] = find(e.i);
    const auto [b, fb] = find(e.j);
    if(a == b) continue;
    const std::uint8_t x = fa ^ fb ^ std::uint8_t(e.flips); // b's frame relative to a's
    const int vb = x ? -vote_sum[b] : vote_sum[b];
    if(split_by_votes && ((vote_sum[a] > 0 && vb < 0) || (vote_sum[a] < 0 && vb > 0))) continue;
    auto [child, root] = height[a] < height[b] ? std::make_pair(a, b) : std::make_pair(b, a);
    if(height[a] == height[b]) ++height[root];
    up[child] = root;
    parity[child] = x;
    vote_sum[root] = vote_sum[a] + vb; // in a's frame, which is root's frame up to the parity x
    if(root == b && x) vote_sum[root] = -vote_sum[root];
    forest[e.i].emplace_back(e.j, e.flips);
    forest[e.j].emplace_back(e.i, e.flips);
  }
  std::vector<int> sign(n, 0);
  std::vector<std::uint32_t> tree_of(n), stack;
  std::vector<double> outwardness; // per tree: sum of (p - c) . n, c the tree's centroid
  std::vector<int> tree_votes;     // per tree: its points' votes in its frame
  std::vector<std::size_t> tree_size;
  for(std::size_t root = 0; root < n; ++root) {
    if(sign[root] != 0) continue;
    const auto t = std::uint32_t(outwardness.size());
    outwardness.push_back(0.);
    tree_votes.push_back(0);
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
      tree_votes[t] += sign[i] * votes[i];
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

  // 4. each tree outward, by its votes or else by its outwardness; trees of one point away from the
  // centroid
  report.components = outwardness.size();
  std::vector<bool> turned(outwardness.size());
  for(std::size_t t = 0; t < outwardness.size(); ++t) {
    turned[t] = tree_votes[t] != 0 ? tree_votes[t] < 0 : outwardness[t] < 0;
    report.flipped_components += (tree_size[t] > 1 && turned[t]) ? 1 : 0;
  }
  normals.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    const std::uint32_t t = tree_of[i];
    Vector v = items[i].second;
    if(tree_size[t] > 1) {
      if((sign[i] < 0) != turned[t]) v = -v;
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

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_ORIENTED_NORMALS_H
