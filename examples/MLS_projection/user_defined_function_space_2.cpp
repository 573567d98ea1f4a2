// A user-defined prior: the function space of circles, plugged into the unified projection P_U.
//
// A model of the concept `MLSFunctionSpace` describes its members in a local frame (first
// coordinate along the frame's tangent, second along its normal); every member passes through
// the frame origin. Here a member is the circle of signed curvature k tangent to the tangent
// axis at the origin (its centre at (0, 1/k); k = 0 is the tangent line itself). P_U moves and
// turns the frame, so the operator reaches every circle of the plane, and samples of a circle
// are reproduced exactly: their energy is zero for the true circle. The quadratic space only
// approximates a circle (k x^2 is its osculating parabola), to the order of (h k)^2 h.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Vec2 = Eigen::Vector2d;

class Circle_function_space {
public:
  static constexpr int ambient_dimension = 2;
  static constexpr int number_of_parameters = 1; // the signed curvature k
  using Parameters = Eigen::Matrix<double, 1, 1>;

  static const char* name() { return "circle"; }
  // the curvature plus the frame's three parameters (origin and angle)
  static constexpr std::size_t minimum_number_of_points() { return 4; }

  Parameters identity() const { return Parameters::Zero(); }

  // The initial member: the weighted least-squares osculating parabola y = k x^2 / 2.
  Parameters fit(const Vec2* p, const double* w, std::size_t n) const {
    double num = 0, den = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const double x2 = p[i][0] * p[i][0];
      num += w[i] * x2 * p[i][1];
      den += w[i] * x2 * x2;
    }
    Parameters c;
    c[0] = den > 0 ? 2 * num / den : 0.;
    return c;
  }

  // The closest point on the circle, its normal on the side of +e_2 at the origin, and the
  // signed distance (positive on the side of the normal). Finite for any finite input: a query
  // at the centre takes the origin.
  CGAL::MLS::Closest_point<2> closest_point(const Parameters& c, const Vec2& x) const {
    CGAL::MLS::Closest_point<2> cp;
    const double k = c[0];
    if(std::abs(k) < 1e-12) { // the tangent line
      cp.point = Vec2(x[0], 0);
      cp.normal = Vec2(0, 1);
    } else {
      const Vec2 centre(0, 1 / k);
      const Vec2 v = x - centre;
      const double d = v.norm();
      cp.point = d > 0 ? Vec2(centre + v / (d * std::abs(k))) : Vec2(0, 0);
      cp.normal = (k > 0 ? 1. : -1.) * (centre - cp.point) * std::abs(k); // towards the centre when k > 0
    }
    cp.signed_distance = (x - cp.point).dot(cp.normal);
    return cp;
  }
};

// The largest distance of the projections of `queries` to the circle of radius `R` at the
// origin; -1 if a projection fails.
template <class Projection>
double max_error(const Projection& projection, const std::vector<Point_2>& queries, double R) {
  double worst = 0;
  for(const Point_2& q : queries) {
    const auto result = projection.project(q);
    if(!result.is_success()) {
      std::cerr << "projection of " << q << ": " << CGAL::MLS::to_string(result.status) << std::endl;
      return -1;
    }
    worst = (std::max)(worst, std::abs(std::hypot(result.point.x(), result.point.y()) - R));
  }
  return worst;
}

int main() {
  // 200 samples of a circle of radius 0.3, irregularly spaced; queries off the circle
  const double R = 0.3;
  std::vector<Point_2> samples, queries;
  for(int i = 0; i < 200; ++i) {
    const double t = 2 * CGAL_PI * (i + 0.3 * std::sin(7. * i)) / 200;
    samples.emplace_back(R * std::cos(t), R * std::sin(t));
  }
  for(int i = 0; i < 50; ++i) {
    const double t = 0.37 * i, r = R * (1 + 0.05 * std::sin(3. * i));
    queries.emplace_back(r * std::cos(t), r * std::sin(t));
  }

  CGAL::MLS::Projection_options options;
  options.weight = CGAL::MLS::Weight_kind::WENDLAND; // compact support: every weighted sample lies on the circle
  const CGAL::MLS::Unified_projection<Kernel, Circle_function_space> with_circles(samples, options);
  const CGAL::MLS::Unified_projection<Kernel, CGAL::MLS::Paraboloid_function_space<2>> with_parabolas(
      with_circles.shared_samples(), options);

  const double h = with_circles.bandwidth();
  const double e_circle = max_error(with_circles, queries, R);
  const double e_quadratic = max_error(with_parabolas, queries, R);
  std::cout << "bandwidth h = " << h << "\n"
            << "P_U, circles:   max distance to the circle " << e_circle / h << " h\n"
            << "P_U, quadratic: max distance to the circle " << e_quadratic / h << " h\n";
  // the circle prior reproduces the circle to rounding; the quadratic one does not
  return (e_circle >= 0 && e_circle < 1e-9 * h && e_quadratic > e_circle) ? EXIT_SUCCESS : EXIT_FAILURE;
}
