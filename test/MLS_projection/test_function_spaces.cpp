// Tests of the function spaces with closest-point projection (MLSFunctionSpace):
// Plane_function_space, Paraboloid_function_space and Wedge_fan_function_space, in 2D and 3D;
// and of the weight functions' derivatives.
// Eigen-only: no CGAL kernel or search header, so that this file compiles fast.
//
// Each closest point is checked against an independent brute force: a dense sampling of the
// member followed by a local refinement (golden section then Newton for curves and cones,
// damped Newton on the 2D problem for the quadric). Distances must agree within 1e-9,
// relative to d + 1e-6 (|x| + 1) (the second term only matters for queries on the surface).

#include "test_framework.h"

#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/Weight_function.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace MLS = CGAL::MLS;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

namespace {

// Worst relative errors against the brute force, printed at the end of each test.
struct Worst {
  const char* what;
  double value = 0;
  int count = 0;
  explicit Worst(const char* w) : what(w) {}
  void add(double e) { value = std::max(value, e); ++count; }
  ~Worst() { std::cout << "       " << what << ": " << count << " queries, worst relative error " << value << "\n"; }
};

double rel_error(double mine, double brute, double xnorm) {
  return std::abs(mine - brute) / (brute + 1e-6 * (xnorm + 1.));
}

double log_uniform(std::mt19937& g, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(g));
}

// Golden-section minimisation of a 1D function on [lo, hi].
template <class F> double golden(const F& f, double lo, double hi) {
  const double r = (std::sqrt(5.) - 1.) / 2.;
  double a = lo, b = hi, c = b - r * (b - a), d = a + r * (b - a), fc = f(c), fd = f(d);
  for(int i = 0; i < 200 && b - a > 1e-15 * (1. + std::abs(a) + std::abs(b)); ++i) {
    if(fc < fd) { b = d; d = c; fd = fc; c = b - r * (b - a); fc = f(c); }
    else { a = c; c = d; fc = fd; d = a + r * (b - a); fd = f(d); }
  }
  return 0.5 * (a + b);
}

// ---------------------------------------------------------------- 2D parabola z = k x^2
double brute_parabola(double k, const V2& x) {
  auto E = [&](double u) { const double dz = k * u * u - x[1]; return (u - x[0]) * (u - x[0]) + dz * dz; };
  // Any closest point is within d0 of x; d0 from two points of the curve (vertical, origin).
  const double d0 = std::min(std::abs(x[1] - k * x[0] * x[0]), x.norm());
  std::vector<double> us;
  const int M = 4000;
  for(int i = 0; i <= M; ++i) us.push_back(x[0] - d0 + 2. * d0 * i / M);
  if(k != 0) // also sample uniformly in height, for steep parabolas
    for(int i = 0; i <= M; ++i) {
      const double z = x[1] - d0 + 2. * d0 * i / M;
      if(z / k >= 0) { us.push_back(std::sqrt(z / k)); us.push_back(-std::sqrt(z / k)); }
    }
  std::sort(us.begin(), us.end());
  double best = HUGE_VAL;
  for(std::size_t i = 0; i < us.size(); ++i) {
    const double e = E(us[i]);
    const bool local_min = (i == 0 || e <= E(us[i - 1])) && (i + 1 == us.size() || e <= E(us[i + 1]));
    if(!local_min) continue;
    const double lo = us[i == 0 ? 0 : i - 1], hi = us[i + 1 == us.size() ? i : i + 1];
    double u = golden(E, lo, hi);
    for(int it = 0; it < 3; ++it) { // Newton on E'
      const double s = k * u * u - x[1];
      const double g = (u - x[0]) + 2 * k * u * s, h = 1 + 2 * k * s + 4 * k * k * u * u;
      if(h > 0 && E(u - g / h) <= E(u)) u -= g / h;
    }
    best = std::min(best, std::sqrt(E(u)));
  }
  return best;
}

// Checks a 2D graph closest point: on the curve, distance, normal, parallelism, sign.
void check_parabola(double k, const V2& x, Worst& worst) {
  MLS::Paraboloid_function_space<2> fs;
  Eigen::Matrix<double, 1, 1> c(k);
  const auto cp = fs.closest_point(c, x);
  const double scale = 1. + x.norm();
  MLS_CHECK(cp.point.allFinite() && cp.normal.allFinite() && std::isfinite(cp.signed_distance));
  MLS_CHECK_NEAR(cp.point[1], k * cp.point[0] * cp.point[0], 1e-12 * (scale + std::abs(cp.point[1])));
  const double d = (x - cp.point).norm();
  const double db = brute_parabola(k, x);
  const double e = rel_error(d, db, x.norm());
  worst.add(e);
  MLS_CHECK_MSG(e <= 1e-9, "k " + mls_test::fmt(k) + " x " + mls_test::fmt(x[0]) + "," + mls_test::fmt(x[1]) +
                               " mine " + mls_test::fmt(d) + " brute " + mls_test::fmt(db));
  MLS_CHECK_NEAR(cp.normal.norm(), 1., 1e-12);
  MLS_CHECK(!cp.is_on_feature);
  MLS_CHECK_NEAR(std::abs(cp.signed_distance), d, 1e-14 * scale);
  // normal orthogonal to the tangent (1, 2 k u), up, and x - point parallel to it
  MLS_CHECK_NEAR(cp.normal.dot(V2(1., 2 * k * cp.point[0]).normalized()), 0., 1e-12);
  MLS_CHECK(cp.normal[1] > 0);
  MLS_CHECK_LE(((x - cp.point) - cp.signed_distance * cp.normal).norm(), 1e-7 * scale);
  const double above = x[1] - k * x[0] * x[0];
  if(std::abs(above) > 1e-9 * scale) MLS_CHECK((cp.signed_distance > 0) == (above > 0));
}

MLS_TEST(quadratic_2_random_against_brute_force) {
  std::mt19937 g(1);
  std::uniform_real_distribution<double> u(-2, 2), sgn(-1, 1);
  Worst worst("parabola");
  for(int i = 0; i < 3000; ++i) {
    const double k = (sgn(g) < 0 ? -1 : 1) * log_uniform(g, 1e-3, 1e3);
    check_parabola(k, V2(u(g), u(g)), worst);
  }
}

