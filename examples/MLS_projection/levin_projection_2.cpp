// Levin's MLS projection in 2D: a curve defined by noisy samples of a circle,
// with two function spaces for the second phase: the plane (here a line: the
// first phase alone) and quadratic polynomials over the frame.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/Random.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;

// The ambient dimension of an operator is the one of its function space.
using Line_projection = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Plane_function_space<2>>;
using Quadratic_projection = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Polynomial_function_space<2>>;

// The mean distance of the projections of `queries` to the unit circle; -1 if one fails.
template <class Projection>
double mean_error(const Projection& projection, const std::vector<Point_2>& queries)
{
  double sum = 0;
  for(const Point_2& q : queries) {
    const typename Projection::Result result = projection.project(q);
    if(!result.is_success()) {
      std::cerr << "projection of " << q << ": " << CGAL::MLS::to_string(result.status) << std::endl;
      return -1;
    }
    sum += std::abs(std::sqrt((result.point - CGAL::ORIGIN).squared_length()) - 1.);
  }
  return sum / double(queries.size());
}

int main()
{
  // 200 samples of the unit circle with a small radial noise (fixed seed).
  const double pi = std::acos(-1.);
  CGAL::Random random(7);
  std::vector<Point_2> points;
  for(int i = 0; i < 200; ++i) {
    const double angle = 2 * pi * i / 200., radius = 1. + random.get_double(-0.001, 0.001);
    points.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  // Queries inside and outside the curve.
  std::vector<Point_2> queries;
  for(int i = 0; i < 20; ++i) {
    const double angle = 0.3 + 2 * pi * i / 20., radius = (i % 2 == 0) ? 0.95 : 1.05;
    queries.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }

  // The same options for both: the default bandwidth (from the 6th nearest neighbours).
  const Line_projection line(points);
  const Quadratic_projection quadratic(points);
  std::cout << "bandwidth h = " << quadratic.bandwidth() << std::endl;

  const Quadratic_projection::Result r = quadratic.project(queries.front());
  std::cout << "query " << queries.front() << " -> point " << r.point << ", normal " << r.normal
            << ", status " << CGAL::MLS::to_string(r.status) << std::endl;

  // On a curved input the best line leaves the curve (a bias of order h^2 / R);
  // a quadratic follows the curvature.
  const double line_error = mean_error(line, queries);
  const double quadratic_error = mean_error(quadratic, queries);
  std::cout << "mean distance to the circle, line space:      " << line_error << "\n"
            << "mean distance to the circle, quadratic space: " << quadratic_error << std::endl;

  if(line_error < 0 || quadratic_error < 0 || quadratic_error > 1e-3 || quadratic_error >= line_error) {
    std::cerr << "unexpected errors" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
