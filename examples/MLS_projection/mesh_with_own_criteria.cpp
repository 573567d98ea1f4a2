// Meshes the MLS surface of a point set (.xyz, .pwn, .ply or .off, normals not needed) with
// CGAL's make_mesh_3 on the package's mesh domain, with the program's own criteria: facets of
// about the bandwidth, creases and corners protected.
//   mesh_with_own_criteria [in.xyz] [out.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/MLS_projection/MLS_implicit_function.h>
#include <CGAL/MLS_projection/MLS_mesh_domain_3.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Projection = CGAL::MLS::Mixed_projection<Kernel, 3>;
using Function = CGAL::MLS::MLS_implicit_function<Projection>;
using Domain = CGAL::MLS::MLS_mesh_domain_3<Kernel>;
using Tr = CGAL::Mesh_triangulation_3<Domain>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
namespace params = CGAL::parameters;

int main(int argc, char* argv[])
{
  const std::string input = argc > 1 ? argv[1] : "data/solid.xyz";
  const std::string output = argc > 2 ? argv[2] : "solid.off";
  std::vector<Point_3> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  // the implicit function (normals estimated and oriented), the domain with its sharp features
  const Function function{Projection(points), CGAL::MLS::Implicit_function_options(), CGAL::Parallel_if_available_tag()};
  const double h = function.bandwidth();
  const Domain domain(function, CGAL::MLS::parameters::facet_distance(0.1 * h));
  if(!domain.is_closed()) {
    std::cerr << "the points do not bound a volume" << std::endl;
    return 1;
  }
  const CGAL::Mesh_criteria_3<Tr> criteria(params::edge_size = 0.75 * h, params::facet_angle = 25,
                                           params::facet_size = h, params::facet_distance = 0.1 * h);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude(), params::manifold());

  CGAL::Surface_mesh<Point_3> mesh;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, mesh);
  if(!CGAL::IO::write_polygon_mesh(output, mesh, params::stream_precision(17))) {
    std::cerr << "cannot write " << output << std::endl;
    return 1;
  }
  std::cout << domain.feature_polylines().size() << " creases protected, " << mesh.number_of_faces()
            << " facets written to " << output << std::endl;
  return 0;
}
