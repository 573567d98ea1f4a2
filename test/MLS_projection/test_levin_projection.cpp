// Tests of Levin's projection P_L, the sample set and project_points, in 2D and 3D,
// with the Simple_cartesian<double> and Epick kernels.
//
// Tolerances. With bandwidth h and a local fit of degree d, the MLS approximation error on a
// smooth noiseless sample is O(h^(d+1)) times a curvature factor. For a circle or sphere of
// radius R sampled densely, the graph of the surface over a tangent frame is
// u^2/(2R) + u^4/(8R^3) + ..., so the quadratic fit misses by about h^4/(8R^3) (x a constant
// from the weighted window, a few units since the window extends to ~2-3h), and the plane fit
// by about h^2/(2R). Each tolerance below is derived that way and checked to separate the two.
// Numerical tolerances (projection property, invariance) come from the optimiser's relative
// tolerance (1e-12 on steps in units of h, forward-difference Jacobian with steps 1.5e-8):
// the frame is found to about 1e-7 h, so 1e-5 h leaves a margin while catching any real change.

#include "test_framework.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/internal/projection/levin_energy.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/project_points.h>

#include <cmath>
#include <random>
#include <vector>

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SC = CGAL::Simple_cartesian<double>;
namespace MLS = CGAL::MLS;

namespace {

template <class K>
std::vector<typename K::Point_2> circle(int n, double R, double cx = 0, double cy = 0) {
  std::vector<typename K::Point_2> pts;
  for(int i = 0; i < n; ++i) {
    const double t = 2 * CGAL_PI * i / n;
    pts.emplace_back(cx + R * std::cos(t), cy + R * std::sin(t));
  }
  return pts;
}

// Fibonacci sphere: near-uniform, deterministic.
template <class K>
std::vector<typename K::Point_3> sphere(int n, double R = 1) {
  std::vector<typename K::Point_3> pts;
  const double golden = CGAL_PI * (3 - std::sqrt(5.));
  for(int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), t = golden * i;
    pts.emplace_back(R * r * std::cos(t), R * r * std::sin(t), R * z);
  }
  return pts;
}

// Random directions, for queries off the surface.
std::vector<Eigen::Vector3d> directions(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> d;
  for(int i = 0; i < n; ++i) d.push_back(mls_test::random_vector(g, gen).normalized());
  return d;
}

