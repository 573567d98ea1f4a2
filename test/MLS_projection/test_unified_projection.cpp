// Tests of the closest-point operators P_S, P_E and P_U (sections 3.2-3.4 of the paper) with the
// plane, quadratic and wedge-fan function spaces.
//
// Exactness. A noiseless sample of a member of F has zero energy for the exact frame and
// function under any weight; with Wendland's compactly supported weight every point in the
// support lies on the member, so the exact fit is a global minimum with zero residuals, and
// Levenberg-Marquardt converges quadratically to it: the projections must lie on the true shape
// to 1e-9 of the shape's size (1 here; about 3e-8 h; the optimiser's tolerance is 1e-12 on
// relative steps, and the closest points of the frame's parameters carry a few ulps of the
// coordinates). Anything larger is an optimiser failure (a wrong local minimum), which is what
// these tests are for.

#include "test_framework.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/mls_project_point_set.h>
#include <CGAL/MLS_projection/project_points.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <random>
#include <utility>
#include <vector>

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SC = CGAL::Simple_cartesian<double>;
namespace MLS = CGAL::MLS;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

namespace {

MLS::Projection_options wendland() {
  MLS::Projection_options o;
  o.weight = MLS::Weight_kind::WENDLAND;
  return o;
}

// A 2D wedge with opening angle phi, apex at the origin, bisector +y, rays sampled every `s` to
// length L. Distance of a point to it.
struct Wedge_2 {
  double phi, s = 0.01, L = 1.;
  V2 ray(int side) const { return V2(side * std::sin(phi / 2), std::cos(phi / 2)); }
  std::vector<SC::Point_2> sample() const {
    std::vector<SC::Point_2> pts{SC::Point_2(0, 0)};
    for(double t = s; t <= L + 1e-12; t += s)
      for(int side : {-1, 1}) pts.emplace_back(t * ray(side)[0], t * ray(side)[1]);
    return pts;
  }
  double distance(const V2& x) const {
    double d = x.norm();
    for(int side : {-1, 1}) {
      const double t = x.dot(ray(side));
      if(t > 0) d = std::min(d, (x - t * ray(side)).norm());
    }
    return d;
  }
};

// A 3D edge: two half-planes meeting along the x axis with dihedral angle `phi`, symmetric about
// the plane y = 0, bisector +z; sampled on a grid of spacing s.
struct Edge_3 {
  double phi, s = 0.02, L = 0.6;
  V3 face(int side) const { return V3(0, side * std::sin(phi / 2), std::cos(phi / 2)); }
  std::vector<Epick::Point_3> sample() const {
    std::vector<Epick::Point_3> pts;
    for(double x = -L; x <= L + 1e-12; x += s) {
      pts.emplace_back(x, 0, 0);
      for(double t = s; t <= L + 1e-12; t += s)
        for(int side : {-1, 1}) {
          const V3 p = V3(x, 0, 0) + t * face(side);
          pts.emplace_back(p[0], p[1], p[2]);
        }
    }
    return pts;
  }
  double distance(const V3& p) const {
    double d = V2(p[1], p[2]).norm();
    for(int side : {-1, 1}) {
      const double t = p.dot(face(side));
      if(t > 0) d = std::min(d, (p - t * face(side) - V3(p[0], 0, 0)).norm());
    }
    return d;
  }
};

V2 eig(const SC::Point_2& p) { return V2(p.x(), p.y()); }
V3 eig(const Epick::Point_3& p) { return V3(p.x(), p.y(), p.z()); }
V3 eig(const Epick::Vector_3& p) { return V3(p.x(), p.y(), p.z()); }

} // namespace

// ---------------------------------------------------------------------------------------------

MLS_TEST(unified_with_plane_agrees_with_levin) {
  std::vector<Epick::Point_3> pts;
  std::mt19937 gen(3);
  std::normal_distribution<double> g, noise(0, 0.01);
  for(int i = 0; i < 3000; ++i) {
    const V3 d = mls_test::random_vector(g, gen).normalized();
    const V3 p = d + mls_test::random_vector(noise, gen);
    pts.emplace_back(p[0], p[1], p[2]);
  }
  MLS::Levin_projection<Epick, MLS::Plane_function_space<3>> PL(pts);
  MLS::Unified_projection<Epick, MLS::Plane_function_space<3>> PU(PL.shared_samples());
  const double h = PL.bandwidth();
  double worst = 0;
  int apart = 0;
  for(int i = 0; i < 60; ++i) {
    const V3 direction = mls_test::random_vector(g, gen).normalized();
    const V3 d = direction * (1 + 0.05 * g(gen));
    const Epick::Point_3 r(d[0], d[1], d[2]);
    const auto a = PL.project(r), b = PU.project(r);
    MLS_CHECK(a.is_success() && b.status == MLS::Projection_status::CONVERGED);
    const double distance = (eig(a.point) - eig(b.point)).norm() / h;
    if(distance > 1e-5) {
      ++apart;
      std::cout << "  query " << i << " (|r| = " << d.norm() << "): P_U(plane) " << distance << " h from P_L\n";
    } else {
      worst = std::max(worst, distance);
    }
  }
  // Both minimise the same energy (with the plane, C(r) is the foot of r on the frame); they stop
  // within the optimisers' tolerance in the flat valleys of noisy data.
  MLS_CHECK_LE(worst, 1e-5);
  // Query 40 (0.048 off the sphere) has its C(r) in a gap of the random sampling, 0.62 h from the
  // nearest foot: the support test once rejected Levin's start there, and P_U(plane) stopped
  // 1.5 h away, off the surface.
  MLS_CHECK(apart == 0);
}

MLS_TEST(wedge_2d_is_reproduced_exactly) {
  for(const double degrees : {60., 120.}) {
    const Wedge_2 wedge{degrees * CGAL_PI / 180};
    const auto pts = wedge.sample();
    MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PU(pts, wendland());
    const double h = PU.bandwidth();
    double worst = 0;
    int on_apex = 0;
    for(int i = 0; i < 200; ++i) {
      const double t = -0.3 + 0.6 * i / 199; // along the x axis, crossing the apex region
      for(const double y : {-0.02, 0.0, 0.03}) {
        const V2 x = V2(t, std::abs(t) / std::tan(wedge.phi / 2) + y);
        const auto res = PU.project(SC::Point_2(x[0], x[1]));
        MLS_CHECK(res.is_success());
        worst = std::max(worst, wedge.distance(eig(res.point)));
        if(res.is_on_feature) {
          ++on_apex;
          MLS_CHECK_LE(eig(res.point).norm(), 1e-9);
        }
      }
    }
    std::cout << "  2D wedge " << degrees << " deg: max distance " << worst / h << " h, " << on_apex << " on the apex\n";
    MLS_CHECK_LE(worst, 1e-9);
    MLS_CHECK(on_apex > 0);
  }
}

