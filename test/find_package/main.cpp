// Consumer of the installed MLS_projection package (see run.cmake): projects a
// point on the MLS surface of a few samples of the plane z = 0.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;

int main()
{
  std::vector<Point_3> points;
  for(int i = -5; i <= 5; ++i)
    for(int j = -5; j <= 5; ++j)
      points.emplace_back(0.1 * i, 0.1 * j, 0.);

  const CGAL::MLS::Levin_projection<Kernel> projection(points);
  const auto result = projection.project(Point_3(0.05, -0.02, 0.3));
  std::cout << "point " << result.point << ", normal " << result.normal << ", status "
            << CGAL::MLS::to_string(result.status) << std::endl;

  const bool ok = result.is_success() && std::abs(result.point.z()) < 1e-6 &&
                  std::abs(result.point.x() - 0.05) < 1e-6 && std::abs(result.point.y() + 0.02) < 1e-6 &&
                  std::abs(std::abs(result.normal.z()) - 1.) < 1e-6;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
