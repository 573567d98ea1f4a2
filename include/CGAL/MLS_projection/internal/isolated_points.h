// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The points of a scan that lie apart from the others: outliers away from the surface.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_ISOLATED_POINTS_H
#define CGAL_MLS_PROJECTION_INTERNAL_ISOLATED_POINTS_H

#include <CGAL/MLS_projection/internal/Point_tree.h>

#include <CGAL/for_each.h>

#include <boost/range/irange.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// Flags the isolated points of `points`: with \f$d(p)\f$ the root-mean-square distance from
/// \f$p\f$ to its 6 nearest other points, \f$p\f$ is isolated when \f$d(p)\f$ exceeds 3 times the
/// median of \f$d\f$ over those 6 neighbours (a point off a surface among its samples), or 4 times
/// its median over all points (a point among other outliers). A region sampled more than 4 times
/// as sparsely as the median (16 times fewer points per area) is flagged too. The flags do not
/// depend on the threads.
template <class ConcurrencyTag>
std::vector<bool> isolated_points(const std::vector<Vec<3>>& points) {
  constexpr std::size_t k = 6;
  const std::size_t n = points.size();
  std::vector<bool> isolated(n, false);
  if(n <= 2 * k) return isolated;
  const Point_tree<3> tree(points);
  std::vector<double> d(n);
  std::vector<std::array<std::size_t, k>> neighbors(n);
  CGAL::for_each<ConcurrencyTag>(boost::irange<std::size_t>(0, n), [&](std::size_t i) {
    thread_local std::vector<std::pair<double, std::size_t>> found;
    tree.k_nearest(points[i], k + 1, found);
    double sum = 0;
    std::size_t m = 0;
    for(const auto& f : found) {
      if(f.second == i || m == k) continue;
      sum += f.first;
      neighbors[i][m++] = f.second;
    }
    d[i] = std::sqrt(sum / double(k));
    return true;
  });
  std::vector<double> sorted(d);
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double global = sorted[n / 2];
  for(std::size_t i = 0; i < n; ++i) {
    std::array<double, k> around;
    for(std::size_t j = 0; j < k; ++j) around[j] = d[neighbors[i][j]];
    std::nth_element(around.begin(), around.begin() + k / 2, around.end());
    const double reference = (std::min)(around[k / 2], 4. / 3. * global);
    isolated[i] = reference > 0 && d[i] > 3. * reference; // not among duplicates

  }
  return isolated;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_ISOLATED_POINTS_H