// The apex of a 2D wedge at any opening angle, from both sides: every query on a grid of step h/10
// within 1.5 h of the wedge and 3 h of its apex, inside the wedge and on its reflex side below the
// apex, with either weight. Before the plane split also tried the minor axis, the 30-degree wedge
// had 278 of 1388 queries off (up to 1.4 h) and the 50-degree one 58 of 1507 on its reflex side
// (up to 1.5 h): Levin's frame and the turned one are no start for a narrow wedge.
// The bound is 1e-8 h, not the 1e-9 h of the other exactness tests: with Wendland's weight, for
// queries about 2 h from a 150-degree apex along a ray, the support's edge just reaches the apex,
// the points that pin it weigh almost nothing (the weight vanishes to fourth order), and the
// optimiser stops at an energy of 2.5e-11 h^2, 8.9e-10 h off (measured; the same before this test).
MLS_TEST(wedge_2d_apex_at_any_opening_angle) {
  for(const bool gaussian : {true, false})
    for(const double degrees : {20., 30., 50., 90., 150.}) {
      const Wedge_2 wedge{degrees * CGAL_PI / 180};
      const auto pts = wedge.sample();
      MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PU(pts, gaussian ? MLS::Projection_options() : wendland());
      const double h = PU.bandwidth();
      double worst = 0;
      int n = 0;
      for(int i = -30; i <= 30; ++i)
        for(int j = -30; j <= 30; ++j) {
          const V2 x(0.1 * i * h, 0.1 * j * h);
          if(x.norm() > 3 * h || wedge.distance(x) > 1.5 * h) continue;
          ++n;
          const auto res = PU.project(SC::Point_2(x[0], x[1]));
          MLS_CHECK(res.is_success());
          worst = std::max(worst, wedge.distance(eig(res.point)));
        }
      std::cout << "  " << (gaussian ? "Gaussian" : "Wendland") << ", " << degrees << " deg, " << n
                << " queries: max distance " << worst / h << " h\n";
      MLS_CHECK_LE(worst, 1e-8 * h);
    }
}

MLS_TEST(apex_ball_collapses_onto_apex) {
  // Figure 4: points in the normal cone of the apex (between the two ray normals) project onto it.
  const Wedge_2 wedge{CGAL_PI / 2};
  const auto pts = wedge.sample();
  MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PU(pts, wendland());
  for(const double a : {-0.3, 0.0, 0.3})
    for(const double rad : {0.01, 0.03}) {
      const auto res = PU.project(SC::Point_2(rad * std::sin(a), -rad * std::cos(a)));
      MLS_CHECK(res.is_success() && res.is_on_feature);
      MLS_CHECK_LE(eig(res.point).norm(), 1e-9);
    }
}

MLS_TEST(edge_3d_is_reproduced_exactly) {
  for(const double degrees : {60., 90., 120.}) {
    const Edge_3 edge{degrees * CGAL_PI / 180};
    const auto pts = edge.sample();
    MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts, wendland());
    const double h = PU.bandwidth();
    double worst = 0;
    int on_crease = 0;
    for(int i = 0; i < 60; ++i) {
      const double y = -0.2 + 0.4 * i / 59;
      const V3 x(0.05 * std::sin(i), y, std::abs(y) / std::tan(edge.phi / 2) + 0.01 * std::cos(3. * i));
      const auto res = PU.project(Epick::Point_3(x[0], x[1], x[2]));
      MLS_CHECK(res.is_success());
      worst = std::max(worst, edge.distance(eig(res.point)));
      if(res.is_on_feature) {
        ++on_crease;
        MLS_CHECK_LE(V2(res.point.y(), res.point.z()).norm(), 1e-9);
        MLS_CHECK_NEAR(std::abs(res.feature_direction.x()), 1., 1e-9);
      }
    }
    // the collapse ball of the crease (section 3.3, Figure 4): below the valley's crease, within
    // the cone of the two face normals, every point projects onto the crease itself
    for(const double delta : {0.005, 0.02})
      for(const double y : {-0.3 * delta, 0.0, 0.3 * delta}) {
        const auto res = PU.project(Epick::Point_3(0.1 * delta, y, -delta));
        MLS_CHECK(res.is_success() && res.is_on_feature);
        MLS_CHECK_LE(V2(res.point.y(), res.point.z()).norm(), 1e-9);
        MLS_CHECK_NEAR(res.point.x(), 0.1 * delta, 1e-9);
        MLS_CHECK_NEAR(std::abs(res.feature_direction.x()), 1., 1e-9);
      }
    std::cout << "  3D edge " << degrees << " deg: max distance " << worst / h << " h, " << on_crease << " on the crease\n";
    // 11 parameters and a forward-difference Jacobian: measured up to 9e-9 of the model's size
    MLS_CHECK_LE(worst, 2e-8);
  }
}

// Every query of a dense grid across the crease (spacing h/10 in the plane normal to it, within
// 0.5 h of the edge and 3 h of the crease) projects onto the edge. Sparser lines missed the wrong
// minima this grid found before the fix (see on_a_piece_with_data() in the operator): exact fans
// whose C(r) lies on a cone bridging the faces, selected 0.092 h off at 45 degrees, and stalled
// fits preferred to the exact one (up to 7.7e-6 h off at 60 degrees). From 2 to 3 h of the
// crease, where it lies at the edge of the weight's support, fits stalled near the exact fan until
// the optimiser's scaling got its floor and the feature starts the planes' member (measured
// before: 12 of 5940 queries within 6 h of the crease at 30 to 120 degrees off by more than
// 1e-8 h, at most 2.8e-6 h at 120 degrees, 2.2 h from the crease; after: none, at most 1.2e-13 h).
MLS_TEST(edge_3d_is_reproduced_exactly_on_a_dense_grid_across_the_crease) {
  // the Gaussian weight at 60 degrees only: its one failure measured before the fix
  const std::pair<MLS::Weight_kind, double> cases[] = {{MLS::Weight_kind::WENDLAND, 45.},
                                                       {MLS::Weight_kind::WENDLAND, 60.},
                                                       {MLS::Weight_kind::WENDLAND, 120.},
                                                       {MLS::Weight_kind::GAUSSIAN, 60.}};
  for(const auto& [weight, degrees] : cases) {
    const Edge_3 edge{degrees * CGAL_PI / 180};
    MLS::Projection_options o;
    o.weight = weight;
    MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(edge.sample(), o);
    const double h = PU.bandwidth();
    double worst = 0;
    int queries = 0;
    for(int a = -30; a <= 30; ++a)
      for(int b = -30; b <= 30; ++b) {
        const V3 q(0.013, 0.1 * h * a, 0.1 * h * b);
        if(edge.distance(q) > 0.5 * h || V2(q[1], q[2]).norm() > 3 * h) continue;
        ++queries;
        const auto res = PU.project(Epick::Point_3(q[0], q[1], q[2]));
        MLS_CHECK(res.is_success());
        worst = std::max(worst, edge.distance(eig(res.point)));
      }
    std::cout << "  " << degrees << " deg edge, " << (weight == MLS::Weight_kind::GAUSSIAN ? "Gaussian" : "Wendland")
              << ", " << queries << " queries: max distance " << worst / h << " h\n";
    MLS_CHECK_LE(worst, 1e-9);
  }
}

// A bandwidth just above the sample spacing: on a grid, C(r) can then be further than h/2 from
// every sample's closest point while lying on the data (between samples). The support test must
// accept it, or the exact fit is discarded for a wrong one (measured before the fix: 0.09 h with
// the Gaussian, 0.23 h with Wendland).
MLS_TEST(edge_3d_is_reproduced_exactly_with_a_bandwidth_near_the_spacing) {
  std::vector<Epick::Point_3> pts;
  for(int i = -10; i <= 10; ++i)
    for(int j = -10; j <= 10; ++j) pts.emplace_back(0.1 * i, 0.1 * j, -std::abs(0.1 * i));
  for(const MLS::Weight_kind weight : {MLS::Weight_kind::GAUSSIAN, MLS::Weight_kind::WENDLAND}) {
    MLS::Projection_options o;
    o.weight = weight;
    o.bandwidth = 0.12;
    MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts, o);
    double worst = 0;
    for(int i = 0; i < 41; ++i) {
      const double x = -0.5 + 0.025 * i, y = 0.3 * std::sin(1.7 * i);
      const auto res = PU.project(Epick::Point_3(x, y, -std::abs(x) + 0.03 * std::cos(2.3 * i)));
      MLS_CHECK(res.is_success());
      const V3 p = eig(res.point);
      worst = std::max(worst, std::abs(std::abs(p[0]) + p[2]) / std::sqrt(2.));
    }
    std::cout << "  90 deg edge, h = 1.2 spacings: max distance " << worst / 0.12 << " h\n";
    MLS_CHECK_LE(worst, 2e-8);
  }
}