template <class P> double norm(const P& p) { return std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y())); }
double norm3(const Epick::Point_3& p) { return std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length())); }
double dist(const Epick::Point_3& a, const Epick::Point_3& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

// The two rays of a 2D wedge with opening angle `phi` (radians) meeting at the origin, symmetric
// about the y axis (the bisector), sampled every `spacing` up to length `L`.
std::vector<SC::Point_2> wedge(double phi, double spacing, double L) {
  std::vector<SC::Point_2> pts;
  pts.emplace_back(0, 0);
  for(double t = spacing; t <= L; t += spacing) {
    pts.emplace_back(t * std::sin(phi / 2), t * std::cos(phi / 2));
    pts.emplace_back(-t * std::sin(phi / 2), t * std::cos(phi / 2));
  }
  return pts;
}

// |cos| of the angle between Levin's phase-1 frame normal at the apex of a wedge and its bisector.
double apex_frame_alignment(double phi_degrees) {
  const auto pts = wedge(phi_degrees * CGAL_PI / 180, 0.01, 1.);
  MLS::Levin_projection<SC, MLS::Plane_function_space<2>> P(pts);
  const auto res = P.project(SC::Point_2(0, 0));
  if(!res.is_success()) return -1;
  return std::abs(CGAL::to_double(res.frame.normal.y()));
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Accuracy against analytic shapes

MLS_TEST(circle_2d_projects_onto_circle) {
  // 400 samples on the unit circle: spacing 0.0157, h = 6th-neighbour distance = 3 spacings = 0.047.
  const auto pts = circle<SC>(400, 1.);
  MLS::Levin_projection<SC, MLS::Polynomial_function_space<2>> Pq(pts);
  MLS::Levin_projection<SC, MLS::Plane_function_space<2>> Pp(pts);
  const double h = Pq.bandwidth();
  MLS_CHECK_NEAR(h, 3 * 2 * CGAL_PI / 400, 1e-3);
  double err_q = 0, err_p = 0;
  for(int i = 0; i < 200; ++i) {
    const double t = 0.0137 + 2 * CGAL_PI * i / 200, rad = 1 + 0.4 * h * std::sin(7. * i);
    const SC::Point_2 r(rad * std::cos(t), rad * std::sin(t));
    const auto a = Pq.project(r), b = Pp.project(r);
    MLS_CHECK(a.status == MLS::Projection_status::CONVERGED);
    MLS_CHECK(b.status == MLS::Projection_status::CONVERGED);
    err_q = std::max(err_q, std::abs(norm(a.point) - 1));
    err_p = std::max(err_p, std::abs(norm(b.point) - 1));
    // normal: radial, pointing away from the centroid (the centre of the circle)
    MLS_CHECK_NEAR(CGAL::to_double(a.normal * (a.point - CGAL::ORIGIN)) / norm(a.point), 1., 1e-6);
  }
  // quadratic: h^4/(8R^3) = 6e-7, times the window constant: 2e-5 is generous yet 100x below the plane's error
  MLS_CHECK_LE(err_q, 2e-5);
  // plane: the error is of order h^2/(2R) = 1.1e-3; it must be far larger than the quadratic's
  MLS_CHECK_LE(2e-4, err_p);
  MLS_CHECK_LE(err_p, 3 * h * h);
}

MLS_TEST(sphere_3d_projects_onto_sphere) {
  // 6000 samples: spacing ~ sqrt(4 pi / 6000) = 0.046, h ~ 2.3 spacings ~ 0.1.
  const auto pts = sphere<Epick>(6000);
  MLS::Levin_projection<Epick> P(pts);
  const double h = P.bandwidth();
  MLS_CHECK(h > 0.07 && h < 0.14);
  const auto dirs = directions(300, 1);
  double err = 0;
  for(std::size_t i = 0; i < dirs.size(); ++i) {
    const double rad = 1 + 0.4 * h * std::sin(3. * i);
    const Eigen::Vector3d q = rad * dirs[i];
    const auto res = P.project(Epick::Point_3(q[0], q[1], q[2]));
    MLS_CHECK(res.status == MLS::Projection_status::CONVERGED);
    err = std::max(err, std::abs(norm3(res.point) - 1));
    const Epick::Vector_3 radial = (res.point - CGAL::ORIGIN) / norm3(res.point);
    MLS_CHECK_NEAR(CGAL::to_double(res.normal * radial), 1., 1e-5);
  }
  // h^4/(8R^3) = 1.2e-5 times the window constant (a few units), and sampling irregularity.
  MLS_CHECK_LE(err, 2e-4);
}

MLS_TEST(plane_is_reproduced_exactly) {
  // A tilted plane through (0.3, -0.2, 0.1), sampled on a jittered grid: the plane is a member
  // of both spaces, so every projection lies on it to rounding error.
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.5, 1).normalized();
  const auto basis = MLS::internal::tangent_basis<3>(n);
  const Eigen::Vector3d o(0.3, -0.2, 0.1);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Epick::Point_3> pts;
  for(int i = -30; i <= 30; ++i)
    for(int j = -30; j <= 30; ++j) {
      const Eigen::Vector2d e = mls_test::random_vector<2>(jitter, gen);
      const Eigen::Vector3d p = o + (0.05 * (i + e[0])) * basis[0] + (0.05 * (j + e[1])) * basis[1];
      pts.emplace_back(p[0], p[1], p[2]);
    }
  for(int weight = 0; weight < 2; ++weight) {
    MLS::Projection_options opt;
    opt.weight = weight == 0 ? MLS::Weight_kind::GAUSSIAN : MLS::Weight_kind::WENDLAND;
    MLS::Levin_projection<Epick> Pq(pts, opt);
    MLS::Levin_projection<Epick, MLS::Plane_function_space<3>> Pp(pts, opt);
    for(int i = 0; i < 50; ++i) {
      const Eigen::Vector3d r = o + 0.03 * (i - 25) * basis[0] + 0.02 * (i % 7) * basis[1] + 0.05 * std::sin(i) * n;
      for(const auto& res : {Pq.project(Epick::Point_3(r[0], r[1], r[2])), Pp.project(Epick::Point_3(r[0], r[1], r[2]))}) {
        MLS_CHECK(res.is_success());
        const Eigen::Vector3d p(res.point.x(), res.point.y(), res.point.z());
        MLS_CHECK_LE(std::abs((p - o).dot(n)), 1e-12);
        // the projection of a point off a plane is its orthogonal projection
        MLS_CHECK_LE((p - (r - (r - o).dot(n) * n)).norm(), 1e-12);
        MLS_CHECK_NEAR(std::abs(CGAL::to_double(res.normal.x() * n[0] + res.normal.y() * n[1] + res.normal.z() * n[2])), 1., 1e-12);
      }
    }
  }
}

MLS_TEST(paraboloid_is_approximated_to_second_order) {
  // z = 0.5 x^2 + 1.5 y^2, rotated and translated. Levin's frame is tilted away from the axis
  // off the vertex, so the graph in it is not exactly quadratic: the error is third order,
  // about |grad k| h^3 ~ 1e-4 for h ~ 0.07; the plane fit misses by the sagitta k h^2 ~ 5e-3.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d T(5, -3, 2);
  const auto f = [](double x, double y) { return 0.5 * x * x + 1.5 * y * y; };
  std::vector<Epick::Point_3> pts;
  for(int i = -40; i <= 40; ++i)
    for(int j = -40; j <= 40; ++j) {
      const double x = 0.025 * i, y = 0.025 * j;
      const Eigen::Vector3d p = R * Eigen::Vector3d(x, y, f(x, y)) + T;
      pts.emplace_back(p[0], p[1], p[2]);
    }
  MLS::Levin_projection<Epick> P(pts);
  double err = 0;
  for(int i = 0; i < 100; ++i) {
    const double x = 0.4 * std::sin(1.3 * i), y = 0.4 * std::cos(0.7 * i);
    const Eigen::Vector3d r = R * Eigen::Vector3d(x, y, f(x, y) + 0.02 * std::sin(5. * i)) + T;
    const auto res = P.project(Epick::Point_3(r[0], r[1], r[2]));
    MLS_CHECK(res.status == MLS::Projection_status::CONVERGED);
    const Eigen::Vector3d p = R.transpose() * (Eigen::Vector3d(res.point.x(), res.point.y(), res.point.z()) - T);
    err = std::max(err, std::abs(p[2] - f(p[0], p[1])) / std::sqrt(1 + p[0] * p[0] + 9 * p[1] * p[1]));
  }
  MLS_CHECK_LE(err, 5e-4);
}

// ---------------------------------------------------------------------------------------------
// The projection property and invariances

MLS_TEST(projection_property) {
  // Noisy sphere (sigma = 0.01 = 0.07 h), queries up to 0.05 = 0.35 h off the surface.
  // Levin's proof of P(P(r)) = P(r) (paper, section 3.5) assumes that the minimiser of
  // equation 1 stays the same when r moves along the frame normal. It does only up to a term
  // t * (tangential derivative of the energy with respect to q through the weights), where t is
  // the query's distance: with noise this term does not vanish, and the first re-projection
  // moves the point by a small fraction of h (measured: 5e-5 h with the plane, 5e-6 h with the
  // quadratic); re-projecting again moves it less (the iteration contracts towards the set of
  // stationary points, Amenta and Kil's view of the MLS surface). On noiseless samples of a
  // sphere the term vanishes by symmetry and P(P(r)) = P(r) to the optimiser's precision.
  const auto pts = sphere<Epick>(3000);
  std::mt19937 gen(5);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<Epick::Point_3> noisy;
  for(const auto& p : pts) {
    const Eigen::Vector3d e = mls_test::random_vector(noise, gen);
    noisy.emplace_back(p.x() + e[0], p.y() + e[1], p.z() + e[2]);
  }
  MLS::Levin_projection<Epick> Pq(noisy);
  MLS::Levin_projection<Epick, MLS::Plane_function_space<3>> Pp(Pq.shared_samples());
  const double h = Pq.bandwidth();
  double first_q = 0, first_p = 0, second = 0;
  for(const auto& d : directions(100, 7)) {
    const Eigen::Vector3d q = (1 + 0.05 * d[0]) * d;
    const Epick::Point_3 r(q[0], q[1], q[2]);
    const auto a1 = Pq.project(r), a2 = Pq.project(a1.point), a3 = Pq.project(a2.point);
    const auto b1 = Pp.project(r), b2 = Pp.project(b1.point), b3 = Pp.project(b2.point);
    MLS_CHECK(a1.is_success() && a2.is_success() && a3.is_success());
    MLS_CHECK(b1.is_success() && b2.is_success() && b3.is_success());
    first_q = std::max(first_q, dist(a1.point, a2.point) / h);
    first_p = std::max(first_p, dist(b1.point, b2.point) / h);
    second = std::max({second, dist(a2.point, a3.point) / h, dist(b2.point, b3.point) / h});
  }
  MLS_CHECK_LE(first_q, 2e-5);
  MLS_CHECK_LE(first_p, 2e-4);
  MLS_CHECK_LE(second, std::max(first_q, first_p));
  std::cout << "  projection property, noisy sphere: |P2-P1|/h quadratic " << first_q << ", plane " << first_p
            << "; |P3-P2|/h " << second << "\n";

  MLS::Levin_projection<Epick> Pn(pts);
  double noiseless = 0;
  for(const auto& d : directions(100, 8)) {
    const Eigen::Vector3d q = (1 + 0.05 * d[0]) * d;
    const auto a1 = Pn.project(Epick::Point_3(q[0], q[1], q[2])), a2 = Pn.project(a1.point);
    noiseless = std::max(noiseless, dist(a1.point, a2.point) / Pn.bandwidth());
  }
  std::cout << "  projection property, noiseless sphere: |P2-P1|/h " << noiseless << "\n";
  MLS_CHECK_LE(noiseless, 1e-6);
}

MLS_TEST(invariance_under_rigid_motion_and_scaling) {
  std::mt19937 gen(11);
  std::normal_distribution<double> noise(0, 0.005);
  std::vector<Epick::Point_3> pts;
  for(const auto& p : sphere<Epick>(2500)) { // an ellipsoid with noise
    const Eigen::Vector3d e = mls_test::random_vector(noise, gen);
    pts.emplace_back(p.x() + e[0], 0.7 * p.y() + e[1], 0.5 * p.z() + e[2]);
  }
  std::vector<Epick::Point_3> queries;
  for(const auto& d : directions(60, 13)) queries.emplace_back(1.02 * d[0], 0.7 * d[1], 0.5 * d[2] - 0.01);

  MLS::Levin_projection<Epick> P(pts);
  const double h = P.bandwidth();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2.1, Eigen::Vector3d(-1, 0.5, 2).normalized()).toRotationMatrix();
  struct Motion {
    double scale;
    Eigen::Vector3d translation;
  };
  // a rotation with a UTM-like offset of 1e6, then uniform scalings by 1e-3 and 1e3
  for(const Motion m : {Motion{1., Eigen::Vector3d(6.1e5, 4.3e6, 120.)}, Motion{1e-3, Eigen::Vector3d(0.1, 0, 0)},
                        Motion{1e3, Eigen::Vector3d(0, -50, 0)}}) {
    const auto apply = [&](const Epick::Point_3& p) {
      const Eigen::Vector3d x = m.scale * (R * Eigen::Vector3d(p.x(), p.y(), p.z())) + m.translation;
      return Epick::Point_3(x[0], x[1], x[2]);
    };
    std::vector<Epick::Point_3> moved;
    for(const auto& p : pts) moved.push_back(apply(p));
    MLS::Levin_projection<Epick> Pm(moved);
    MLS_CHECK_NEAR(Pm.bandwidth() / m.scale, h, 1e-9 * h);
    double worst_point = 0, worst_normal = 0;
    for(const auto& q : queries) {
      const auto a = P.project(q);
      const auto b = Pm.project(apply(q));
      MLS_CHECK(a.is_success() && b.is_success());
      worst_point = std::max(worst_point, dist(apply(a.point), b.point) / (m.scale * h));
      const Eigen::Vector3d na = R * Eigen::Vector3d(a.normal.x(), a.normal.y(), a.normal.z());
      worst_normal = std::max(worst_normal, (na - Eigen::Vector3d(b.normal.x(), b.normal.y(), b.normal.z())).norm());
    }
    // the UTM-like offset costs the world coordinates their last bits: 1e6 * 2^-52 = 2e-10, i.e. 2e-8 h
    MLS_CHECK_LE(worst_point, 1e-5);
    MLS_CHECK_LE(worst_normal, 1e-5);
  }
}

