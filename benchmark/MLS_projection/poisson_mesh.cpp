// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The meshing baseline of scan_benchmark.py: CGAL's Poisson surface reconstruction of a point set
// without normals, as a CGAL user runs it (CGAL's Poisson example): normals by PCA on 18
// neighbours oriented by a minimum spanning tree (the estimation mls_mesh uses), then
// poisson_surface_reconstruction_delaunay with the average spacing (6 neighbours).
//
//   poisson_mesh POINTS.xyz OUT.off
//
// Writes OUT.off only on success; exit status 1 and a message on stderr otherwise.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <fstream>
#include <iostream>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Item = std::pair<Point, Vector>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Point_map = CGAL::First_of_pair_property_map<Item>;
using Normal_map = CGAL::Second_of_pair_property_map<Item>;

int main(int argc, char** argv) {
  if(argc != 3) {
    std::cerr << "usage: poisson_mesh POINTS.xyz OUT.off\n";
    return 2;
  }
  std::vector<Item> points;
  if(!CGAL::IO::read_points(argv[1], std::back_inserter(points),
                            CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())) ||
     points.size() < 10) {
    std::cerr << "poisson_mesh: cannot read points from " << argv[1] << "\n";
    return 1;
  }
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  CGAL::pca_estimate_normals<CGAL::Parallel_if_available_tag>(points, 18, np);
  points.erase(CGAL::mst_orient_normals(points, 18, np), points.end());
  const double spacing =
    CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(points, 6, CGAL::parameters::point_map(Point_map()));
  Polyhedron mesh;
  if(!CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), Point_map(), Normal_map(), mesh,
                                                    spacing)) {
    std::cerr << "poisson_mesh: the reconstruction failed\n";
    return 1;
  }
  std::ofstream out(argv[2]);
  out.precision(17);
  if(!CGAL::IO::write_OFF(out, mesh)) {
    std::cerr << "poisson_mesh: cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