MLS_TEST(quadratic_2_special_cases) {
  Worst worst("parabola special");
  std::mt19937 g(2);
  std::uniform_real_distribution<double> u(-2, 2);
  MLS::Paraboloid_function_space<2> fs;
  // k = 0: the line, exactly.
  for(int i = 0; i < 50; ++i) {
    const V2 x(u(g), u(g));
    const auto cp = fs.closest_point(Eigen::Matrix<double, 1, 1>(0.), x);
    MLS_CHECK(cp.point == V2(x[0], 0.));
    MLS_CHECK(cp.normal == V2(0., 1.));
    MLS_CHECK(cp.signed_distance == x[1]);
  }
  // tiny and huge k
  for(double k : {1e-300, 1e-200, 1e-12, -1e-9, 1e6, -1e8, 1e8})
    for(int i = 0; i < 100; ++i) check_parabola(k, V2(u(g), u(g)), worst);
  // on the axis (a = 0): one minimum at the vertex below the centre of curvature 1/(2k),
  // two symmetric minima above it, and the triple root exactly at it
  for(double k : {0.25, 1., 7.}) {
    const double c = 1. / (2. * k);
    for(double b : {0.5 * c, c, c * (1 + 1e-9), c * (1 + 1e-6), 1.5 * c, 10. * c, -c}) {
      const V2 x(0., b);
      check_parabola(k, x, worst);
      check_parabola(-k, V2(0., -b), worst);
      const auto cp = fs.closest_point(Eigen::Matrix<double, 1, 1>(k), x);
      const double expected_u = b > c ? std::sqrt((2 * k * b - 1) / (2 * k * k)) : 0.;
      // (within 1e-9 of the triple root the quartic-flat energy cannot tell the roots apart)
      if(std::abs(b - c) > 1e-8 * c) MLS_CHECK_NEAR(std::abs(cp.point[0]), expected_u, 1e-6 * (1 + expected_u));
      // the distance is exact to double precision even where the root is only ~1e-8 accurate
      const double dexp = b > c ? std::sqrt(expected_u * expected_u + std::pow(k * expected_u * expected_u - b, 2))
                                : std::abs(b);
      MLS_CHECK_NEAR((x - cp.point).norm(), dexp, 1e-13 * (1 + dexp));
    }
  }
  // at the origin, and on the curve
  const auto cp0 = fs.closest_point(Eigen::Matrix<double, 1, 1>(3.), V2::Zero());
  MLS_CHECK(cp0.point == V2::Zero() && cp0.signed_distance == 0);
  for(int i = 0; i < 100; ++i) {
    const double k = u(g), a = u(g);
    check_parabola(k, V2(a, k * a * a), worst);
  }
}

// ---------------------------------------------------------------- 3D quadric
struct Quadric {
  double a, b, theta;
  // f(u) = a (e1 . u)^2 + b (e2 . u)^2 (not u^T H u, which cancels badly for large a, b)
  double operator()(const V2& u) const {
    const double x1 = std::cos(theta) * u[0] + std::sin(theta) * u[1], y1 = -std::sin(theta) * u[0] + std::cos(theta) * u[1];
    return a * x1 * x1 + b * y1 * y1;
  }
  Eigen::Matrix2d H() const { // f(u) = u^T H u
    const V2 e1(std::cos(theta), std::sin(theta)), e2(-std::sin(theta), std::cos(theta));
    return a * e1 * e1.transpose() + b * e2 * e2.transpose();
  }
};

double brute_quadric(const Quadric& Q, const V3& x) {
  const Eigen::Matrix2d H = Q.H();
  const V2 xt = x.head<2>();
  auto f = [&](const V2& u) { return Q(u); };
  auto E = [&](const V2& u) { const double dz = f(u) - x[2]; return (u - xt).squaredNorm() + dz * dz; };
  const double d0 = std::min(std::abs(x[2] - f(xt)), x.norm());
  // A tensor grid in the principal coordinates (x', y'): uniform samples of the disk of
  // radius d0 around the query, plus samples uniform in height x' = +-sqrt(z / |a|), which
  // resolve very steep quadrics.
  const V2 e1(std::cos(Q.theta), std::sin(Q.theta)), e2(-std::sin(Q.theta), std::cos(Q.theta));
  const double p = e1.dot(xt), q = e2.dot(xt);
  const int M = 120;
  auto samples = [&](double c, double k, double other_k, double other_c) {
    std::vector<double> s;
    for(int i = 0; i <= M; ++i) s.push_back(c - d0 + 2 * d0 * i / M);
    const double zmax = std::abs(x[2]) + d0 + std::abs(other_k) * std::pow(std::abs(other_c) + d0, 2);
    if(k != 0)
      for(int i = 0; i <= M; ++i) {
        const double w = std::sqrt(zmax * i / M / std::abs(k));
        if(std::abs(w - c) <= d0) s.push_back(w);
        if(std::abs(-w - c) <= d0) s.push_back(-w);
      }
    std::sort(s.begin(), s.end());
    return s;
  };
  const std::vector<double> sx = samples(p, Q.a, Q.b, q), sy = samples(q, Q.b, Q.a, p);
  const int nx = int(sx.size()), ny = int(sy.size());
  std::vector<double> grid(nx * ny);
  auto at = [&](int i, int j) { return V2(sx[i] * e1 + sy[j] * e2); };
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j) grid[i * ny + j] = E(at(i, j));
  double best = std::sqrt(E(V2::Zero())); // the origin is on the surface
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j) {
      const double e = grid[i * ny + j];
      bool local_min = true;
      for(int di = -1; di <= 1 && local_min; ++di)
        for(int dj = -1; dj <= 1; ++dj) {
          const int ii = i + di, jj = j + dj;
          if(ii < 0 || jj < 0 || ii >= nx || jj >= ny) continue;
          if(grid[ii * ny + jj] < e) { local_min = false; break; }
        }
      if(!local_min) continue;
      // damped Newton (gradient step when the Hessian is not positive definite)
      V2 u = at(i, j);
      for(int it = 0; it < 100; ++it) {
        const double s = f(u) - x[2];
        const V2 gf = 2 * H * u;
        const V2 g = 2 * (u - xt) + 2 * s * gf;
        const Eigen::Matrix2d Hs = 2 * Eigen::Matrix2d::Identity() + 2 * gf * gf.transpose() + 4 * s * H;
        V2 step;
        Eigen::LLT<Eigen::Matrix2d> llt(Hs);
        if(llt.info() == Eigen::Success) step = -llt.solve(g);
        else step = -g / (2 + Hs.norm());
        const double e0 = E(u);
        bool moved = false;
        for(int h = 0; h < 40; ++h, step *= 0.5)
          if(E(u + step) < e0) { u += step; moved = true; break; }
        if(!moved) break;
      }
      best = std::min(best, std::sqrt(E(u)));
    }
  return best;
}

