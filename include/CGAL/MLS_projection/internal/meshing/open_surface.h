// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The meshing of an open scan: the closed boundary of a slab under the surface, within reach of
// the data, is meshed; its facets on the surface are kept, clipped where the data end.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_OPEN_SURFACE_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_OPEN_SURFACE_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/MLS_projection/internal/meshing/mesher_calls.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The slab under an open surface \f$f = 0\f$: the points below it (\f$-T < f < 0\f$, \f$T\f$ =
/// `depth`) whose distance \f$d\f$ to the nearest input point is less than \f$R\f$ (`reach`,
/// larger than \f$T\f$ plus the spacing, so that the data do not pierce the slab). Its boundary
/// is the surface where \f$d < R\f$, a wall \f$d = R\f$ from the surface's border down to the
/// back, and the back \f$f = -T\f$.
struct Open_surface_slab {
  double depth = 0;
  double reach = 0;

  /// The slab's function, negative inside, given \f$f\f$ and \f$d\f$ at a point.
  double value(double f, double d) const { return (std::max)({f, -depth - f, d - reach}); }

  /// Whether \f$f\f$ at the centroid of a boundary facet puts it on the surface, not on the back.
  bool on_surface(double f) const { return std::abs(f) < 0.5 * depth; }
};

/// Clips the triangle mesh `mesh` to the faces where `keep(face)` holds, cut along the level set
/// \f$\ell = 0\f$ of the vertex values `level(point)`, keeping \f$\ell \le 0\f$: a face with
/// some vertices on each side keeps a triangle or a quadrilateral (two triangles), whose new
/// vertices are `place(p)` at the point \f$p\f$ of an edge where the linear interpolation of \f$\ell\f$
/// vanishes (one per edge, shared by its two faces). Values within `snap` of 0 count as 0, so
/// the level set passes through the vertices near it instead of cutting slivers beside them. The
/// vertices where the faces kept meet at a point only are split (so the result is a manifold with
/// boundary). Returns the number of faces of the result.
template <class PolygonMesh, class Keep, class Level, class Place>
std::size_t clip_mesh(PolygonMesh& mesh, const Keep& keep, const Level& level, const Place& place, double snap) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, vertex_point_t>::type>::value_type;
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<Point> points;
  std::vector<double> values; // of the points (0 at the cuts)
  std::unordered_map<vertex_descriptor, std::size_t> index;
  const auto point_of = [&](vertex_descriptor v) {
    const auto [it, added] = index.emplace(v, points.size());
    if(added) {
      points.push_back(get(vpm, v));
      const double l = level(points.back());
      values.push_back(std::abs(l) <= snap ? 0. : l);
    }
    return it->second;
  };
  // the point of edge (a, b), a inside and b outside, where the level vanishes
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> cuts;
  const auto cut = [&](std::size_t a, std::size_t b) {
    if(values[a] == 0) return a;
    const auto [it, added] = cuts.emplace(std::make_pair((std::min)(a, b), (std::max)(a, b)), points.size());
    if(added) {
      const double t = values[a] / (values[a] - values[b]);
      points.push_back(place(points[a] + t * (points[b] - points[a])));
      values.push_back(0.);
    }
    return it->second;
  };
  std::vector<std::array<std::size_t, 3>> triangles;
  const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    if(a != b && b != c && c != a) triangles.push_back({a, b, c});
  };
  for(auto f : faces(mesh)) {
    if(!keep(f)) continue;
    std::array<std::size_t, 3> t;
    int n = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      if(n < 3) t[std::size_t(n++)] = point_of(v);
    if(n != 3) continue;
    int inside = 0;
    for(std::size_t i : t) inside += values[i] <= 0 ? 1 : 0;
    if(inside == 3) add(t[0], t[1], t[2]);
    if(inside == 0 || inside == 3) continue;
    // rotate (keeping the orientation) so that t[0] is the vertex alone on its side
    while((values[t[0]] <= 0) == (values[t[1]] <= 0) || (values[t[1]] <= 0) != (values[t[2]] <= 0))
      std::rotate(t.begin(), t.begin() + 1, t.end());
    if(inside == 1) {
      add(t[0], cut(t[0], t[1]), cut(t[0], t[2]));
    } else {
      const std::size_t c1 = cut(t[1], t[0]), c2 = cut(t[2], t[0]);
      add(c1, t[1], t[2]);
      add(c1, t[2], c2);
    }
  }
  // the points of the triangles only (not the outer vertices of the faces cut)
  std::vector<std::size_t> used(points.size(), points.size());
  std::vector<Point> kept;
  for(auto& t : triangles)
    for(std::size_t& i : t) {
      if(used[i] == points.size()) {
        used[i] = kept.size();
        kept.push_back(points[i]);
      }
      i = used[i];
    }
  points = std::move(kept);
  PMP::orient_polygon_soup(points, triangles); // duplicates the vertices where the faces meet at a point
  clear_mesh(mesh);
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return triangles.size();
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_OPEN_SURFACE_H
