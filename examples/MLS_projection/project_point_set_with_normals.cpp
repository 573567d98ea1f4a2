// Projects a point set with normals onto its own MLS surface, in parallel when TBB
// is available, with two operators sharing one sample set (and its kd-tree).
// The points and normals are stored as pairs and read through property maps.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Random.h>
#include <CGAL/tags.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;
using Point_with_normal = std::pair<Point_3, Vector_3>;
using Point_map = CGAL::First_of_pair_property_map<Point_with_normal>;
using Normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>;

using Sample_set = CGAL::MLS::Sample_set<Kernel, 3>;
using Plane_projection = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Plane_function_space<3>>;
using Quadratic_projection = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Polynomial_function_space<3>>;

const double R = 1.0, r = 0.4; // the radii of the torus

// The distance from p to the torus.
double distance_to_torus(const Point_3& p)
{
  const double rho = std::sqrt(p.x() * p.x() + p.y() * p.y()) - R;
  return std::abs(std::sqrt(rho * rho + p.z() * p.z()) - r);
}

// Projects every input point with `projection`, in parallel if available; checks that every
// projection succeeds with a normal agreeing with the input normal, within `tolerance` of the torus.
template <class Projection>
bool project_all(const Projection& projection, const std::vector<Point_with_normal>& input, const char* name,
                 double tolerance)
{
  std::vector<typename Projection::Result> results;
  results.reserve(input.size());
  std::cout << name << ":" << std::flush;
  const bool done = CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(
    projection, input, std::back_inserter(results),
    CGAL::parameters::point_map(Point_map())
      .callback([](double fraction) {
        std::cout << " " << int(100 * fraction) << "%" << std::flush;
        return true; // false would cancel
      }));
  std::cout << std::endl;
  if(!done || results.size() != input.size()) return false;

  double sum = 0, worst = 0;
  for(std::size_t i = 0; i < input.size(); ++i) {
    const auto& res = results[i];
    if(!res.is_success() || res.normal * input[i].second < 0.9) {
      std::cerr << "  point " << i << ": " << CGAL::MLS::to_string(res.status) << ", normal " << res.normal
                << std::endl;
      return false;
    }
    const double d = distance_to_torus(res.point);
    sum += d;
    worst = (std::max)(worst, d);
  }
  std::cout << "  distance to the torus: mean " << sum / double(input.size()) << ", max " << worst << std::endl;
  return worst < tolerance;
}

int main()
{
  // 6000 points of a torus with their normals, moved along the normal by up to 0.5% (fixed seed).
  const double pi = std::acos(-1.);
  CGAL::Random random(1);
  std::vector<Point_with_normal> input;
  for(int i = 0; i < 6000; ++i) {
    const double u = random.get_double(0, 2 * pi), v = random.get_double(0, 2 * pi);
    const Vector_3 normal(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
    const Point_3 centre(R * std::cos(u), R * std::sin(u), 0.);
    input.emplace_back(centre + (r + random.get_double(-0.002, 0.002)) * normal, normal);
  }

  // One sample set for both operators: the points and normals are copied and the
  // kd-tree is built once. Input normals orient the results.
  const auto samples = std::make_shared<const Sample_set>(
    input, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));

  const Plane_projection plane(samples);
  const Quadratic_projection quadratic(samples);
  std::cout << samples->size() << " points, bandwidth h = " << quadratic.bandwidth() << std::endl;

  // The plane leaves a curved surface by O(h^2 curvature); a quadratic follows it.
  const bool ok = project_all(plane, input, "plane space", 0.03) &&
                  project_all(quadratic, input, "quadratic space", 0.005);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
