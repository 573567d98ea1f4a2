// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_mesh: the reconstruction, of inputs with normals and of inputs without (the function then
// estimates and orients them), with the operator chosen on the command line; see
// <mls_tools/mesh_job.h>. The attribute maps are always passed (with 0 channels when the input
// has none): one instantiation per operator and normals.

#include <CGAL/MLS_projection/mls_surface_reconstruction.h>
#include <mls_tools/mesh_job.h>

#include <CGAL/property_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstddef>
#include <vector>

namespace {

using Index = std::size_t;

template <class OperatorTag, class NamedParameters>
bool reconstruct(const mls_tools::Mesh_input& input, mls_tools::Mesh& mesh, const mls_tools::Mesh_settings& s,
                 CGAL::MLS::Meshing_report& report, OperatorTag tag, const NamedParameters& maps) {
  std::vector<Index> indices(input.points.size());
  for(Index i = 0; i < indices.size(); ++i) indices[i] = i;
  const auto attributes = [&input](Index i) {
    const auto first = input.attributes.begin() + std::ptrdiff_t(i * input.channels);
    return std::vector<double>(first, first + std::ptrdiff_t(input.channels));
  };
  auto vertex_map =
    mesh.add_property_map<mls_tools::Mesh::Vertex_index, std::vector<double>>(mls_tools::vertex_attributes_property).first;
  return CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(
    indices, mesh,
    maps.attribute_map(boost::make_function_property_map<Index>(attributes))
      .vertex_attribute_map(vertex_map)
      .projection_operator(tag)
      .mesher(s.mesher)
      .features(s.features)
      .remove_outliers(s.remove_outliers)
      .open_surface(s.open_surface)
      .parallel_mesher(s.parallel_mesher)
      .facet_size(s.facet_size)
      .facet_distance(s.facet_distance)
      .neighbor_radius(s.bandwidth)
      .maximum_running_time(s.time_limit)
      .callback(s.callback)
      .report(report));
}

template <class NamedParameters>
bool reconstruct(const mls_tools::Mesh_input& input, mls_tools::Mesh& mesh, const mls_tools::Mesh_settings& s,
                 CGAL::MLS::Meshing_report& report, const NamedParameters& maps) {
  using namespace CGAL::MLS;
  using C = mls_tools::Operator_choice;
  switch(s.projection_operator) {
  case C::LEVIN_PLANE: return reconstruct(input, mesh, s, report, Levin_operator_tag<Plane_function_space<3>>(), maps);
  case C::LEVIN_QUADRATIC:
    return reconstruct(input, mesh, s, report, Levin_operator_tag<Polynomial_function_space<3>>(), maps);
  case C::UNIFIED_PLANE: return reconstruct(input, mesh, s, report, Unified_operator_tag<Plane_function_space<3>>(), maps);
  case C::UNIFIED_QUADRATIC:
    return reconstruct(input, mesh, s, report, Unified_operator_tag<Paraboloid_function_space<3>>(), maps);
  case C::UNIFIED_WEDGE:
    return reconstruct(input, mesh, s, report, Unified_operator_tag<Wedge_fan_function_space<3>>(), maps);
  case C::MIXED: break;
  }
  return reconstruct(input, mesh, s, report, Mixed_operator_tag(), maps);
}

} // namespace

bool mls_tools::reconstruct_with_normals(const Mesh_input& input, Mesh& mesh, const Mesh_settings& settings,
                                         CGAL::MLS::Meshing_report& report) {
  return reconstruct(
    input, mesh, settings, report,
    CGAL::MLS::parameters::point_map(boost::make_function_property_map<Index>([&input](Index i) { return input.points[i].first; }))
      .normal_map(boost::make_function_property_map<Index>([&input](Index i) { return input.points[i].second; })));
}

bool mls_tools::reconstruct_without_normals(const Mesh_input& input, Mesh& mesh, const Mesh_settings& settings,
                                            CGAL::MLS::Meshing_report& report) {
  return reconstruct(
    input, mesh, settings, report,
    CGAL::MLS::parameters::point_map(boost::make_function_property_map<Index>([&input](Index i) { return input.points[i].first; })));
}
