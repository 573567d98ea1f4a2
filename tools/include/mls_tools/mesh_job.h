// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The interface between the command line of mls_mesh (tools/mls_mesh.cpp) and the translation
// unit calling CGAL::MLS::mls_surface_reconstruction() (tools/mls_mesh_reconstruct.cpp), which
// instantiates it for every operator and function space, with and without normals.

#ifndef MLS_TOOLS_MESH_JOB_H
#define MLS_TOOLS_MESH_JOB_H

#include <CGAL/MLS_projection/Meshing_report.h>
#include <CGAL/MLS_projection/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace mls_tools {

using Mesh_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Mesh_kernel::Point_3>;
using Point_with_normal = std::pair<Mesh_kernel::Point_3, Mesh_kernel::Vector_3>;

/// What the reconstruction reads: the points with their normals, and `channels` attribute values
/// per point (none when `channels` is 0).
struct Mesh_input {
  std::vector<Point_with_normal> points;
  std::size_t channels = 0;
  std::vector<double> attributes;
};

/// The name of the mesh's vertex property (`std::vector<double>`) holding the vertices'
/// attributes, written by the reconstruction when the input has attributes.
constexpr const char* vertex_attributes_property = "v:attributes";

/// The projection operators of `--operator` and `--space`.
enum class Operator_choice { LEVIN_PLANE, LEVIN_QUADRATIC, UNIFIED_PLANE, UNIFIED_QUADRATIC, UNIFIED_WEDGE, MIXED };

/// The named parameters of mls_surface_reconstruction() that the tool sets (lengths and times:
/// 0 for the library's default).
struct Mesh_settings {
  Operator_choice projection_operator = Operator_choice::MIXED;
  CGAL::MLS::Mesher mesher = CGAL::MLS::Mesher::MESH_3;
  bool features = true, remove_outliers = true, open_surface = false, parallel_mesher = false;
  double facet_size = 0, facet_distance = 0, bandwidth = 0, time_limit = 0;
  std::function<bool(double)> callback;
};

/// mls_surface_reconstruction<Parallel_if_available_tag> of the points with their normals.
bool reconstruct_with_normals(const Mesh_input& input, Mesh& mesh, const Mesh_settings& settings,
                              CGAL::MLS::Meshing_report& report);
/// The same, the normals (the pairs' second members) ignored: estimated and oriented by the
/// function.
bool reconstruct_without_normals(const Mesh_input& input, Mesh& mesh, const Mesh_settings& settings,
                                 CGAL::MLS::Meshing_report& report);

} // namespace mls_tools

#endif // MLS_TOOLS_MESH_JOB_H
