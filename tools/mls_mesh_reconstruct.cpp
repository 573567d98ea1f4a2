// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_mesh: the reconstruction, of inputs with normals and of inputs without (the function then
// estimates and orients them); see <mls_tools/mesh_job.h>.

#include <CGAL/MLS_projection/mls_surface_reconstruction.h>
#include <mls_tools/mesh_job.h>

#include <CGAL/property_map.h>

bool mls_tools::reconstruct_with_normals(const std::vector<Point_with_normal>& points, Mesh& mesh,
                                         const CGAL::MLS::Meshing_options& options) {
  return CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(
    points, mesh, options,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
}

bool mls_tools::reconstruct_without_normals(const std::vector<Point_with_normal>& points, Mesh& mesh,
                                            const CGAL::MLS::Meshing_options& options) {
  return CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(
    points, mesh, options, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>()));
}