MLS_TEST(large_offsets_are_as_accurate_as_centred_input) {
  // A circle at UTM-like coordinates: the error must be the centred circle's.
  const auto pts = circle<Epick>(400, 1., 512345.0, 5123456.0);
  MLS::Levin_projection<Epick, MLS::Polynomial_function_space<2>> P(pts);
  double err = 0;
  for(int i = 0; i < 100; ++i) {
    const double t = 0.1 + 0.0628 * i;
    const auto res = P.project(Epick::Point_2(512345.0 + 1.01 * std::cos(t), 5123456.0 + 1.01 * std::sin(t)));
    MLS_CHECK(res.is_success());
    err = std::max(err, std::abs(std::hypot(res.point.x() - 512345.0, res.point.y() - 5123456.0) - 1));
  }
  MLS_CHECK_LE(err, 2e-5);
}

MLS_TEST(sequential_equals_parallel) {
  std::mt19937 gen(17);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<Epick::Point_3> pts;
  for(const auto& p : sphere<Epick>(20000)) {
    const Eigen::Vector3d e = mls_test::random_vector(noise, gen);
    pts.emplace_back(p.x() + e[0], p.y() + e[1], p.z() + e[2]);
  }
  MLS::Levin_projection<Epick> P(pts);
  std::vector<MLS::Projection_result<Epick, 3>> seq, par;
  MLS_CHECK(MLS::project_points<CGAL::Sequential_tag>(P, pts, std::back_inserter(seq)));
  MLS_CHECK(MLS::project_points<CGAL::Parallel_if_available_tag>(P, pts, std::back_inserter(par)));
  MLS_CHECK(seq.size() == pts.size() && par.size() == pts.size());
  std::size_t differ = 0;
  for(std::size_t i = 0; i < std::min(seq.size(), par.size()); ++i)
    if(seq[i].point != par[i].point || seq[i].normal != par[i].normal || seq[i].energy != par[i].energy) ++differ;
  MLS_CHECK_MSG(differ == 0, std::to_string(differ) + " results differ");
  // the noisy points move onto a smooth surface: their mean distance to the sphere shrinks
  double before = 0, after = 0;
  for(std::size_t i = 0; i < pts.size(); ++i) {
    before += std::abs(norm3(pts[i]) - 1);
    after += std::abs(norm3(seq[i].point) - 1);
  }
  MLS_CHECK_LE(after, 0.5 * before);
}

