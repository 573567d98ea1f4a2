// Finds the sharp creases and corners of the MLS surface of a point set (.xyz, .pwn, .ply or .off,
// normals not needed) with the mixed operator, and prints them.
//   detect_sharp_features [in.xyz]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/detect_sharp_features.h>
#include <CGAL/MLS_projection/project_points.h>

#include <cmath>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;

int main(int argc, char* argv[])
{
  const std::string input = argc > 1 ? argv[1] : "data/solid.xyz";
  std::vector<Point_3> points;
  if(!CGAL::IO::read_points(input, std::back_inserter(points))) {
    std::cerr << "cannot read " << input << std::endl;
    return 1;
  }
  // the features are read off the local fits of the samples' projections
  const CGAL::MLS::Mixed_projection<Kernel, 3> projection(points);
  std::vector<CGAL::MLS::Projection_result<Kernel, 3>> projected;
  CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(projection, points, std::back_inserter(projected));
  const auto features = CGAL::MLS::detect_sharp_features<CGAL::Parallel_if_available_tag>(projection, projected);

  std::cout << features.polylines.size() << " creases, " << features.corners.size() << " corners" << std::endl;
  for(const auto& line : features.polylines) {
    double length = 0;
    for(std::size_t i = 1; i < line.size(); ++i) length += std::sqrt(CGAL::squared_distance(line[i - 1], line[i]));
    std::cout << "crease of " << line.size() << " vertices, length " << length << ", from " << line.front() << " to "
              << line.back() << std::endl;
  }
  for(const Point_3& corner : features.corners) std::cout << "corner " << corner << std::endl;
  return features.polylines.empty() ? 1 : 0;
}