void check_quadric(const Quadric& Q, const V3& x, Worst& worst, double tol = 1e-9) {
  MLS::Paraboloid_function_space<3> fs;
  const Eigen::Vector3d c(Q.a, Q.b, Q.theta);
  const auto cp = fs.closest_point(c, x);
  auto f = [&](const V2& u) { return Q(u); };
  const double scale = 1. + x.norm();
  MLS_CHECK(cp.point.allFinite() && cp.normal.allFinite() && std::isfinite(cp.signed_distance));
  const std::string desc = "a " + mls_test::fmt(Q.a) + " b " + mls_test::fmt(Q.b) + " th " + mls_test::fmt(Q.theta) +
                           " x " + mls_test::fmt(x[0]) + "," + mls_test::fmt(x[1]) + "," + mls_test::fmt(x[2]);
  MLS_CHECK_MSG(std::abs(cp.point[2] - f(cp.point.head<2>())) <= 1e-12 * (scale + std::abs(cp.point[2])), desc);
  MLS_CHECK_MSG(std::abs(cp.point[2] - fs.height(c, cp.point.head<2>())) <= 1e-12 * (scale + std::abs(cp.point[2])), desc);
  const double d = (x - cp.point).norm(), db = brute_quadric(Q, x);
  const double e = rel_error(d, db, x.norm());
  worst.add(e);
  MLS_CHECK_MSG(e <= tol, desc + " mine " + mls_test::fmt(d) + " brute " + mls_test::fmt(db));
  MLS_CHECK_NEAR(cp.normal.norm(), 1., 1e-12);
  MLS_CHECK(!cp.is_on_feature && cp.direction == V3::Zero());
  MLS_CHECK(cp.normal[2] > 0);
  // normal orthogonal to the finite-difference tangents of the graph
  const double h = 1e-6;
  const V2 u = cp.point.head<2>();
  const V3 t1(2 * h, 0, f(u + V2(h, 0)) - f(u - V2(h, 0))), t2(0, 2 * h, f(u + V2(0, h)) - f(u - V2(0, h)));
  MLS_CHECK_MSG(std::abs(cp.normal.dot(t1.normalized())) <= 1e-7, desc + " n.t1 " + mls_test::fmt(cp.normal.dot(t1.normalized())));
  MLS_CHECK_MSG(std::abs(cp.normal.dot(t2.normalized())) <= 1e-7, desc + " n.t2 " + mls_test::fmt(cp.normal.dot(t2.normalized())));
  MLS_CHECK_NEAR(std::abs(cp.signed_distance), d, 1e-14 * scale);
  MLS_CHECK_LE(((x - cp.point) - cp.signed_distance * cp.normal).norm(), 1e-7 * scale);
  const double above = x[2] - f(x.head<2>());
  if(std::abs(above) > 1e-9 * scale) MLS_CHECK((cp.signed_distance > 0) == (above > 0));
}

MLS_TEST(quadratic_3_random_against_brute_force) {
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(-2, 2), sgn(-1, 1), ang(-CGAL_PI, CGAL_PI);
  Worst worst("quadric");
  for(int i = 0; i < 600; ++i) {
    Quadric Q{(sgn(g) < 0 ? -1 : 1) * log_uniform(g, 1e-2, 10.), (sgn(g) < 0 ? -1 : 1) * log_uniform(g, 1e-2, 10.), ang(g)};
    check_quadric(Q, V3(u(g), u(g), u(g)), worst);
  }
}

MLS_TEST(quadratic_3_degenerate_cases) {
  std::mt19937 g(4);
  std::uniform_real_distribution<double> u(-2, 2), ang(-CGAL_PI, CGAL_PI), k(-3, 3);
  Worst worst("quadric degenerate");
  for(int i = 0; i < 40; ++i) {
    const V3 x(u(g), u(g), u(g));
    const double th = ang(g), a = k(g);
    check_quadric({0, 0, th}, x, worst);                    // plane
    check_quadric({a, 0, th}, x, worst);                    // cylinders
    check_quadric({0, a, th}, x, worst);
    check_quadric({a, 1e-9, th}, x, worst);                 // nearly cylindrical
    check_quadric({a, a, th}, x, worst);                    // umbilic
    check_quadric({a, -a * (1 + 1e-7), th}, x, worst);
    check_quadric({1e-12, -1e-12, th}, x, worst);           // nearly flat
    check_quadric({1e6 * a, 1e-3, th}, x, worst);           // very different curvatures
    // on the principal planes (p = 0 or q = 0): the denominators 1 + 2 a s vanish
    const double ct = std::cos(th), st = std::sin(th);
    const double p = u(g), q = u(g), r = 3 * std::abs(u(g));
    check_quadric({1., 0.4, th}, V3(-st * q, ct * q, r), worst);
    check_quadric({0.4, 1., th}, V3(ct * p, st * p, r), worst);
    check_quadric({1., -0.4, th}, V3(-st * q, ct * q, r), worst);
    check_quadric({-1., 2., th}, V3(0, 0, -r), worst);
  }
  // on the axis of an umbilic above its centre of curvature: a circle of closest points
  MLS::Paraboloid_function_space<3> fs;
  for(double b : {0.25, 0.5, 0.5 + 1e-9, 1., 5.}) {
    const V3 x(0, 0, b);
    check_quadric({1., 1., 0.3}, x, worst);
    const auto cp = fs.closest_point(V3(1., 1., 0.3), x);
    const double rho2 = std::max(0., (2 * b - 1) / 2.); // radius^2 of the circle, k = 1
    MLS_CHECK_NEAR(cp.point.head<2>().squaredNorm(), rho2, 1e-6);
  }
  // the origin, and points on the surface
  MLS_CHECK(fs.closest_point(V3(1, 2, 3), V3::Zero()).point == V3::Zero());
  for(int i = 0; i < 50; ++i) {
    const Quadric Q{k(g), k(g), ang(g)};
    const V2 w(u(g), u(g));
    check_quadric(Q, V3(w[0], w[1], w.dot(Q.H() * w)), worst);
  }
}