namespace {

// A cube [-0.5, 0.5]^3 sampled on each face with a regular grid of spacing s (edges and corners
// included once).
std::vector<Epick::Point_3> cube(double s) {
  std::vector<Epick::Point_3> pts;
  const int n = int(std::lround(1. / s));
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
      for(int k = 0; k <= n; ++k)
        if(i == 0 || i == n || j == 0 || j == n || k == 0 || k == n) pts.emplace_back(-0.5 + i * s, -0.5 + j * s, -0.5 + k * s);
  return pts;
}
// n points of the unit sphere on a Fibonacci lattice.
std::vector<Epick::Point_3> fibonacci_sphere(int n) {
  std::vector<Epick::Point_3> sphere;
  for(int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.) / n, rho = std::sqrt(1 - z * z), a = i * CGAL_PI * (3 - std::sqrt(5.));
    sphere.emplace_back(rho * std::cos(a), rho * std::sin(a), z);
  }
  return sphere;
}
double cube_distance(const V3& p) {
  const V3 q = p.cwiseAbs() - V3::Constant(0.5);
  const double outside = q.cwiseMax(0.).norm();
  return outside > 0 ? outside : -q.maxCoeff();
}

} // namespace

// mls_project_point_set(): the points and normals of a set projected in place, with the default
// operator (Mixed_projection) on the set itself. The cube sampled at 0.05 with its points moved by
// +-0.01 (a fifth of the spacing, alternating) along the face normals, each point's normal
// given as its outward direction from the centre: every point is projected, to the results of
// project_points() with Mixed_projection on the same samples, bit for bit; the noise is smoothed:
// the RMS distance to the cube falls below 0.7 times its value (measured 0.0098 to 0.0055: the
// quadratic of weights of width h, about 2 spacings, follows a part of the checkerboard, the
// bump centred on the query; Levin's quadratic, far from the edges, leaves the same 0.58, and near
// the edges, where it rounds them, 0.0099); the normals are unit and outward. A cancelling
// callback leaves the set as it was.
MLS_TEST(mls_project_point_set_in_place) {
  using Item = std::pair<Epick::Point_3, Epick::Vector_3>;
  std::vector<Item> items;
  int k = 0;
  for(const auto& p : cube(0.05)) {
    const V3 q = eig(p), n = q.normalized();
    const V3 face = q.cwiseAbs().maxCoeff() == std::abs(q[0]) ? V3(q[0] > 0 ? 1 : -1, 0, 0)
                    : q.cwiseAbs().maxCoeff() == std::abs(q[1]) ? V3(0, q[1] > 0 ? 1 : -1, 0)
                                                                 : V3(0, 0, q[2] > 0 ? 1 : -1);
    const V3 moved = q + (k++ % 2 ? 0.01 : -0.01) * face;
    items.emplace_back(Epick::Point_3(moved[0], moved[1], moved[2]), Epick::Vector_3(n[0], n[1], n[2]));
  }
  const auto np = MLS::parameters::point_map(CGAL::First_of_pair_property_map<Item>())
                    .normal_map(CGAL::Second_of_pair_property_map<Item>());
  const auto rms = [](const std::vector<Item>& set) {
    double s2 = 0;
    for(const Item& i : set) s2 += std::pow(cube_distance(eig(i.first)), 2);
    return std::sqrt(s2 / double(set.size()));
  };
  const MLS::Mixed_projection<Epick, 3> PM(items, MLS::Projection_options(), np);
  std::vector<MLS::Projection_result<Epick, 3>> expected;
  MLS::project_points<CGAL::Sequential_tag>(PM, items, std::back_inserter(expected), np);

  std::vector<Item> cancelled = items;
  MLS_CHECK(MLS::mls_project_point_set<CGAL::Parallel_if_available_tag>(
              cancelled, np.callback(std::function<bool(double)>([](double) { return false; }))) == 0);
  MLS_CHECK(cancelled == items);

  std::vector<Item> projected = items;
  MLS_CHECK(MLS::mls_project_point_set<CGAL::Parallel_if_available_tag>(projected, np) == items.size());
  std::size_t differ = 0, inward = 0;
  for(std::size_t i = 0; i < items.size(); ++i) {
    if(projected[i].first != expected[i].point || projected[i].second != expected[i].normal) ++differ;
    if(!(std::abs(eig(projected[i].second).norm() - 1) < 1e-12 && eig(projected[i].second).dot(eig(items[i].first)) > 0)) ++inward;
  }
  std::cout << "  in place: RMS distance to the cube " << rms(items) << " -> " << rms(projected) << std::endl;
  MLS_CHECK_MSG(differ == 0, std::to_string(differ) + " points differ from project_points");
  MLS_CHECK(inward == 0);
  MLS_CHECK_LE(rms(projected), 0.7 * rms(items));
}

MLS_TEST(cube_corner_and_edges_are_reproduced_exactly) {
  const auto pts = cube(0.025);
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts, wendland());
  const double h = PU.bandwidth();
  double worst = 0;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-0.5, 0.5), off(-0.3, 0.3);
  int corner = 0, edge = 0;
  // queries near the corner (0.5, 0.5, 0.5), near the edge x = y = 0.5, and on faces
  for(int i = 0; i < 40; ++i) {
    V3 x;
    const V3 a = mls_test::random_vector(off, gen), b = mls_test::random_vector(u, gen);
    if(i < 15) x = V3(0.5, 0.5, 0.5) + 0.5 * h * a;
    else if(i < 30) x = V3(0.5 + 0.3 * h * a[0], 0.5 + 0.3 * h * a[1], 0.4 * b[2]);
    else x = V3(0.5 + 0.3 * h * a[0], 0.4 * b[1], 0.4 * b[2]);
    const auto res = PU.project(Epick::Point_3(x[0], x[1], x[2]));
    MLS_CHECK(res.is_success());
    const V3 p = eig(res.point);
    worst = std::max(worst, std::abs(cube_distance(p)));
    if(res.is_on_feature && res.feature_direction == CGAL::NULL_VECTOR) {
      ++corner;
      MLS_CHECK_LE((p - V3(0.5, 0.5, 0.5)).norm(), 1e-9);
    } else if(res.is_on_feature) {
      ++edge;
      // on one of the three edges through the corner region, along the right axis
      const V3 d = eig(res.feature_direction).cwiseAbs();
      const int axis = d[0] > 0.5 ? 0 : (d[1] > 0.5 ? 1 : 2);
      MLS_CHECK_NEAR(d[axis], 1., 1e-9);
      for(int j = 0; j < 3; ++j)
        if(j != axis) MLS_CHECK_NEAR(std::abs(p[j]), 0.5, 1e-9);
    } else if(i >= 15 && i < 30) {
      // points near the edge that land on a face: normal is that face's
      const V3 n = eig(res.normal).cwiseAbs();
      MLS_CHECK(std::abs(n[0] - 1) < 1e-9 || std::abs(n[1] - 1) < 1e-9);
    }
  }
  // the corner's collapse ball: points outside the corner, in the cone of the three face normals
  for(const V3& d : {V3(1, 1, 1), V3(1, 0.8, 0.9), V3(0.9, 1, 0.7)}) {
    const auto res = PU.project(Epick::Point_3(0.5 + 0.01 * d[0], 0.5 + 0.01 * d[1], 0.5 + 0.01 * d[2]));
    MLS_CHECK(res.is_success() && res.is_on_feature);
    MLS_CHECK_LE((eig(res.point) - V3(0.5, 0.5, 0.5)).norm(), 1e-9);
  }
  std::cout << "  cube: max distance " << worst << " (h = " << h << "), " << corner << " at the corner, " << edge << " on edges\n";
  MLS_CHECK_LE(worst, 1e-9);
  MLS_CHECK(edge > 0);
}

