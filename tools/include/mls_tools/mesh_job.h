// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The interface between the command line of mls_mesh (tools/mls_mesh.cpp) and the translation
// unit calling CGAL::MLS::mls_surface_reconstruction() (tools/mls_mesh_reconstruct.cpp), which
// instantiates every operator, function space and mesher. One unit for inputs with and without
// normals: the two calls share those instantiations (as two units, each would compile all of
// them).

#ifndef MLS_TOOLS_MESH_JOB_H
#define MLS_TOOLS_MESH_JOB_H

#include <CGAL/MLS_projection/Meshing_options.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
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

/// mls_surface_reconstruction<Parallel_if_available_tag> of the points with their normals.
bool reconstruct_with_normals(const Mesh_input& input, Mesh& mesh, const CGAL::MLS::Meshing_options& options);
/// The same, the normals (the pairs' second members) ignored: estimated and oriented by the
/// function.
bool reconstruct_without_normals(const Mesh_input& input, Mesh& mesh, const CGAL::MLS::Meshing_options& options);

} // namespace mls_tools

#endif // MLS_TOOLS_MESH_JOB_H