MLS_TEST(quadratic_fit_recovers_member) {
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(-1, 1), ang(-CGAL_PI, CGAL_PI);
  MLS::Paraboloid_function_space<3> fs3;
  MLS::Paraboloid_function_space<2> fs2;
  for(int t = 0; t < 20; ++t) {
    const Quadric Q{2 * u(g), 2 * u(g), ang(g)};
    std::vector<V3> p;
    std::vector<double> w;
    for(int i = 0; i < 30; ++i) {
      const V2 v(u(g), u(g));
      // add a plane and an offset: the fit drops them
      p.emplace_back(v[0], v[1], v.dot(Q.H() * v) + 0.3 * v[0] - 0.2 * v[1] + 0.1);
      w.push_back(0.5 + u(g) * 0.4);
    }
    const V3 c = fs3.fit(p.data(), w.data(), p.size());
    for(int i = 0; i < 10; ++i) {
      const V2 v(u(g), u(g));
      MLS_CHECK_NEAR(fs3.height(c, v), v.dot(Q.H() * v), 1e-9);
    }
    std::vector<Eigen::Vector2d> p2;
    const double k = 3 * u(g);
    for(int i = 0; i < 10; ++i) { const double s = u(g); p2.emplace_back(s, k * s * s - s + 2.); }
    MLS_CHECK_NEAR(fs2.fit(p2.data(), w.data(), p2.size())[0], k, 1e-9);
  }
  MLS_CHECK(fs3.identity() == V3::Zero());
  MLS_CHECK(fs3.closest_point(fs3.identity(), V3(0.3, -0.2, 0.7)).point == V3(0.3, -0.2, 0.));
}

// ---------------------------------------------------------------- plane
MLS_TEST(plane_closest_point) {
  MLS::Plane_function_space<3> p3;
  MLS::Plane_function_space<2> p2;
  const auto c3 = p3.closest_point(p3.identity(), V3(0.1, -2, -0.5));
  MLS_CHECK(c3.point == V3(0.1, -2, 0) && c3.normal == V3::UnitZ() && c3.signed_distance == -0.5 && !c3.is_on_feature);
  const auto c2 = p2.closest_point(p2.identity(), V2(4, 0.25));
  MLS_CHECK(c2.point == V2(4, 0) && c2.normal == V2::UnitY() && c2.signed_distance == 0.25);
}

// ---------------------------------------------------------------- 2D wedge
using Fan2 = MLS::Wedge_fan_function_space<2>;

double brute_ray(const V2& d, const V2& x) { // distance to {t d, t >= 0}, d unit
  auto E = [&](double t) { return (x - t * d).squaredNorm(); };
  const int M = 1000;
  const double T = 2 * x.norm();
  int bi = 0;
  for(int i = 1; i <= M; ++i) if(E(T * i / M) < E(T * bi / M)) bi = i;
  double t = golden(E, T * std::max(0, bi - 1) / M, T * std::min(M, bi + 1) / M);
  t = std::max(0., t + (x - t * d).dot(d)); // Newton (E is quadratic), clamped
  return std::sqrt(E(t));
}

MLS_TEST(wedge_2_random) {
  std::mt19937 g(6);
  std::uniform_real_distribution<double> u(-2, 2), ang(-7, 7);
  Fan2 fs;
  Worst worst("wedge 2D");
  int singular = 0;
  for(int i = 0; i < 3000; ++i) {
    const Eigen::Vector2d c(ang(g), ang(g));
    const V2 x(u(g), u(g));
    const V2 d1(std::cos(c[0]), std::sin(c[0])), d2(std::cos(c[1]), std::sin(c[1]));
    const auto cp = fs.closest_point(c, x);
    const double d = (x - cp.point).norm(), db = std::min(brute_ray(d1, x), brute_ray(d2, x));
    const double e = rel_error(d, db, x.norm());
    worst.add(e);
    MLS_CHECK_MSG(e <= 1e-9, mls_test::fmt(d) + " vs " + mls_test::fmt(db));
    MLS_CHECK_LE(std::min(brute_ray(d1, cp.point), brute_ray(d2, cp.point)), 1e-12 * (1 + x.norm()));
    MLS_CHECK_NEAR(cp.normal.norm(), 1., 1e-12);
    MLS_CHECK_NEAR(std::abs(cp.signed_distance), d, 1e-14);
    // apex collapse region: x . d1 <= 0 and x . d2 <= 0
    const bool in_apex_region = x.dot(d1) < -1e-12 && x.dot(d2) < -1e-12;
    if(in_apex_region) {
      MLS_CHECK(cp.point == V2::Zero() && cp.is_on_feature);
      ++singular;
    }
    if(x.dot(d1) > 1e-9 || x.dot(d2) > 1e-9) MLS_CHECK(cp.point != V2::Zero());
    if(!cp.is_on_feature) { // on a ray: normal orthogonal to it and x - point parallel to it
      const V2 r = cp.point.normalized();
      MLS_CHECK_LE(std::abs(cp.normal.dot(r)), 1e-12);
      MLS_CHECK_LE(((x - cp.point) - cp.signed_distance * cp.normal).norm(), 1e-12 * (1 + x.norm()));
    }
    // sign flips across the curve, away from the apex
    if(!cp.is_on_feature && cp.point.norm() > 1e-3) {
      const double eps = 1e-6 * cp.point.norm();
      MLS_CHECK(fs.closest_point(c, cp.point + eps * cp.normal).signed_distance > 0);
      MLS_CHECK(fs.closest_point(c, cp.point - eps * cp.normal).signed_distance < 0);
    }
  }
  std::cout << "       wedge 2D: " << singular << " queries in the apex collapse region\n";
  MLS_CHECK(singular > 100);
}