// The benchmark's noiseless cube (15000 random points on the faces, the benchmark's generator and
// seed, default options): its input point 7454, 0.3 h from an edge, once projected 6.3e-7 h off
// its face. The race's leader, a corner fan, stopped at 4.8e-7 h^2 while Levin's frame, second
// in the race, reached the exact fan; since the leader's rivals run to convergence when it nearly
// fits the data, the exact fan is found (see the manual, "Rivals of a near-exact leader").
MLS_TEST(race_leader_near_exact_is_checked_against_its_rivals) {
  std::mt19937_64 engine(20260101); // specified output: the same points on every platform
  const auto uniform = [&engine] { return double(engine() >> 11) * (1.0 / 9007199254740992.0); };
  std::vector<Epick::Point_3> pts;
  while(pts.size() < 15000) {
    const int face = std::min(5, int(6 * uniform()));
    double c[3];
    c[face / 2] = face % 2 == 0 ? -0.5 : 0.5;
    c[(face / 2 + 1) % 3] = uniform() - 0.5;
    c[(face / 2 + 2) % 3] = uniform() - 0.5;
    pts.emplace_back(c[0], c[1], c[2]);
  }
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts);
  const auto res = PU.project(pts[7454]);
  MLS_CHECK(res.is_success());
  const double d = std::abs(cube_distance(eig(res.point)));
  std::cout << "  benchmark cube, input point 7454: " << d / PU.bandwidth() << " h off\n";
  MLS_CHECK_LE(d, 1e-9);
}

MLS_TEST(paraboloid_is_reproduced_exactly_by_quadratic_space) {
  // z = 0.8 x^2 - 0.5 y^2 rotated about z by 0.4 (the space's own rotation), tilted and moved:
  // a member of the quadratic space in some frame.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.6, V3(1, -2, 0.5).normalized()).toRotationMatrix();
  const V3 T(0.3, -1, 2);
  const auto f = [](double x, double y) {
    const double xr = std::cos(0.4) * x + std::sin(0.4) * y, yr = -std::sin(0.4) * x + std::cos(0.4) * y;
    return 0.8 * xr * xr - 0.5 * yr * yr;
  };
  std::vector<Epick::Point_3> pts;
  for(int i = -30; i <= 30; ++i)
    for(int j = -30; j <= 30; ++j) {
      const double x = 0.02 * i + 0.005 * std::sin(7. * j), y = 0.02 * j + 0.005 * std::cos(5. * i);
      const V3 p = R * V3(x, y, f(x, y)) + T;
      pts.emplace_back(p[0], p[1], p[2]);
    }
  // Far from the vertex (queries up to 7h from it) the frame's origin must travel to the vertex
  // along a long, flat valley of the energy: Levenberg-Marquardt needs about 600 iterations to
  // reach machine precision there (with the default budget it stops with NOT_CONVERGED about
  // 1e-6 from the surface), hence the larger budget of this test.
  MLS::Projection_options options = wendland();
  options.max_evaluations = 4000;
  MLS::Unified_projection<Epick, MLS::Paraboloid_function_space<3>> PU(pts, options);
  double worst = 0;
  for(int i = 0; i < 40; ++i) {
    const double x = 0.3 * std::sin(1.7 * i), y = 0.3 * std::cos(1.1 * i);
    const V3 q = R * V3(x, y, f(x, y) + 0.01 * std::sin(3. * i)) + T;
    const auto res = PU.project(Epick::Point_3(q[0], q[1], q[2]));
    MLS_CHECK(res.status == MLS::Projection_status::CONVERGED);
    const V3 p = R.transpose() * (eig(res.point) - T);
    worst = std::max(worst, std::abs(p[2] - f(p[0], p[1])));
  }
  std::cout << "  paraboloid: max |z - f(x, y)| " << worst << "\n";
  MLS_CHECK_LE(worst, 1e-9);
}

// Section 3.2 and Figure 1: near the apex of a noiselessly sampled sharp wedge, Levin's frame
// cannot fit both rays and P_L pulls projections away from the data (the pinch); P_U with the
// wedge space reproduces the apex, and P_U with the quadratic space rounds the corner instead.
// Queries: a grid of step h/10 in the band within 0.3 h of the wedge and 2 h of its apex (default
// weight and bandwidth). Measured (max distance to the wedge): P_L 0.317 h at 60 degrees and
// 0.128 h at 120, P_U quadratic 0.120 h and 0.097 h, P_U wedge 4e-13 h and 1e-13 h. At 30 degrees
// P_U quadratic 0.106 h against P_L's 0.369 h (P_U wedge: wedge_2d_apex_at_any_opening_angle).
MLS_TEST(pinch_is_gone_near_a_sharp_2d_apex) {
  for(const double degrees : {60., 120.}) {
    const Wedge_2 wedge{degrees * CGAL_PI / 180};
    const auto pts = wedge.sample();
    MLS::Levin_projection<SC, MLS::Polynomial_function_space<2>> PL(pts);
    MLS::Unified_projection<SC, MLS::Paraboloid_function_space<2>> PQ(PL.shared_samples());
    MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PW(PL.shared_samples());
    const double h = PL.bandwidth();
    double worst_L = 0, worst_Q = 0, worst_W = 0;
    int n = 0;
    for(double x = -2 * h; x <= 2 * h; x += 0.1 * h)
      for(double y = -h; y <= 2.5 * h; y += 0.1 * h) {
        if(V2(x, y).norm() > 2 * h || wedge.distance(V2(x, y)) > 0.3 * h) continue;
        ++n;
        const SC::Point_2 q(x, y);
        const auto rL = PL.project(q), rQ = PQ.project(q), rW = PW.project(q);
        MLS_CHECK(rL.is_success() && rQ.is_success() && rW.is_success());
        worst_L = std::max(worst_L, wedge.distance(eig(rL.point)));
        worst_Q = std::max(worst_Q, wedge.distance(eig(rQ.point)));
        worst_W = std::max(worst_W, wedge.distance(eig(rW.point)));
      }
    std::cout << "  " << degrees << " deg, " << n << " queries near the apex: max distance P_L " << worst_L / h << " h, P_U quadratic "
              << worst_Q / h << " h, P_U wedge " << worst_W / h << " h\n";
    MLS_CHECK_LE(worst_W, 1e-9 * h);
    MLS_CHECK_LE(worst_Q, 0.15 * h);
    MLS_CHECK(worst_Q < 0.8 * worst_L);
    if(degrees < 90) MLS_CHECK(worst_L > 0.25 * h); // the pinch this test is about
  }
}

