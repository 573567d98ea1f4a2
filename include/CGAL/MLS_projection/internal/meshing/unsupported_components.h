// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_UNSUPPORTED_COMPONENTS_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_UNSUPPORTED_COMPONENTS_H

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

// Meshes that keep removed elements until a garbage collection (Surface_mesh) are collected, so
// that the caller's num_vertices() and num_faces() count the elements kept only.
template <class PolygonMesh>
auto collect_garbage_if_any(PolygonMesh& mesh, int) -> decltype(collect_garbage(mesh), void()) {
  collect_garbage(mesh);
}
template <class PolygonMesh>
void collect_garbage_if_any(PolygonMesh&, long) {}

/// Removes from `mesh` the connected components that do not pass through the data: those whose
/// median vertex distance to the data (`distance_to_data`, a function of a vertex's point) exceeds
/// `max_median`, and those whose bounding box has a diagonal shorter than `min_extent`. The MLS
/// surface is defined near its samples only; a closed component away from them is a bubble of the
/// implicit function's sign, not part of the sampled surface, and so is a component smaller than
/// the mesh's facets (Mesh_3 labels each cell by the sign at its circumcentre: next to the vertices
/// of protected polylines on a noisy surface, a tiny cell can be the only one on its side, a
/// closed component of 4 facets). When every component would go, the one nearest to the data
/// (smallest median) is kept. Returns the number of components removed.
template <class PolygonMesh, class DistanceToData>
std::size_t remove_unsupported_components(PolygonMesh& mesh, const DistanceToData& distance_to_data, double max_median,
                                          double min_extent) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t n = PMP::connected_components(mesh, component);
  if(n < 2) return 0;
  // each vertex counted once, in the component of any of its faces
  std::vector<std::vector<double>> distances(n);
  std::vector<Bbox_3> boxes(n);
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh)) {
    const auto h = halfedge(v, mesh);
    if(h == boost::graph_traits<PolygonMesh>::null_halfedge()) continue;
    face_descriptor f = face(h, mesh);
    if(f == boost::graph_traits<PolygonMesh>::null_face()) f = face(opposite(h, mesh), mesh);
    if(f == boost::graph_traits<PolygonMesh>::null_face()) continue;
    const auto& p = get(vpm, v);
    distances[get(component, f)].push_back(distance_to_data(p));
    boxes[get(component, f)] += p.bbox();
  }
  std::vector<double> median(n, std::numeric_limits<double>::infinity());
  for(std::size_t c = 0; c < n; ++c) {
    auto& d = distances[c];
    if(d.empty()) continue;
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    median[c] = d[d.size() / 2];
  }
  std::vector<std::size_t> removed;
  for(std::size_t c = 0; c < n; ++c) {
    const Bbox_3& b = boxes[c];
    const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
    if(!(median[c] <= max_median) || std::sqrt(dx * dx + dy * dy + dz * dz) < min_extent) removed.push_back(c);
  }
  if(removed.size() == n) {
    const std::size_t nearest = std::size_t(std::min_element(median.begin(), median.end()) - median.begin());
    removed.erase(removed.begin() + std::ptrdiff_t(nearest));
  }
  if(!removed.empty()) {
    PMP::remove_connected_components(mesh, removed, component);
    collect_garbage_if_any(mesh, 0);
  }
  return removed.size();
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_UNSUPPORTED_COMPONENTS_H