MLS_TEST(callback_reports_progress_and_cancels) {
  const auto pts = sphere<Epick>(10000);
  MLS::Levin_projection<Epick, MLS::Plane_function_space<3>> P(pts);
  std::vector<double> fractions;
  std::vector<MLS::Projection_result<Epick, 3>> out;
  const bool done = MLS::project_points<CGAL::Parallel_if_available_tag>(
    P, pts, std::back_inserter(out), CGAL::parameters::callback(std::function<bool(double)>([&](double f) {
      fractions.push_back(f);
      return fractions.size() < 2;
    })));
  MLS_CHECK(!done);
  MLS_CHECK(fractions.size() == 2);
  MLS_CHECK(out.size() == 2 * 4096); // two batches were completed before the cancellation
  out.clear();
  fractions.clear();
  MLS_CHECK(MLS::project_points<CGAL::Sequential_tag>(P, pts, std::back_inserter(out),
                                                      CGAL::parameters::callback(std::function<bool(double)>([&](double f) {
                                                        fractions.push_back(f);
                                                        return true;
                                                      }))));
  MLS_CHECK(out.size() == pts.size() && !fractions.empty() && fractions.back() == 1.);
}

// ---------------------------------------------------------------------------------------------
// Section 3.2: Levin's frame at the apex of a sharp wedge

