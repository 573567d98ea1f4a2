// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Votes for the orientation of unoriented normals from the space around the points: which voxels
// the outside reaches, and how far along each normal the points' neighbourhood extends.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTSIDE_VOTES_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTSIDE_VOTES_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// For each point `p[i]` with unit normal `m[i]`, +1 when `m[i]` points out of the volume the
/// points bound, -1 when it points in, 0 when the space around does not tell. `spacing` is the
/// points' average spacing.
///
/// Voxels (edge `spacing / 2`, coarser when the grid would exceed `max_cells`) within 1.5
/// spacings of a point form the *near band*, those within 2.5 spacings the *wall*. The outside is
/// the free space reached from the grid's border without crossing the wall (a wall 5 spacings
/// thick has no gap on a random sampling, where the near band has some: without a wall, the
/// outside reaches the inside); the other free voxels are enclosed; the voxels of the wall out of
/// the near band take the class of the free voxels nearest to them (in steps of 6-neighbours), so
/// that a groove or a gap narrower than the wall is still outside. Along \f$\pm m_i\f$, the first
/// voxel out of the near band is looked for up to 12 spacings away:
/// - outside on one side only: the normal points to that side, unless the band ends there more
///   than a spacing further than on the other side (a concave crease, whose other face runs along
///   the outer ray, or a groove sealed by the wall);
/// - outside on both sides (a part thinner than the wall): the normal points to the side where the
///   band ends at least a spacing sooner. On a blade of thickness \f$t\f$, the band ends \f$t\f$
///   further on the blade's side than on the face's.
inline std::vector<std::int8_t> outside_votes(const std::vector<Vec<3>>& p, const std::vector<Vec<3>>& m, double spacing,
                                              std::size_t max_cells = std::size_t(1) << 25) {
  const std::size_t n = p.size();
  std::vector<std::int8_t> votes(n, 0);
  if(n == 0 || !(spacing > 0) || !std::isfinite(spacing)) return votes;
  const double near = 1.5 * spacing, wall = 2.5 * spacing, reach = 12 * spacing;
  Vec<3> lo = p[0], hi = p[0];
  for(const Vec<3>& q : p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  if(!(hi - lo).allFinite()) return votes;
  double cell = 0.5 * spacing, extent[3];
  for(;; cell *= 1.25) { // in doubles: the first sizes may exceed any integer
    for(int a = 0; a < 3; ++a) extent[a] = std::ceil((hi[a] - lo[a] + 2 * wall) / cell) + 4;
    if(extent[0] * extent[1] * extent[2] <= double(max_cells)) break;
  }
  const std::array<std::int64_t, 3> dims = {std::int64_t(extent[0]), std::int64_t(extent[1]), std::int64_t(extent[2])};
  const Vec<3> origin = lo - Vec<3>::Constant(wall + 2 * cell);
  const std::int64_t sx = dims[0], sxy = dims[0] * dims[1], cells = sxy * dims[2];
  enum : std::uint8_t { FREE, NEAR, WALL, OUTSIDE, ENCLOSED };
  std::vector<std::uint8_t> grid(std::size_t(cells), FREE);
  const auto index_of = [&](const Vec<3>& x) -> std::int64_t {
    std::int64_t c[3];
    for(int a = 0; a < 3; ++a) {
      c[a] = std::int64_t(std::floor((x[a] - origin[a]) / cell));
      if(c[a] < 0 || c[a] >= dims[a]) return -1;
    }
    return c[0] + c[1] * sx + c[2] * sxy;
  };

  // the near band and the wall: in each row of voxels, the range of centres within the radius
  const int r = int(std::ceil(wall / cell));
  const auto mark_row = [&](std::uint8_t* row, double qx, double r2, std::uint8_t state) {
    if(r2 < 0) return;
    const double half = std::sqrt(r2), x = (qx - origin[0]) / cell - 0.5;
    const std::int64_t first = std::int64_t(std::ceil(x - half / cell)), last = std::int64_t(std::floor(x + half / cell));
    for(std::int64_t k = first; k <= last; ++k)
      if(state == NEAR || row[k] == FREE) row[k] = state;
  };
  for(const Vec<3>& q : p) {
    const std::int64_t i = index_of(q), z0 = i / sxy, y0 = (i % sxy) / sx;
    for(std::int64_t z = z0 - r; z <= z0 + r; ++z)
      for(std::int64_t y = y0 - r; y <= y0 + r; ++y) {
        const double dy = origin[1] + cell * (double(y) + 0.5) - q[1], dz = origin[2] + cell * (double(z) + 0.5) - q[2];
        std::uint8_t* row = grid.data() + y * sx + z * sxy;
        mark_row(row, q[0], wall * wall - dy * dy - dz * dz, WALL);
        mark_row(row, q[0], near * near - dy * dy - dz * dz, NEAR);
      }
  }

  // breadth-first spreading of a class from the queued voxels into the voxels of state `from`
  std::deque<std::int64_t> queue;
  const auto spread = [&](std::uint8_t from) {
    while(!queue.empty()) {
      const std::int64_t i = queue.front(), x = i % sx, y = (i % sxy) / sx, z = i / sxy;
      queue.pop_front();
      const std::uint8_t c = grid[std::size_t(i)];
      const std::int64_t next[6] = {x > 0 ? i - 1 : -1,           x + 1 < dims[0] ? i + 1 : -1,
                                    y > 0 ? i - sx : -1,          y + 1 < dims[1] ? i + sx : -1,
                                    z > 0 ? i - sxy : -1,         z + 1 < dims[2] ? i + sxy : -1};
      for(std::int64_t j : next)
        if(j >= 0 && grid[std::size_t(j)] == from) {
          grid[std::size_t(j)] = c;
          queue.push_back(j);
        }
    }
  };
  grid[0] = OUTSIDE; // the border is free: the wall is at least 2 voxels from it
  queue.push_back(0);
  spread(FREE);
  for(std::int64_t i = 0; i < cells; ++i)
    if(grid[std::size_t(i)] == FREE) grid[std::size_t(i)] = ENCLOSED;
  for(std::int64_t i = 0; i < cells; ++i) {
    const std::uint8_t g = grid[std::size_t(i)];
    if(g != OUTSIDE && g != ENCLOSED) continue;
    const std::int64_t x = i % sx, y = (i % sxy) / sx, z = i / sxy;
    if((x > 0 && grid[std::size_t(i - 1)] == WALL) || (x + 1 < dims[0] && grid[std::size_t(i + 1)] == WALL) ||
       (y > 0 && grid[std::size_t(i - sx)] == WALL) || (y + 1 < dims[1] && grid[std::size_t(i + sx)] == WALL) ||
       (z > 0 && grid[std::size_t(i - sxy)] == WALL) || (z + 1 < dims[2] && grid[std::size_t(i + sxy)] == WALL))
      queue.push_back(i);
  }
  spread(WALL);

  // the votes
  struct Exit {
    double distance;
    bool outside, found;
  };
  const auto exit_along = [&](const Vec<3>& q, const Vec<3>& d) {
    for(double t = 0; t <= reach; t += 0.5 * cell) {
      const std::int64_t i = index_of(q + t * d);
      if(i < 0) return Exit{t, true, true};
      const std::uint8_t g = grid[std::size_t(i)];
      if(g != NEAR) return Exit{t, g == OUTSIDE, true};
    }
    return Exit{reach, false, false};
  };
  for(std::size_t i = 0; i < n; ++i) {
    const Exit front = exit_along(p[i], m[i]), back = exit_along(p[i], -m[i]);
    const double sooner = back.distance - front.distance; // > 0: the band ends sooner in front
    if(front.outside && back.outside) {
      if(std::abs(sooner) >= spacing) votes[i] = sooner > 0 ? 1 : -1;
    } else if(front.outside != back.outside && (front.outside ? sooner : -sooner) > -spacing) {
      votes[i] = front.outside ? 1 : -1;
    }
  }
  return votes;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_OUTSIDE_VOTES_H
