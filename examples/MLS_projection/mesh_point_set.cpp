// Meshes a point set (.xyz, .pwn, .ply or .off, normals not needed) with the package's defaults:
// the unified operator with the mixed space, creases and corners protected, Mesh_3.
//   mesh_point_set [in.xyz] [out.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/MLS_projection/mls_surface_reconstruction.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

int main(int argc, char* argv[])
{
  const std::string input = argc > 1 ? argv[1] : "data/solid.xyz";
  const std::string output = argc > 2 ? argv[2] : "solid.off";
  std::vector<Point_3> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  Mesh mesh;
  if(!CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(points, mesh)) {
    std::cerr << "meshing failed" << std::endl;
    return 1;
  }
  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << "cannot write " << output << std::endl;
    return 1;
  }
  std::cout << points.size() << " points, " << mesh.number_of_faces() << " facets written to " << output << std::endl;
  return 0;
}