MLS_TEST(levin_frame_at_wedge_apex_switches_to_bisector) {
  // Wide wedge: the frame crosses both rays, its normal along the bisector.
  MLS_CHECK_LE(0.99, apex_frame_alignment(120));
  MLS_CHECK_LE(0.99, apex_frame_alignment(150));
  // Sharp wedge: the frame is the bisector itself (normal orthogonal to it), where no function
  // can fit both rays: the pinch of Figure 1.
  MLS_CHECK_LE(apex_frame_alignment(50), 0.01);
  MLS_CHECK_LE(apex_frame_alignment(30), 0.01);
}

// ---------------------------------------------------------------------------------------------
// Degenerate input: statuses, never NaN

MLS_TEST(bad_input_gives_status_not_nan) {
  using Result = MLS::Projection_result<Epick, 3>;
  const auto finite = [](const Result& r) {
    return std::isfinite(r.point.x()) && std::isfinite(r.point.y()) && std::isfinite(r.point.z()) &&
           std::isfinite(r.normal.x()) && std::isfinite(r.normal.y()) && std::isfinite(r.normal.z());
  };
  const Epick::Point_3 q(0.1, 0.2, 0.3);
  {
    std::vector<Epick::Point_3> none;
    MLS::Levin_projection<Epick> P(none);
    const auto r = P.project(q);
    MLS_CHECK(r.status == MLS::Projection_status::TOO_FEW_NEIGHBORS && finite(r) && r.point == q);
  }
  {
    std::vector<Epick::Point_3> same(50, Epick::Point_3(1, 1, 1));
    MLS::Levin_projection<Epick> P(same);
    const auto r = P.project(q);
    MLS_CHECK(r.status == MLS::Projection_status::DEGENERATE_NEIGHBORHOOD && finite(r) && r.normal == CGAL::NULL_VECTOR);
  }
  {
    std::vector<Epick::Point_3> line;
    for(int i = 0; i < 100; ++i) line.emplace_back(0.01 * i, 0.02 * i, -0.01 * i);
    MLS::Levin_projection<Epick> P(line);
    const auto r = P.project(q);
    MLS_CHECK(r.status == MLS::Projection_status::DEGENERATE_NEIGHBORHOOD && finite(r));
  }
  {
    std::vector<Epick::Point_3> pts = sphere<Epick>(500);
    pts.emplace_back(std::nan(""), 0, 0);
    pts.emplace_back(0, std::numeric_limits<double>::infinity(), 0);
    MLS::Levin_projection<Epick> P(pts);
    MLS_CHECK(P.samples().size() == 500 && P.samples().number_of_ignored_points() == 2);
    const auto r = P.project(Epick::Point_3(0, std::nan(""), 1));
    MLS_CHECK(r.status == MLS::Projection_status::INVALID_QUERY);
    // a far query: a finite answer, whatever its status
    const auto far = P.project(Epick::Point_3(40, 30, 20));
    MLS_CHECK(finite(far));
    // a few points only
    std::vector<Epick::Point_3> three(pts.begin(), pts.begin() + 3);
    MLS::Levin_projection<Epick> P3(three);
    const auto r3 = P3.project(q);
    MLS_CHECK(!r3.is_success() && finite(r3));
  }
  {
    // duplicates do not break anything
    std::vector<Epick::Point_3> pts = sphere<Epick>(800);
    const std::size_t n = pts.size();
    for(std::size_t i = 0; i < n; ++i) pts.push_back(pts[i]);
    MLS::Levin_projection<Epick> P(pts);
    const auto r = P.project(Epick::Point_3(0, 0, 1.05));
    MLS_CHECK(r.is_success() && std::abs(norm3(r.point) - 1) < 1e-3);
  }
}