MLS_TEST(wedge_2_plane_and_orientation) {
  Fan2 fs;
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for(int i = 0; i < 100; ++i) {
    const V2 x(u(g), u(g));
    const auto cp = fs.closest_point(fs.identity(), x);
    MLS_CHECK_NEAR((cp.point - V2(x[0], 0)).norm(), 0., 1e-15);
    MLS_CHECK_NEAR(cp.signed_distance, x[1], 1e-15);
    MLS_CHECK(!cp.is_on_feature && cp.normal[1] > 1 - 1e-15);
    // swapped and shifted by 2 pi: the same member
    const auto cq = fs.closest_point(Eigen::Vector2d(CGAL_PI + 2 * CGAL_PI, -2 * CGAL_PI), x);
    MLS_CHECK_NEAR((cq.point - cp.point).norm(), 0., 1e-14);
    MLS_CHECK_NEAR(cq.signed_distance, cp.signed_distance, 1e-14);
  }
  // a valley (inside is up) and a ridge (outside is up): the apex normal is +e2
  for(const Eigen::Vector2d c : {Eigen::Vector2d(CGAL_PI / 4, 3 * CGAL_PI / 4), Eigen::Vector2d(-CGAL_PI / 4, -3 * CGAL_PI / 4)}) {
    const auto above = fs.closest_point(c, V2(0, 1)), below = fs.closest_point(c, V2(0, -1));
    MLS_CHECK(above.signed_distance > 0 && below.signed_distance < 0);
    const auto& apex = (c[0] > 0) ? below : above;
    MLS_CHECK(apex.is_on_feature && apex.point == V2::Zero());
    MLS_CHECK_NEAR((apex.normal - V2(0, 1)).norm(), 0., 1e-15);
  }
  // the initial member (sector fit, apex at the origin) reproduces a line and a wedge through it
  for(const double slope_right : {0.3, -1.2}) {
    std::vector<V2> p;
    std::vector<double> w;
    for(int i = 0; i < 20; ++i) {
      const double s = u(g);
      p.emplace_back(s, s > 0 ? slope_right * s : 0.3 * s);
      w.push_back(1.);
    }
    const Eigen::Vector2d c = fs.fit(p.data(), w.data(), p.size());
    for(const V2& q : p) MLS_CHECK_NEAR(fs.closest_point(c, q).signed_distance, 0., 1e-14);
  }
}

// ---------------------------------------------------------------- 3D fan
template <int N> using Fan3 = MLS::Wedge_fan_function_space<3, N>;

// Independent brute force: distance to the cone {a v + b w, a, b >= 0}, by maximising x . u(phi)
// over the unit vectors u of the arc from v to w (dense sampling, golden section, Newton).
double brute_cone(const V3& v, const V3& w, const V3& x) {
  const double Phi = std::acos(std::clamp(v.dot(w), -1., 1.));
  V3 e2 = w - v.dot(w) * v;
  if(e2.norm() < 1e-12) return std::sqrt((x - std::max(0., x.dot(v)) * v).squaredNorm());
  e2.normalize();
  const double A = x.dot(v), B = x.dot(e2);
  auto F = [&](double phi) { return -(A * std::cos(phi) + B * std::sin(phi)); };
  const int M = 1000;
  int bi = 0;
  for(int i = 1; i <= M; ++i) if(F(Phi * i / M) < F(Phi * bi / M)) bi = i;
  double phi = golden(F, Phi * std::max(0, bi - 1) / M, Phi * std::min(M, bi + 1) / M);
  for(int it = 0; it < 3; ++it) {
    const double g = A * std::sin(phi) - B * std::cos(phi), h = A * std::cos(phi) + B * std::sin(phi);
    if(h > 0) phi = std::clamp(phi - g / h, 0., Phi);
  }
  const V3 uu = std::cos(phi) * v + std::sin(phi) * e2;
  return (x - std::max(0., x.dot(uu)) * uu).norm();
}

template <int N>
double brute_fan(const Eigen::Matrix<double, 2 * N, 1>& c, const V3& x) {
  std::vector<std::pair<double, V3>> vs;
  for(int i = 0; i < N; ++i) {
    double lon = std::fmod(c[2 * i + 1], 2 * CGAL_PI);
    if(lon < 0) lon += 2 * CGAL_PI;
    vs.emplace_back(lon, V3(std::cos(c[2 * i]) * std::cos(c[2 * i + 1]), std::cos(c[2 * i]) * std::sin(c[2 * i + 1]),
                            std::sin(c[2 * i])));
  }
  std::sort(vs.begin(), vs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  double best = x.norm();
  for(int i = 0; i < N; ++i) best = std::min(best, brute_cone(vs[i].second, vs[(i + 1) % N].second, x));
  return best;
}

template <int N>
void random_fans(unsigned seed, int count, Worst& worst) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-2, 2), lat(-1.4, 1.4), lon(-7, 7);
  Fan3<N> fs;
  for(int t = 0; t < count; ++t) {
    Eigen::Matrix<double, 2 * N, 1> c;
    for(int i = 0; i < N; ++i) { c[2 * i] = lat(g); c[2 * i + 1] = lon(g); }
    const auto prepared = fs.prepare_member(c);
    for(int j = 0; j < 10; ++j) {
      const V3 x(u(g), u(g), u(g));
      const auto cp = fs.closest_point(c, x);
      // the fan prepared once gives the same closest point, to the last bit (the implicit
      // function's values must not depend on it)
      const auto q = fs.closest_point(prepared, x);
      MLS_CHECK(q.point == cp.point && q.normal == cp.normal && q.signed_distance == cp.signed_distance &&
                q.is_on_feature == cp.is_on_feature && q.direction == cp.direction);
      const double d = (x - cp.point).norm(), db = brute_fan<N>(c, x);
      const double e = rel_error(d, db, x.norm());
      worst.add(e);
      MLS_CHECK_MSG(e <= 1e-9, mls_test::fmt(d) + " vs " + mls_test::fmt(db));
      MLS_CHECK_LE(brute_fan<N>(c, cp.point), 1e-12 * (1 + x.norm()));
      MLS_CHECK_NEAR(cp.normal.norm(), 1., 1e-12);
      MLS_CHECK_NEAR(std::abs(cp.signed_distance), d, 1e-14 * (1 + x.norm()));
      if(cp.is_on_feature) {
        if(cp.direction != V3::Zero()) { // crease: the point is on the ray
          MLS_CHECK_NEAR(cp.direction.norm(), 1., 1e-12);
          MLS_CHECK_LE(cp.point.cross(cp.direction).norm(), 1e-12 * (1 + x.norm()));
        } else {
          MLS_CHECK(cp.point == V3::Zero());
        }
      } else if(d > 1e-6) {
        // smooth: x - point along the normal, and nearby queries project in the tangent plane
        MLS_CHECK_LE(((x - cp.point) - cp.signed_distance * cp.normal).norm(), 1e-12 * (1 + x.norm()));
        MLS_CHECK_LE(std::abs(cp.normal.dot(cp.point)), 1e-12 * (1 + x.norm())); // plane through apex
        const V3 delta = 1e-7 * V3(u(g), u(g), u(g));
        const auto cq = fs.closest_point(c, x + delta);
        if(!cq.is_on_feature && (cq.normal - cp.normal).norm() < 1e-12)
          MLS_CHECK_LE(std::abs(cp.normal.dot(cq.point - cp.point)), 1e-14 * (1 + x.norm()) + 1e-9 * delta.norm());
      }
    }
  }
}