// Invariance under rigid motions and uniform scaling: sampled members of the spaces (a cube for
// the fan, a paraboloid for the quadratic), moved by x -> s R x + t, project queries moved the
// same way onto the moved projections (relative to the moved size: 1e-9, the exactness bound).
// On samples of shapes outside the space (a cylinder's rim with the fan), P_U is only
// approximately invariant: the manual gives the measured figures.
MLS_TEST(invariance_under_rigid_motions_and_scaling) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, V3(1, 2, 3).normalized()).toRotationMatrix();
  const V3 t(3, -2, 5);
  const auto moved = [&](const std::vector<Epick::Point_3>& pts, double s) {
    std::vector<Epick::Point_3> out;
    for(const auto& p : pts) {
      const V3 x = s * (R * eig(p) + t);
      out.emplace_back(x[0], x[1], x[2]);
    }
    return out;
  };
  std::vector<Epick::Point_3> queries;
  for(int i = 0; i < 12; ++i) queries.emplace_back(0.5 + 0.02 * std::sin(i), 0.48 + 0.03 * std::cos(2. * i), 0.5 - 0.3 * i / 11.);
  std::vector<Epick::Point_3> paraboloid, pq;
  for(int i = -20; i <= 20; ++i)
    for(int j = -20; j <= 20; ++j) paraboloid.emplace_back(0.025 * i, 0.025 * j, 0.8 * (0.025 * i) * (0.025 * i) - 0.3 * (0.025 * j) * (0.025 * j));
  for(int i = 0; i < 12; ++i) pq.emplace_back(0.2 * std::sin(1.3 * i), 0.2 * std::cos(0.7 * i), 0.02 * std::sin(2. * i));
  const auto check = [&](auto make, const std::vector<Epick::Point_3>& pts, const std::vector<Epick::Point_3>& qs, const char* name) {
    const auto P = make(pts);
    for(const double s : {1., 1e-3, 1e3}) {
      const auto Q = make(moved(pts, s));
      const auto mq = moved(qs, s);
      double worst = 0;
      for(std::size_t i = 0; i < qs.size(); ++i) {
        const auto a = P.project(qs[i]), b = Q.project(mq[i]);
        MLS_CHECK(a.is_success() && b.is_success());
        worst = std::max(worst, (s * (R * eig(a.point) + t) - eig(b.point)).norm() / s);
      }
      std::cout << "  " << name << ", scale " << s << ": max |P(sRx + t) - (sRP(x) + t)| / s = " << worst << "\n";
      MLS_CHECK_LE(worst, 1e-9);
    }
  };
  check([](const auto& p) { return MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>>(p, wendland()); }, cube(0.05), queries,
        "P_U wedge, cube");
  MLS::Projection_options long_budget = wendland(); // see paraboloid_is_reproduced_exactly_by_quadratic_space
  long_budget.max_evaluations = 4000;
  check([&](const auto& p) { return MLS::Unified_projection<Epick, MLS::Paraboloid_function_space<3>>(p, long_budget); }, paraboloid, pq,
        "P_U quadratic, paraboloid");
}

// On noisy data the minimum of a projection depends on the path of its optimisation; the path is
// the same in a rotated copy when the starts and the parameters turn with the data (the start
// frames' tangent axes from the data, the origin's offsets along the start's axes). Cube of 6000
// points with noise sigma = 0.003 (0.043 h), 100 cold projections of P_U wedge near its edges,
// rotated and moved as above. Measured: median difference 1.7e-7 h, max 0.089 h, 14 of 100 over
// 0.1 sigma (other minima: the race's selection is not stable under rounding); with the tangent
// axes of `tangent_basis()` (from the coordinate axes) and offsets along the coordinate axes
// (d29d649): median 4.8e-3 h, max 0.17 h, 53 of 100. (Warm starts follow a Hilbert curve in the
// coordinates, whose order changes with the rotation: see the manual.)
MLS_TEST(rotation_invariance_on_a_noisy_cube) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, V3(1, 2, 3).normalized()).toRotationMatrix();
  const V3 t(3, -2, 5);
  const double sigma = 0.003;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::normal_distribution<double> noise(0., sigma);
  std::vector<Epick::Point_3> pts, moved_pts, queries;
  const auto on_face = [&](int i, double margin) {
    V3 x(u(gen), u(gen), u(gen));
    x[(i % 6) / 2] = (i % 2) ? 0.5 : -0.5;
    if(margin > 0) { // near an edge of the face
      const int o = ((i % 6) / 2 + 1) % 3;
      x[o] = (x[o] > 0 ? 1 : -1) * (0.5 - margin * std::abs(u(gen)));
    }
    return x;
  };
  for(int i = 0; i < 6000; ++i) {
    const V3 x = on_face(i, 0) + V3(noise(gen), noise(gen), noise(gen));
    pts.emplace_back(x[0], x[1], x[2]);
    const V3 y = R * x + t;
    moved_pts.emplace_back(y[0], y[1], y[2]);
  }
  for(int i = 0; i < 100; ++i) {
    const V3 x = on_face(i, 0.08) + 0.02 * V3(u(gen), u(gen), u(gen));
    queries.emplace_back(x[0], x[1], x[2]);
  }
  using Wedge = MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>>;
  const Wedge P(pts, MLS::Projection_options()), Q(moved_pts, MLS::Projection_options());
  const double h = P.bandwidth();
  std::vector<double> d;
  for(const auto& q : queries) {
    const V3 y = R * eig(q) + t;
    const auto a = P.project(q), b = Q.project(Epick::Point_3(y[0], y[1], y[2]));
    MLS_CHECK(a.is_success() && b.is_success());
    d.push_back((R * eig(a.point) + t - eig(b.point)).norm() / h);
  }
  std::sort(d.begin(), d.end());
  const auto over = std::count_if(d.begin(), d.end(), [&](double x) { return x > 0.1 * sigma / h; });
  std::cout << "  h " << h << ": |P(Rx + t) - (RP(x) + t)| median " << d[d.size() / 2] << " h, max " << d.back() << " h; "
            << over << " of " << d.size() << " over 0.1 sigma" << std::endl;
  // the optimiser's watch stops a fit when C(r) moves by less than 1e-5 h over its window: two
  // runs of the same path stop within that
  MLS_CHECK_LE(d[d.size() / 2], 1e-5);
  MLS_CHECK_LE(over, 20);
}

MLS_TEST(continuity_along_a_line_of_queries) {
  // A dense line of queries crossing a 2D wedge's apex region and running along its rays:
  // consecutive projections move by at most a small multiple of the query spacing, except
  // where the line crosses the apex's collapse ball (projections equal there) or leaves it.
  for(const double degrees : {60., 120.}) {
    const Wedge_2 wedge{degrees * CGAL_PI / 180};
    const auto pts = wedge.sample();
    MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PU(pts, wendland());
    MLS::Unified_projection<SC, MLS::Paraboloid_function_space<2>> PQ(PU.shared_samples());
    const double step = 0.3 / 400;
    for(int space = 0; space < 2; ++space) {
      V2 previous;
      double worst_jump = 0;
      for(int i = 0; i <= 400; ++i) {
        const double t = -0.15 + i * step;
        const V2 x(t, std::abs(t) / std::tan(wedge.phi / 2) + 0.01);
        const auto res = space == 0 ? PU.project(SC::Point_2(x[0], x[1])) : PQ.project(SC::Point_2(x[0], x[1]));
        MLS_CHECK(res.is_success());
        const V2 p = eig(res.point);
        // the collapse ball ends where the query's foot on a ray leaves the apex: allow that one jump
        if(i > 0 && std::abs(t) > 0.05) worst_jump = std::max(worst_jump, (p - previous).norm() / step);
        previous = p;
      }
      std::cout << "  " << degrees << " deg, " << (space == 0 ? "wedge" : "quadratic")
                << ": largest move between consecutive projections " << worst_jump << " query steps\n";
      MLS_CHECK_LE(worst_jump, 3.);
    }
  }
}

