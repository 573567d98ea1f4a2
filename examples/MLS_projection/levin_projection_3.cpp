// Levin's MLS projection of a few points onto the surface defined by a noisy
// sampled sphere, with the default function space (quadratic polynomials).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/point_generators_3.h>
#include <CGAL/Random.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;

// Levin's two-phase projection; the second template parameter, the function space,
// defaults to CGAL::MLS::Polynomial_function_space<3> (quadratics over the frame).
using Projection = CGAL::MLS::Levin_projection<Kernel>;

int main()
{
  // 2000 points on the unit sphere, moved along the radius by up to 1% (fixed seed).
  CGAL::Random random(42);
  CGAL::Random_points_on_sphere_3<Point_3> on_sphere(1.0, random);
  std::vector<Point_3> points;
  for(int i = 0; i < 2000; ++i, ++on_sphere) {
    const Vector_3 v = *on_sphere - CGAL::ORIGIN;
    points.push_back(CGAL::ORIGIN + (1. + random.get_double(-0.01, 0.01)) * v);
  }

  // Builds the kd-tree once; the bandwidth h is derived from the sampling density.
  Projection projection(points);
  std::cout << "bandwidth h = " << projection.bandwidth() << std::endl;

  const std::vector<Point_3> queries = {
    Point_3(1.2, 0., 0.), Point_3(0., 0.9, 0.1), Point_3(-0.5, -0.5, 0.6), Point_3(0.3, -0.2, -1.1)};

  int failures = 0;
  for(const Point_3& q : queries) {
    const Projection::Result result = projection.project(q);
    std::cout << "query " << q << "\n  point  " << result.point << "\n  normal " << result.normal
              << "\n  status " << CGAL::MLS::to_string(result.status) << std::endl;

    // The projection must succeed, land on the sphere (up to the noise) and have an
    // outward normal: without input normals, normals point away from the centroid.
    const Vector_3 radial = result.point - CGAL::ORIGIN;
    const double radius = std::sqrt(radial.squared_length());
    if(!result.is_success() || std::abs(radius - 1.) > 0.01 || result.normal * radial < 0.99 * radius) {
      std::cerr << "  unexpected result (|p| = " << radius << ")" << std::endl;
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
