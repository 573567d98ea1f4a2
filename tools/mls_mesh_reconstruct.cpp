// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_mesh: the reconstruction, of inputs with normals and of inputs without (the function then
// estimates and orients them); see <mls_tools/mesh_job.h>. The attribute maps are always passed
// (with 0 channels when the input has none): one instantiation of the whole reconstruction each.

#include <CGAL/MLS_projection/mls_surface_reconstruction.h>
#include <mls_tools/mesh_job.h>

#include <CGAL/property_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstddef>
#include <vector>

namespace {

using Index = std::size_t;

template <class NamedParameters>
bool reconstruct(const mls_tools::Mesh_input& input, mls_tools::Mesh& mesh, const CGAL::MLS::Meshing_options& options,
                 const NamedParameters& np) {
  std::vector<Index> indices(input.points.size());
  for(Index i = 0; i < indices.size(); ++i) indices[i] = i;
  const auto attributes = [&input](Index i) {
    const auto first = input.attributes.begin() + std::ptrdiff_t(i * input.channels);
    return std::vector<double>(first, first + std::ptrdiff_t(input.channels));
  };
  auto vertex_map =
    mesh.add_property_map<mls_tools::Mesh::Vertex_index, std::vector<double>>(mls_tools::vertex_attributes_property).first;
  return CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(
    indices, mesh, options,
    CGAL::MLS::parameters::vertex_attribute_map(
      vertex_map, CGAL::MLS::parameters::attribute_map(boost::make_function_property_map<Index>(attributes), np(input))));
}

} // namespace

bool mls_tools::reconstruct_with_normals(const Mesh_input& input, Mesh& mesh, const CGAL::MLS::Meshing_options& options) {
  return reconstruct(input, mesh, options, [](const Mesh_input& in) {
    return CGAL::parameters::point_map(boost::make_function_property_map<Index>([&in](Index i) { return in.points[i].first; }))
      .normal_map(boost::make_function_property_map<Index>([&in](Index i) { return in.points[i].second; }));
  });
}

bool mls_tools::reconstruct_without_normals(const Mesh_input& input, Mesh& mesh, const CGAL::MLS::Meshing_options& options) {
  return reconstruct(input, mesh, options, [](const Mesh_input& in) {
    return CGAL::parameters::point_map(boost::make_function_property_map<Index>([&in](Index i) { return in.points[i].first; }));
  });
}