MLS_TEST(projection_property_of_the_closest_point_operators) {
  // Noisy circle (sigma = 0.07 h) for the smooth spaces; the noiseless 2D wedge for the wedge
  // space (on noisy samples the wedge space fits kinks to the noise: see the manual).
  // Section 3.5's argument holds for C_{H,f} (r' on the segment [r, C(r)] has the same closest
  // point, so the same minimiser), but with noise the minimum lies in a flat valley along which
  // the optimiser crawls; it stops when 10 improving steps move C(r) by less than 1e-5 h or 1%
  // of the RMS residual (see Closest_point_projection::minimize), so the optimisations from r and
  // from r' stop apart: measured 2.1e-4 h for P_U (1.3e-3 h with the 1e-5 h test alone, 3.3e-4 h
  // when every crawl runs to its end, at 2 to 3 times the cost), 5.9e-5 h for P_S (Levin's
  // projection drifts 5e-5 h on noisy data for another reason, see test_levin_projection),
  // against a noise of 0.07 h. 5e-3 h still catches any jump to a
  // different local minimum, which moves by a sizeable fraction of h.
  std::mt19937 gen(9);
  std::normal_distribution<double> noise(0, 0.003);
  std::vector<SC::Point_2> pts;
  for(int i = 0; i < 500; ++i) {
    const double t = 2 * CGAL_PI * i / 500;
    const V2 e = mls_test::random_vector<2>(noise, gen);
    pts.emplace_back(std::cos(t) + e[0], std::sin(t) + e[1]);
  }
  const auto wedge_pts = Wedge_2{CGAL_PI / 2}.sample();
  MLS::Unified_projection<SC, MLS::Paraboloid_function_space<2>> PU(pts);
  MLS::Enriched_projection<SC, MLS::Paraboloid_function_space<2>> PE(PU.shared_samples());
  MLS::Single_phase_projection<SC, MLS::Paraboloid_function_space<2>> PS(PU.shared_samples());
  MLS::Unified_projection<SC, MLS::Wedge_fan_function_space<2>> PW(wedge_pts);
  double worst[4] = {0, 0, 0, 0};
  for(int i = 0; i < 40; ++i) {
    int k = 0;
    const auto check = [&](const auto& P, const SC::Point_2& r) {
      const auto a = P.project(r);
      const auto b = P.project(a.point);
      MLS_CHECK(a.is_success() && b.is_success());
      worst[k] = std::max(worst[k], (eig(a.point) - eig(b.point)).norm() / P.bandwidth());
      ++k;
    };
    const double t = 0.05 + 2 * CGAL_PI * i / 40, rad = 1 + 0.3 * PU.bandwidth() * std::sin(5. * i);
    const SC::Point_2 r(rad * std::cos(t), rad * std::sin(t));
    check(PU, r);
    check(PE, r);
    check(PS, r);
    const double x = -0.2 + 0.4 * i / 39;
    check(PW, SC::Point_2(x, std::abs(x) + 0.01 * std::sin(3. * i)));
  }
  std::cout << "  |P(P(r)) - P(r)| / h: unified " << worst[0] << ", enriched " << worst[1] << ", single-phase "
            << worst[2] << ", unified wedge (exact wedge) " << worst[3] << "\n";
  for(int k = 0; k < 3; ++k) MLS_CHECK_LE(worst[k], 5e-3);
  MLS_CHECK_LE(worst[3], 1e-8);
}

// The mixed space's screening and complexity penalty: on a sampled cube near edges and corners it
// keeps the fan (the closest-point operator's fit) and is as exact as P_U(wedge); on a noiseless
// sphere P_L's quadratic explains the data and is kept.
MLS_TEST(mixed_space_keeps_the_fan_at_creases_and_the_quadratic_elsewhere) {
  {
    const auto pts = cube(0.025);
    MLS::Mixed_projection<Epick, 3> PM(pts, wendland());
    const double h = PM.bandwidth();
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> u(-0.4, 0.4), off(-0.3, 0.3);
    double worst = 0;
    int fan = 0;
    for(int i = 0; i < 20; ++i) {
      const V3 a = mls_test::random_vector(off, gen);
      const V3 x = i < 10 ? V3(0.5, 0.5, 0.5) + 0.5 * h * a : V3(0.5 + 0.3 * h * a[0], 0.5 + 0.3 * h * a[1], u(gen));
      const auto res = PM.project(Epick::Point_3(x[0], x[1], x[2]));
      MLS_CHECK(res.is_success());
      worst = std::max(worst, std::abs(cube_distance(eig(res.point))));
      fan += res.fit_kind == MLS::Local_fit_kind::CLOSEST_POINT && res.coefficients.size() == 8;
    }
    std::cout << "  mixed on the cube: max distance " << worst << " (h = " << h << "), fan kept for " << fan << "/20\n";
    // as P_U(wedge) on the 3D edges: measured 9e-9 with clang, less with gcc
    MLS_CHECK_LE(worst, 2e-8);
    MLS_CHECK(fan >= 18);
  }
  {
    const int n = 4000;
    const std::vector<Epick::Point_3> sphere = fibonacci_sphere(n);
    MLS::Mixed_projection<Epick, 3> PM(sphere);
    int quadratic = 0;
    double worst = 0;
    for(int i = 0; i < 40; ++i) {
      const Epick::Point_3& p = sphere[i * 97 % n];
      const auto res = PM.project(Epick::Point_3(1.02 * p.x(), 1.02 * p.y(), 1.02 * p.z()));
      quadratic += res.fit_kind == MLS::Local_fit_kind::LEVIN && res.coefficients.size() == 6;
      worst = std::max(worst, std::abs(eig(res.point).norm() - 1));
    }
    std::cout << "  mixed on a sphere: quadratic kept for " << quadratic << "/40, max distance " << worst
              << " (h = " << PM.bandwidth() << ")\n";
    MLS_CHECK(quadratic == 40);
    MLS_CHECK_LE(worst, 1e-3 * PM.bandwidth());
  }
}

// On noisy data the mixed space is not worse than P_L, its smooth half: on a cube sampled with
// Gaussian noise of a quarter and of 0.45 of the spacing (the noise of scanners), over every third
// sample, its worst distance to the cube is at most P_L's and its RMS distance at most 1% above
// (measured: 24% and 3% below P_L's at a quarter spacing; equal and 0.1% above at 0.45, where it
// keeps 4 fans). The fan is kept only where the quadratic leaves 4 times the noise variance; with
// a margin of 2.5, at 0.45 spacing, the worst distance is 4.4% and the RMS distance 3.8% above P_L's.
MLS_TEST(mixed_space_is_not_worse_than_levin_on_a_noisy_cube) {
  const double s = 0.025;
  for(double noise : {0.25, 0.45}) {
    std::mt19937 gen(5);
    std::normal_distribution<double> g(0., noise * s);
    std::vector<Epick::Point_3> pts;
    for(const Epick::Point_3& p : cube(s)) {
      const V3 e = mls_test::random_vector(g, gen);
      pts.emplace_back(p.x() + e[0], p.y() + e[1], p.z() + e[2]);
    }
    const MLS::Mixed_projection<Epick, 3> PM(pts);
    double sum[2] = {0, 0}, worst[2] = {0, 0};
    int queries = 0, fan = 0;
    for(std::size_t i = 0; i < pts.size(); i += 3, ++queries) {
      const auto smooth = PM.smooth_projection().project(pts[i]);
      const auto mixed = PM.project(pts[i]);
      MLS_CHECK(smooth.is_success() && mixed.is_success());
      fan += mixed.fit_kind == MLS::Local_fit_kind::CLOSEST_POINT;
      const double d[2] = {cube_distance(eig(smooth.point)), cube_distance(eig(mixed.point))};
      for(int k = 0; k < 2; ++k) {
        sum[k] += d[k] * d[k];
        worst[k] = std::max(worst[k], std::abs(d[k]));
      }
    }
    const double rms[2] = {std::sqrt(sum[0] / queries), std::sqrt(sum[1] / queries)};
    std::cout << "  noisy cube, noise " << noise << " spacing: P_L RMS " << rms[0] << " max " << worst[0]
              << ", mixed RMS " << rms[1] << " max " << worst[1] << " (fan kept for " << fan << "/" << queries << ")\n";
    MLS_CHECK_LE(rms[1], 1.01 * rms[0]);
    MLS_CHECK_LE(worst[1], worst[0]);
  }
}

