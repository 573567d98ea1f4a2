// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESH_ATTRIBUTES_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESH_ATTRIBUTES_H

#include <CGAL/MLS_projection/interpolate_attributes.h>
#include <CGAL/MLS_projection/internal/projection/Point_tree.h>
#include <CGAL/MLS_projection/project_points.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// A range of attribute values stored contiguously (the value of an attribute map).
struct Attribute_span {
  const double* first = nullptr;
  const double* last = nullptr;
  const double* begin() const { return first; }
  const double* end() const { return last; }
};

/// The attributes of every vertex of `mesh`, in the order of `vertices(mesh)`, interpolated on the
/// local fit of the nearest of the projected `seeds` (results of `projection`; see
/// `interpolate_attributes()`): the fit that placed the surface there. Empty when the samples
/// have no attribute.
template <class ConcurrencyTag, class Projection, class PolygonMesh>
std::vector<std::vector<double>> interpolate_vertex_attributes(const Projection& projection,
                                                               const std::vector<typename Projection::Result>& seeds,
                                                               const PolygonMesh& mesh) {
  const auto& samples = projection.samples();
  if(samples.number_of_attributes() == 0 || seeds.empty()) return {};
  std::vector<Vec<3>> seed_points(seeds.size());
  for(std::size_t i = 0; i < seeds.size(); ++i) seed_points[i] = samples.to_local(seeds[i].point);
  const Point_tree<3> tree(seed_points);
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  std::vector<vertex_descriptor> vs;
  for(vertex_descriptor v : vertices(mesh)) vs.push_back(v);
  std::vector<std::vector<double>> values(vs.size());
  const auto vpm = get(vertex_point, mesh);
  for_each_index<ConcurrencyTag>(0, vs.size(), 64, [&](std::size_t i) {
    thread_local std::vector<std::pair<double, std::size_t>> found;
    const auto& p = get(vpm, vs[i]);
    const typename Projection::Point x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    tree.k_nearest(samples.to_local(x), 1, found);
    values[i].reserve(samples.number_of_attributes());
    interpolate_attributes(projection, seeds[found.front().second], x, std::back_inserter(values[i]));
  });
  return values;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESH_ATTRIBUTES_H
