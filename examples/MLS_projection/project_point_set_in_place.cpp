// Projects a point set (.xyz, .pwn, .ply or .off, normals not needed) onto its own MLS surface, in
// place, with the mixed operator: noise is smoothed and creases stay sharp.
//   project_point_set_in_place [in.xyz] [out.xyz]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/MLS_projection/mls_project_point_set.h>

#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;

int main(int argc, char* argv[])
{
  const std::string input = argc > 1 ? argv[1] : "data/solid.xyz";
  const std::string output = argc > 2 ? argv[2] : "projected.xyz";
  std::vector<Point_3> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  const std::size_t projected = CGAL::MLS::mls_project_point_set<CGAL::Parallel_if_available_tag>(points);
  if(!CGAL::IO::write_points(output, points, CGAL::parameters::stream_precision(17))) {
    std::cerr << "cannot write " << output << std::endl;
    return 1;
  }
  std::cout << projected << " of " << points.size() << " points projected, written to " << output << std::endl;
  return projected == points.size() ? 0 : 1;
}