// An isolated point above a sampled plane: the fan can pass through it, with the weights centred
// on it and the plane's points too far to count (an exact fit of one point). Such a fit counts
// fewer than 2 effective points and is rejected: P_U(wedge) fails there (2 h above the plane and
// more), and the mixed space lands on the plane (1.75 and 2 times its fan's bandwidth above it).
// Without the check, both projected the point onto itself.
MLS_TEST(isolated_point_not_projected_onto_itself) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Epick::Point_3> plane;
  for(int i = 0; i < 1600; ++i) plane.emplace_back(u(gen), u(gen), 0.);
  const MLS::Mixed_projection<Epick, 3> on_plane(plane);
  const double h = on_plane.bandwidth(), hs = on_plane.sharp_bandwidth();
  const auto with = [&plane](const Epick::Point_3& p) {
    std::vector<Epick::Point_3> pts = plane;
    pts.push_back(p);
    return pts;
  };
  for(double t : {2., 2.25}) {
    const Epick::Point_3 above(0.5, 0.5, t * h);
    const auto res = MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>>(with(above)).project(above);
    std::cout << "  isolated point " << t << " h above a plane: P_U(wedge) " << MLS::to_string(res.status) << std::endl;
    MLS_CHECK(res.status == MLS::Projection_status::TOO_FEW_NEIGHBORS);
  }
  for(double t : {1.75, 2.}) {
    const Epick::Point_3 above(0.5, 0.5, t * hs);
    const auto res = MLS::Mixed_projection<Epick, 3>(with(above)).project(above);
    std::cout << "  isolated point " << t << " h_s above a plane: mixed at z = " << res.point.z() / h << " h" << std::endl;
    MLS_CHECK(res.is_success() && std::abs(res.point.z()) <= 0.1 * h);
  }
}

// The noise estimate of the mixed space's screening (internal::estimate_noise_variance()): it
// measures the noise of a noisy plane, and 0 on a coarse noiseless cube (11 by 11 samples per
// face, where most neighbourhoods of P_L's support straddle an edge), so that the threshold stays
// at its floor and the fan is kept at the cube's edges; the curvature of a coarse noiseless sphere
// (4000 points) stays far below the floor too.
MLS_TEST(noise_estimate_measures_noise_not_creases_or_curvature) {
  {
    // sigma = a quarter of the spacing, the noise of a good scanner
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g(0, 1);
    const double spacing = 1. / 40, sigma = 0.25 * spacing;
    std::vector<Epick::Point_3> pts;
    for(int i = 0; i < 1600; ++i) pts.emplace_back(u(gen), u(gen), sigma * g(gen));
    MLS::Mixed_projection<Epick, 3> PM(pts);
    const double ratio = std::sqrt(PM.noise_variance()) / sigma;
    std::cout << "  noisy plane: estimated sigma / sigma = " << ratio << "\n";
    // measured 0.94 to 0.98 over seeds: the quadratic of 12 points leans towards their noise (a
    // bias of -4% at this noise), and the first quartile of 400 neighbourhoods varies by about 2%
    MLS_CHECK(ratio >= 0.9 && ratio <= 1.05);
    MLS_CHECK_NEAR(PM.screening_threshold(), 4 * PM.noise_variance(), 1e-12 * PM.screening_threshold());
    // sigma is about h / 9, above h / 20: the fan is fitted over the whole bandwidth
    MLS_CHECK(PM.sharp_bandwidth() == PM.bandwidth());
  }
  {
    const auto pts = cube(0.1);
    MLS::Mixed_projection<Epick, 3> PM(pts, wendland());
    const double h = PM.bandwidth();
    std::cout << "  coarse cube: estimated variance " << PM.noise_variance() << " (h = " << h << ")\n";
    MLS_CHECK_LE(PM.noise_variance(), 1e-20);
    MLS_CHECK_NEAR(PM.screening_threshold(), (0.01 * h) * (0.01 * h), 1e-12 * h * h);
    // no noise: the fan's bandwidth is 0.5 h, or the floor that gives its support 33 points
    // (about 0.59 h here: the 33rd neighbour is 1.44 times as far as the 16th, h's)
    std::cout << "  coarse cube: sharp bandwidth " << PM.sharp_bandwidth() / h << " h" << std::endl;
    MLS_CHECK(PM.sharp_bandwidth() >= 0.5 * h && PM.sharp_bandwidth() <= 0.7 * h);
    int fan = 0;
    for(double z : {-0.3, -0.1, 0.1, 0.3}) // near the edge x = y = 0.5
      fan += PM.project(Epick::Point_3(0.5 + 0.1 * h, 0.5 + 0.1 * h, z)).fit_kind == MLS::Local_fit_kind::CLOSEST_POINT;
    MLS_CHECK(fan == 4);
  }
  {
    const std::vector<Epick::Point_3> sphere = fibonacci_sphere(4000);
    MLS::Mixed_projection<Epick, 3> PM(sphere);
    const double h = PM.bandwidth();
    std::cout << "  noiseless sphere: 4 x estimated variance / (0.01 h)^2 = "
              << 4 * PM.noise_variance() / ((0.01 * h) * (0.01 * h)) << "\n";
    MLS_CHECK_LE(4 * PM.noise_variance(), (0.01 * h) * (0.01 * h));
  }
}

// project_points with warm starts calls the callback from the calling thread after each block
// it projected, with the fraction done, and writes nothing when cancelled.
MLS_TEST(warm_started_callback_reports_progress_and_cancels) {
  const auto pts = cube(0.025);
  const MLS::Mixed_projection<Epick, 3> PM(pts);
  std::vector<double> fractions;
  std::vector<MLS::Projection_result<Epick, 3>> out;
  const auto record = [&](bool go_on) {
    return CGAL::parameters::callback(std::function<bool(double)>([&fractions, go_on](double f) {
      fractions.push_back(f);
      return go_on;
    }));
  };
  MLS_CHECK(!MLS::project_points<CGAL::Parallel_if_available_tag>(PM, pts, std::back_inserter(out), record(false)));
  MLS_CHECK(out.empty() && fractions.size() == 1);
  fractions.clear();
  MLS_CHECK(MLS::project_points<CGAL::Sequential_tag>(PM, pts, std::back_inserter(out), record(true)));
  // once per block of warm_start_block queries (the last one: 1)
  MLS_CHECK(out.size() == pts.size());
  MLS_CHECK(fractions.size() == (pts.size() + MLS::warm_start_block - 1) / MLS::warm_start_block);
  MLS_CHECK(std::is_sorted(fractions.begin(), fractions.end()) && fractions.back() == 1.);
}