MLS_TEST(wedge_fan_3_random_against_brute_force) {
  Worst w4("fan N=4"), w3("fan N=3"), w6("fan N=6");
  random_fans<4>(8, 300, w4);
  random_fans<3>(9, 100, w3);
  random_fans<6>(10, 100, w6);
}

// The derivatives of the closest point by the parameters and by the query (the closest-point
// operators' Jacobian of C(r)) against central differences, on a cone and on a ray; queries whose
// piece changes within the difference step are skipped. At the apex they are one-sided, and on
// the fan (the closest point of a query, queried again) they exist on the faces only.
template <int D, class Space>
void check_foot_derivatives(const Space& fs, unsigned seed, std::array<int, 5>& pieces, double& worst) {
  constexpr int P = Space::number_of_parameters;
  using V = Eigen::Matrix<double, D, 1>;
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-2, 2), lat(-1.4, 1.4), lon(-7, 7);
  for(int t = 0; t < 2000; ++t) {
    typename Space::Parameters c;
    for(int i = 0; i < P; ++i) c[i] = (D == 3 && i % 2 == 0) ? lat(g) : lon(g);
    V x;
    for(int i = 0; i < D; ++i) x[i] = u(g);
    for(int on_fan = 0; on_fan < 2; ++on_fan) {
      if(on_fan) x = fs.closest_point(c, x).point;
      Eigen::Matrix<double, D, P> dc;
      Eigen::Matrix<double, D, D> dx;
      MLS::Closest_point<D> cp;
      const bool exact = fs.closest_point_derivatives(c, x, cp, dc, dx);
      MLS_CHECK((cp.point - fs.closest_point(c, x).point).norm() == 0.);
      // on the fan, the derivatives exist on the faces: the cones in 3D, the rays in 2D
      const bool on_face = !cp.is_on_feature && cp.point != V::Zero() && exact;
      if(on_fan) {
        if(!exact) ++pieces[4];
        else ++pieces[3];
        if(!exact) continue;
      } else {
        // off the fan, one-sided at the apex only (random fans have no coplanar cones)
        MLS_CHECK(exact == (cp.point != V::Zero()));
        if(!exact) {
          ++pieces[2];
          continue;
        }
      }
      const double eps = 1e-6;
      const auto central = [&](const auto& move) -> std::optional<V> {
        const V plus = move(eps), minus = move(-eps);
        const V forward = (plus - cp.point) / eps, backward = (cp.point - minus) / eps;
        if((forward - backward).norm() > 1e-4 * (1 + forward.norm())) return std::nullopt; // another piece
        return V((plus - minus) / (2 * eps));
      };
      bool same_piece = true;
      double error = 0;
      for(int j = 0; j < P + D; ++j) {
        const auto d = central([&](double e) {
          typename Space::Parameters ce = c;
          V xe = x;
          if(j < P) ce[j] += e;
          else xe[j - P] += e;
          return V(fs.closest_point(ce, xe).point);
        });
        if(!d) {
          same_piece = false;
          break;
        }
        error = std::max(error, ((j < P ? V(dc.col(j)) : V(dx.col(j - P))) - *d).norm());
      }
      if(on_fan) MLS_CHECK(on_face && (!same_piece || error <= 1e-6 * (1 + x.norm())));
      if(!same_piece || on_fan) continue;
      worst = std::max(worst, error);
      MLS_CHECK_LE(error, 1e-6 * (1 + x.norm()));
      ++pieces[(cp.is_on_feature || D == 2) ? 1 : 0];
    }
  }
}

MLS_TEST(wedge_fan_foot_derivatives) {
  for(int D : {2, 3}) {
    std::array<int, 5> pieces{}; // off the fan: cone, ray, one-sided; on it: derivatives, one-sided
    double worst = 0;
    if(D == 2) check_foot_derivatives<2>(Fan2(), 11, pieces, worst);
    else check_foot_derivatives<3>(Fan3<4>(), 12, pieces, worst);
    std::cout << "       " << D << "D, off the fan: " << pieces[0] << " on cones, " << pieces[1] << " on rays, "
              << pieces[2] << " one-sided (apex), worst error " << worst << "; on the fan: " << pieces[3]
              << " differentiable, " << pieces[4] << " one-sided\n";
    if(D == 3) MLS_CHECK(pieces[0] > 200);
    MLS_CHECK(pieces[1] > 200);
    MLS_CHECK(pieces[2] > 50);
    MLS_CHECK(pieces[3] > 1000);
    MLS_CHECK(pieces[4] > (D == 2 ? 200 : 500));
  }
}