MLS_TEST(weights) {
  const MLS::Weight_function p(MLS::Weight_kind::POLYNOMIAL, 2.);
  MLS_CHECK_NEAR(p.support_radius(), 2. * std::sqrt(6.), 1e-15);
  MLS_CHECK_NEAR(p(0.), 1., 0.);
  MLS_CHECK_NEAR(p(12.), std::pow(0.5, 4), 1e-15); // d^2 = R^2 / 2
  MLS_CHECK(p(24.) == 0. && p(23.9) > 0);
  const MLS::Weight_function g(MLS::Weight_kind::GAUSSIAN, 2.);
  MLS_CHECK_NEAR(g(0.), 1., 0.);
  MLS_CHECK_NEAR(g(4.), std::exp(-1.), 1e-15);
  MLS_CHECK(g(64.) == 0. && g(63.9) > 0);
  const MLS::Weight_function w(MLS::Weight_kind::WENDLAND, 2.);
  MLS_CHECK_NEAR(w(0.), 1., 0.);
  MLS_CHECK(w(25.) == 0. && w(24.9) > 0);
  MLS_CHECK_NEAR(w(6.25), std::pow(0.5, 4) * 3., 1e-15);
}

// The gradient and Hessian of Levin's energy (internal::levin_energy, which Newton's method
// uses) against central differences of the energy in the exponential map's coordinates, for each
// weight, in 2D and 3D, on noisy points (relative step 1e-5: errors about 1e-10 for the gradient,
// 1e-6 for the Hessian).
template <int D>
void check_levin_energy_derivatives(MLS::Weight_kind kind) {
  using Vec = MLS::internal::Vec<D>;
  using Step = Eigen::Matrix<double, D, 1>;
  std::mt19937 gen(17);
  std::normal_distribution<double> normal(0, 1);
  std::vector<Vec> y;
  for(int i = 0; i < 200; ++i) {
    Vec v = mls_test::random_vector<D>(normal, gen);
    v[D - 1] *= 0.2;
    y.push_back(v);
  }
  const MLS::Weight_function weight(kind, 1.);
  Vec n = Vec::Unit(D - 1);
  n[0] = 0.3;
  n.normalize();
  const double s = 0.17;
  const auto basis = MLS::internal::tangent_basis<D>(n);
  const auto energy = [&](const Step& x) {
    double E = 0;
    Step g;
    Eigen::Matrix<double, D, D> H;
    MLS_CHECK(MLS::internal::levin_energy<D>(y, MLS::internal::exp_map<D>(n, basis, x), s + x[D - 1], weight, E, g, H));
    return E;
  };
  double E = 0;
  Step g;
  Eigen::Matrix<double, D, D> H;
  MLS_CHECK(MLS::internal::levin_energy<D>(y, n, s, weight, E, g, H));
  MLS_CHECK_NEAR(E, energy(Step::Zero()), 1e-14 * E);
  const double eps = 1e-5;
  Step fd_g;
  Eigen::Matrix<double, D, D> fd_H;
  for(int j = 0; j < D; ++j) {
    const Step ej = eps * Step::Unit(j);
    fd_g[j] = (energy(ej) - energy(-ej)) / (2 * eps);
    for(int k = 0; k < D; ++k) {
      const Step ek = eps * Step::Unit(k);
      fd_H(j, k) = (energy(ej + ek) - energy(ej - ek) - energy(ek - ej) + energy(-ej - ek)) / (4 * eps * eps);
    }
  }
  MLS_CHECK_LE((fd_g - g).norm(), 1e-8 * g.norm());
  MLS_CHECK_LE((fd_H - H).norm(), 1e-5 * H.norm());
}

MLS_TEST(levin_energy_derivatives) {
  for(const MLS::Weight_kind kind : {MLS::Weight_kind::POLYNOMIAL, MLS::Weight_kind::GAUSSIAN, MLS::Weight_kind::WENDLAND}) {
    check_levin_energy_derivatives<2>(kind);
    check_levin_energy_derivatives<3>(kind);
  }
}

// `test_levin_projection --measure-wedge` prints the alignment of Levin's apex frame with the
// bisector for opening angles 20..170 degrees (1-degree steps from 60 to 75): a measurement, not
// a test.
int main(int argc, char** argv) {
  if(argc > 1 && std::string(argv[1]) == "--measure-wedge") {
    for(int phi = 20; phi <= 170; phi += (phi >= 60 && phi < 75 ? 1 : 5)) std::cout << phi << " " << apex_frame_alignment(phi) << "\n";
    return 0;
  }
  return mls_test::run_all(argc, argv);
}