MLS_TEST(sequential_equals_parallel_unified) {
  const auto pts = cube(0.05);
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts);
  std::vector<Epick::Point_3> queries(pts.begin(), pts.begin() + 600);
  std::vector<MLS::Projection_result<Epick, 3>> seq, par;
  MLS::project_points<CGAL::Sequential_tag>(PU, queries, std::back_inserter(seq));
  MLS::project_points<CGAL::Parallel_if_available_tag>(PU, queries, std::back_inserter(par));
  std::size_t differ = 0;
  for(std::size_t i = 0; i < queries.size(); ++i)
    if(seq[i].point != par[i].point || seq[i].normal != par[i].normal || seq[i].is_on_feature != par[i].is_on_feature) ++differ;
  MLS_CHECK(seq.size() == queries.size() && par.size() == queries.size());
  MLS_CHECK_MSG(differ == 0, std::to_string(differ) + " results differ");
}

// project_points continues each projection from the fit of the query before it along a Hilbert
// curve (warm starts). On the grid-sampled cube, queries on a grid of step h/4 in a band of
// 0.3 h around a corner and its edges. Every projection must be exact, cold or warm. This grid
// found a weakness of the cold race (35 of the 629 queries up to 0.24 h off, 1.5 to 2 h from the
// corner: the corner's start, from the fan's sector fit, lost the race or converged in another
// basin), fixed by starting at the member made of the split's planes, with a floor on the
// optimiser's scaling (see the manual, "Starts at features"). Also: where both are exact, a
// closest point of the cube (the same distance to the query: a query on the medial axis has two);
// 4 times fewer iterations with warm starts (measured: 64); the same results sequentially and in
// parallel (the blocks of the Hilbert curve do not depend on the threads).
MLS_TEST(warm_started_project_points_are_exact_and_cheaper) {
  const auto pts = cube(0.025);
  MLS::Projection_options cold_options = wendland();
  cold_options.warm_starts = false;
  const MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> warm(pts, wendland()), cold(pts, cold_options);
  const double h = warm.bandwidth();
  std::vector<Epick::Point_3> queries;
  for(double x = 0.5 - 2 * h; x <= 0.5 + 0.3 * h; x += h / 4)
    for(double y = 0.5 - 2 * h; y <= 0.5 + 0.3 * h; y += h / 4)
      for(double z = 0.5 - 2 * h; z <= 0.5 + 0.3 * h; z += h / 4)
        if(std::abs(cube_distance(V3(x, y, z))) <= 0.3 * h) queries.emplace_back(x, y, z);
  std::vector<MLS::Projection_result<Epick, 3>> w, c, par;
  MLS_CHECK(MLS::project_points<CGAL::Sequential_tag>(warm, queries, std::back_inserter(w)));
  MLS_CHECK(MLS::project_points<CGAL::Sequential_tag>(cold, queries, std::back_inserter(c)));
  MLS_CHECK(MLS::project_points<CGAL::Parallel_if_available_tag>(warm, queries, std::back_inserter(par)));
  MLS_CHECK(w.size() == queries.size() && c.size() == queries.size() && par.size() == queries.size());
  double warm_worst = 0, cold_worst = 0, apart = 0;
  long warm_iterations = 0, cold_iterations = 0;
  std::size_t warm_inexact = 0, cold_inexact = 0, differ = 0, features = 0;
  for(std::size_t i = 0; i < w.size() && i < c.size() && i < par.size(); ++i) {
    MLS_CHECK(w[i].is_success() && c[i].is_success());
    const double dw = std::abs(cube_distance(eig(w[i].point))), dc = std::abs(cube_distance(eig(c[i].point)));
    warm_worst = std::max(warm_worst, dw);
    cold_worst = std::max(cold_worst, dc);
    warm_inexact += dw > 1e-9;
    cold_inexact += dc > 1e-9;
    // (queries on the cube's medial axis have two closest points: compare their distances)
    const V3 q = eig(queries[i]);
    if(dw <= 1e-9 && dc <= 1e-9) apart = std::max(apart, std::abs((eig(w[i].point) - q).norm() - (eig(c[i].point) - q).norm()));
    warm_iterations += w[i].iterations;
    cold_iterations += c[i].iterations;
    features += w[i].is_on_feature;
    if(w[i].point != par[i].point || w[i].normal != par[i].normal) ++differ;
  }
  std::cout << "  " << queries.size() << " queries around the cube's corner (h = " << h << "): warm starts " << warm_inexact
            << " inexact, max " << warm_worst / h << " h, " << warm_iterations << " iterations; cold " << cold_inexact
            << " inexact, max " << cold_worst / h << " h, " << cold_iterations << " iterations; " << features
            << " on features; exact in both: distances to the query " << apart << " apart\n";
  // Exact members have zero energy: every projection, cold or warm, must be on the cube (1e-9,
  // about 2e-8 h; measured 1.5e-13 h).
  MLS_CHECK_LE(warm_inexact, 0u);
  MLS_CHECK_LE(cold_inexact, 0u);
  MLS_CHECK_LE(apart, 1e-9);
  MLS_CHECK(features > 0);
  MLS_CHECK_LE(4 * warm_iterations, cold_iterations);
  MLS_CHECK_MSG(differ == 0, std::to_string(differ) + " results differ between sequential and parallel");
}

// A warm start is a start, not an answer. Two parallel planes 3 h apart, sampled on grids, with
// Wendland's weight (support 2.5 h: each plane is fitted exactly, the other unweighted): after a
// query on the top plane, the query below it on the bottom plane has the closest point C0 on the
// last fit right above it, where the continued fit fits the top plane exactly. The projection
// must still be on the bottom plane, where the query is (before the continued fit's bound used
// the query's nearest input point, it landed on the top plane, 3 h away; on the benchmark's noisy
// torus, with a trial Jacobian that differed only by rounding, a projection landed 9.7 h from its
// query after a jump in the order of its queries).
MLS_TEST(warm_start_from_a_distant_fit_stays_with_the_query) {
  const double s = 0.02;
  std::vector<Epick::Point_3> plane;
  for(double x = -0.6; x <= 0.6 + 1e-12; x += s)
    for(double y = -0.6; y <= 0.6 + 1e-12; y += s) plane.emplace_back(x, y, 0);
  const double d = 3 * MLS::Levin_projection<Epick>(plane, wendland()).bandwidth();
  std::vector<Epick::Point_3> pts = plane;
  for(const auto& p : plane) pts.emplace_back(p.x(), p.y(), d);
  const MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts, wendland());
  const double h = PU.bandwidth();
  MLS_CHECK_LE(2.6 * h, d); // the planes lie beyond each other's support
  decltype(PU)::Warm_start warm;
  const auto top = PU.project(Epick::Point_3(0.1, 0.1, d), warm);
  const auto bottom = PU.project(Epick::Point_3(0.1, 0.1, 0), warm);
  MLS_CHECK(top.is_success() && bottom.is_success());
  std::cout << "  planes " << d / h << " h apart: the top query lands " << std::abs(top.point.z() - d) / h
            << " h from the top plane, the bottom query, warm-started from it, " << std::abs(bottom.point.z()) / h
            << " h from the bottom plane\n";
  // exact members (1e-9 as above)
  MLS_CHECK_LE(std::abs(top.point.z() - d), 1e-9);
  MLS_CHECK_LE(std::abs(bottom.point.z()), 1e-9);
}

int main(int argc, char** argv) { return mls_test::run_all(argc, argv); }