// The two half-planes {s e_x + t w1}, {s e_x + t w2}, t >= 0, of an edge along e_x.
MLS_TEST(wedge_fan_3_edge) {
  std::mt19937 g(11);
  std::uniform_real_distribution<double> u(-2, 2), phi(-1.5, 1.5);
  Fan3<4> fs;
  Worst worst("edge");
  int singular = 0, smooth = 0;
  for(int t = 0; t < 200; ++t) {
    const double p1 = phi(g), p2 = phi(g);
    const V3 w1(0, std::cos(p1), std::sin(p1)), w2(0, -std::cos(p2), std::sin(p2));
    Eigen::Matrix<double, 8, 1> c;
    c << 0, 0, p1, CGAL_PI / 2, 0, CGAL_PI, p2, 3 * CGAL_PI / 2;
    for(int j = 0; j < 20; ++j) {
      V3 x(u(g), u(g), u(g));
      if(j % 4 == 0) x[0] *= 1e-3; // near the crease
      const auto proj = [&](const V3& w) -> V3 { return V3(x[0], 0, 0) + std::max(0., x.dot(w)) * w; };
      const double d1 = (x - proj(w1)).norm(), d2 = (x - proj(w2)).norm();
      const auto cp = fs.closest_point(c, x);
      const double d = (x - cp.point).norm();
      const double e = rel_error(d, std::min(d1, d2), x.norm());
      worst.add(e);
      MLS_CHECK(e <= 1e-9);
      // collapse region: the components of x across the edge point away from both faces
      const V3 perp(0, x[1], x[2]);
      if(perp.dot(w1) < -1e-9 && perp.dot(w2) < -1e-9) {
        ++singular;
        MLS_CHECK(cp.is_on_feature);
        MLS_CHECK_NEAR((cp.point - V3(x[0], 0, 0)).norm(), 0., 1e-15 * (1 + x.norm()));
        MLS_CHECK_NEAR(std::abs(cp.direction.dot(V3::UnitX())), 1., 1e-15);
        MLS_CHECK_NEAR(cp.direction.dot(V3::UnitX()), x[0] >= 0 ? 1. : -1., 1e-15);
        // normal: the normalised sum of the up normals of the two faces
        V3 n1 = V3::UnitX().cross(w1).normalized(), n2 = w2.cross(V3::UnitX()).normalized();
        MLS_CHECK_NEAR((cp.normal - (n1 + n2).normalized()).norm(), 0., 1e-12);
      } else if(perp.dot(w1) > 1e-9 || perp.dot(w2) > 1e-9) {
        if(std::abs(d1 - d2) > 1e-9) { // off the medial surface: above a face
          ++smooth;
          MLS_CHECK(!cp.is_on_feature);
        }
      }
    }
  }
  std::cout << "       edge: " << singular << " queries in crease collapse regions, " << smooth << " above a face\n";
  MLS_CHECK(singular > 100 && smooth > 100);
}

// A cube corner: the boundary of the positive octant, in a frame whose normal is (1,1,1)/sqrt 3.
MLS_TEST(wedge_fan_3_cube_corner) {
  const V3 n = V3(1, 1, 1).normalized();
  const V3 t1 = V3(1, -1, 0).normalized(), t2 = n.cross(t1);
  Eigen::Matrix3d R;
  R.row(0) = t1;
  R.row(1) = t2;
  R.row(2) = n; // frame coordinates = R * world
  // the three edges and, between e_x and e_y, a fourth vector in their face
  const V3 vs[4] = {V3::UnitX(), V3(1, 1, 0).normalized(), V3::UnitY(), V3::UnitZ()};
  Eigen::Matrix<double, 8, 1> c;
  for(int i = 0; i < 4; ++i) {
    const V3 v = R * vs[i];
    c[2 * i] = std::asin(v[2]);
    c[2 * i + 1] = std::atan2(v[1], v[0]);
  }
  Fan3<4> fs;
  std::mt19937 g(12);
  std::uniform_real_distribution<double> u(-2, 2);
  Worst worst("cube corner");
  int apex = 0, crease = 0, face = 0;
  for(int i = 0; i < 5000; ++i) {
    const V3 x(u(g), u(g), u(g)); // world
    double dexp = HUGE_VAL;
    for(int k = 0; k < 3; ++k) { // quarter-plane x_k = 0, other coordinates clamped to >= 0
      V3 y = x.cwiseMax(0.);
      y[k] = 0;
      dexp = std::min(dexp, (x - y).norm());
    }
    const auto cp = fs.closest_point(c, R * x);
    const double e = rel_error((R * x - cp.point).norm(), dexp, x.norm());
    worst.add(e);
    MLS_CHECK(e <= 1e-9);
    const V3 pw = R.transpose() * cp.point;
    const int negatives = (x[0] < -1e-9) + (x[1] < -1e-9) + (x[2] < -1e-9);
    if(negatives == 3) { // the apex collapse region
      ++apex;
      MLS_CHECK(cp.is_on_feature && cp.point == V3::Zero() && cp.direction == V3::Zero());
      MLS_CHECK_NEAR((R.transpose() * cp.normal - n).norm(), 0., 1e-12);
    } else if(negatives == 2) { // the crease along the positive axis
      ++crease;
      const int k = x[0] >= -1e-9 ? 0 : (x[1] >= -1e-9 ? 1 : 2);
      MLS_CHECK(cp.is_on_feature);
      MLS_CHECK_NEAR((R.transpose() * cp.direction - V3::Unit(k)).norm(), 0., 1e-12);
      MLS_CHECK_NEAR((pw - x[k] * V3::Unit(k)).norm(), 0., 1e-12);
    } else if(x.minCoeff() > 1e-9 || negatives == 1) {
      // above a face (inside the octant: the nearest face, away from the medial surface)
      V3 s = x;
      std::sort(s.data(), s.data() + 3);
      if(negatives == 1 || s[1] - s[0] > 1e-9) {
        ++face;
        MLS_CHECK(!cp.is_on_feature);
      }
    }
    MLS_CHECK_NEAR(cp.normal.norm(), 1., 1e-12);
    if(!cp.is_on_feature) MLS_CHECK_NEAR(std::abs((R.transpose() * cp.normal).maxCoeff()), 1., 1e-12);
  }
  std::cout << "       cube corner: " << apex << " apex, " << crease << " crease, " << face << " face queries\n";
  MLS_CHECK(apex > 100 && crease > 100 && face > 100);
}

MLS_TEST(wedge_fan_3_plane_and_fit) {
  std::mt19937 g(13);
  std::uniform_real_distribution<double> u(-2, 2);
  Fan3<4> fs;
  Fan3<5> fs5;
  for(int i = 0; i < 500; ++i) {
    const V3 x(u(g), u(g), u(g));
    for(const auto& cp : {fs.closest_point(fs.identity(), x), fs5.closest_point(fs5.identity(), x)}) {
      MLS_CHECK_NEAR((cp.point - V3(x[0], x[1], 0)).norm(), 0., 1e-14);
      MLS_CHECK_NEAR(cp.signed_distance, x[2], 1e-14);
      MLS_CHECK(!cp.is_on_feature && cp.normal == V3::UnitZ());
    }
  }
  // on the axis: the apex of a flat fan is a smooth point
  const auto ca = fs.closest_point(fs.identity(), V3(0, 0, -1));
  MLS_CHECK(!ca.is_on_feature && ca.point.norm() == 0 && ca.signed_distance == -1);
  // the initial member (apex at the origin) reproduces a tilted plane through the origin
  std::vector<V3> p;
  std::vector<double> w;
  for(int i = 0; i < 60; ++i) {
    const double a = u(g), b = u(g);
    p.emplace_back(a, b, 0.4 * a - 0.7 * b);
    w.push_back(1. + 0.5 * u(g));
  }
  const auto c = fs.fit(p.data(), w.data(), p.size());
  for(const V3& q : p) {
    const auto cp = fs.closest_point(c, q);
    MLS_CHECK_NEAR(cp.signed_distance, 0., 1e-14);
    MLS_CHECK(!cp.is_on_feature);
    MLS_CHECK_NEAR((cp.normal - V3(-0.4, 0.7, 1).normalized()).norm(), 0., 1e-12);
  }
  // and follows an edge along the first axis: the faces' sectors are exact
  p.clear();
  w.assign(400, 1.);
  for(int i = 0; i < 400; ++i) {
    const double a = u(g), b = u(g);
    p.emplace_back(a, b, b > 0 ? 0.4 * b : -0.7 * b);
  }
  const auto ce = fs.fit(p.data(), w.data(), p.size());
  MLS_CHECK_NEAR(std::tan(ce[2]), 0.4, 1e-12);  // the sector around +y
  MLS_CHECK_NEAR(std::tan(ce[6]), 0.7, 1e-12);  // the sector around -y
  // sign flips across each face of a random fan
  Eigen::Matrix<double, 8, 1> cr;
  cr << 0.3, 0.1, -0.4, 1.9, 0.2, 3.3, 0.5, 4.9;
  int flips = 0;
  for(int i = 0; i < 500; ++i) {
    const auto cp = fs.closest_point(cr, V3(u(g), u(g), u(g)));
    if(cp.is_on_feature || cp.point.norm() < 1e-2) continue;
    const double eps = 1e-6 * cp.point.norm();
    MLS_CHECK(fs.closest_point(cr, cp.point + eps * cp.normal).signed_distance > 0);
    MLS_CHECK(fs.closest_point(cr, cp.point - eps * cp.normal).signed_distance < 0);
    ++flips;
  }
  MLS_CHECK(flips > 100);
}

} // namespace

// The first and second derivatives of each weight with respect to the squared distance against
// central differences, in units of the squared support radius R^2 (relative step 1e-5: truncation
// error of order 1e-10, rounding 1e-11 for the first derivative, 1e-6 for the second), the
// overload given the weight equal to it exactly, `evaluate()` equal to the three up to rounding;
// zero beyond the support.
MLS_TEST(weight_derivatives) {
  const double h = 0.3;
  for(const MLS::Weight_kind kind : {MLS::Weight_kind::POLYNOMIAL, MLS::Weight_kind::GAUSSIAN, MLS::Weight_kind::WENDLAND}) {
    const MLS::Weight_function w(kind, h);
    const double R2 = w.support_radius() * w.support_radius();
    double worst = 0, worst_second = 0;
    for(double t = 0.01; t < 1; t += 0.01) {
      const double d2 = t * R2, eps = 1e-5 * d2;
      const double fd = (w(d2 + eps) - w(d2 - eps)) / (2 * eps);
      const double fd2 = (w.derivative(d2 + eps) - w.derivative(d2 - eps)) / (2 * eps);
      worst = std::max(worst, std::abs(w.derivative(d2) - fd) * R2);
      double value = 0, first = 0, second = 0;
      MLS_CHECK(w.evaluate(d2, value, first, second));
      MLS_CHECK_NEAR(value, w(d2), 1e-15);
      MLS_CHECK_NEAR(first, w.derivative(d2), 1e-14 * std::abs(first));
      worst_second = std::max(worst_second, std::abs(second - fd2) * R2 * R2);
      MLS_CHECK(w.derivative(d2, w(d2)) == w.derivative(d2));
    }
    const char* name = kind == MLS::Weight_kind::GAUSSIAN ? "Gaussian" : kind == MLS::Weight_kind::WENDLAND ? "Wendland" : "polynomial";
    std::cout << "       " << name << ": worst error of the derivatives " << worst << " / R^2, " << worst_second << " / R^4\n";
    MLS_CHECK_LE(worst, 1e-8);
    MLS_CHECK_LE(worst_second, 1e-5);
    double value = 0, first = 0, second = 0;
    MLS_CHECK(!w.evaluate(1.5 * R2, value, first, second));
    MLS_CHECK(w.derivative(1.5 * R2) == 0. && w.derivative(1.5 * R2, 0.) == 0. && w(1.5 * R2) == 0.);
  }
}

int main(int argc, char** argv) { return mls_test::run_all(argc, argv); }
