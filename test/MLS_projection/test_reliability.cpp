// Reliability tests of the operators (issue 6):
//  - bad_input_*: the inputs of the command-line bad-input suite (tools/bad_input/), given to
//    the library: every operator (Levin with the polynomial and plane spaces, Unified with the
//    quadratic and wedge-fan spaces, Mixed) returns a status for every query, never throws from
//    project(), never returns a NaN or infinite point or normal, keeps the query with a null
//    normal on failure, returns a unit normal on success, and (where the input defines a shape)
//    lands on it;
//  - threads_*: determinism and thread safety: bit-identical results for 1 and 2 TBB threads,
//    for repeated runs, and for concurrent calls of one operator from several std::threads (the
//    ThreadSanitizer run of scripts/test-sanitizers runs these).
//
// Tolerances. The shapes are spheres of radius 1 sampled with 600 Fibonacci points (spacing
// about 0.14, h about 0.3 with k = 16), circles with 100 points in 2D: the quadratic fit misses
// by about h^4/(8R^3) times a window factor, the plane fit by about h^2/(2R) = 0.045 (see
// test_levin_projection.cpp); the wedge fan, a fold of two planes, does little better than the
// plane. Measured worst distances: Levin quadratic 3.1e-3, Levin plane 0.051, Unified quadratic
// and Mixed 2.5e-3, Unified wedge 0.038, 2D 1.2e-4. The checks allow 0.01 (quadratic spaces) and
// 0.1 (plane and wedge fan), two to three times these, and catch any projection that leaves the
// surface (a wrong frame misses by about h = 0.3).
// Offsets and scales: the sample set works in coordinates centred at the (long double)
// centroid, so a translated or scaled input must give the translated or scaled results up to
// the rounding of the input coordinates (1e6 has an ulp of 1.2e-10) amplified by the optimiser's
// tolerance (1e-12 relative, forward-difference Jacobians with steps 1.5e-8, so the frame is
// found to about 1e-7 h): 1e-5 of the radius leaves a margin and still catches any loss of
// precision (a fit in world coordinates at 1e6 loses about 1e-4) or an absolute threshold that
// does not scale (at 1e-9 such a threshold fails every query).

#include "test_framework.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/project_points.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

using K = CGAL::Simple_cartesian<double>;
namespace MLS = CGAL::MLS;
using P2 = K::Point_2;
using P3 = K::Point_3;

namespace {

const double nan_ = std::numeric_limits<double>::quiet_NaN();
const double inf_ = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Point types in D dimensions.

template <int D> struct Dim;
template <> struct Dim<2> {
  using Point = P2;
  static Point make(const Eigen::Vector3d& v) { return Point(v[0], v[1]); }
  static Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), 0); }
  static Eigen::Vector3d eigen(const K::Vector_2& v) { return Eigen::Vector3d(v.x(), v.y(), 0); }
};
template <> struct Dim<3> {
  using Point = P3;
  static Point make(const Eigen::Vector3d& v) { return Point(v[0], v[1], v[2]); }
  static Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }
  static Eigen::Vector3d eigen(const K::Vector_3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
};

/// The unit sphere (3D, Fibonacci) or circle (2D) with n points, as 3-vectors (z = 0 in 2D).
template <int D>
std::vector<Eigen::Vector3d> round_shape(int n) {
  std::vector<Eigen::Vector3d> pts;
  const double golden = CGAL_PI * (3 - std::sqrt(5.));
  for(int i = 0; i < n; ++i) {
    if(D == 3) {
      const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), t = golden * i;
      pts.emplace_back(r * std::cos(t), r * std::sin(t), z);
    } else {
      const double t = 2 * CGAL_PI * i / n;
      pts.emplace_back(std::cos(t), std::sin(t), 0);
    }
  }
  return pts;
}

/// One bad input: its points, the options, and what is expected.
struct Bad_case {
  std::string name;
  std::vector<Eigen::Vector3d> points;
  MLS::Projection_options options;
  enum Expect { ANY, ALL_FAIL, ON_SHAPE } expect = ANY;
  /// ON_SHAPE: the round shapes (centre, radius) the results must lie on; queries are near them.
  std::vector<std::pair<Eigen::Vector3d, double>> shapes;
};

/// The cases of the bad-input suite, in D dimensions (the file-level cases, missing file, empty
/// file, a directory, garbage, truncated PLY, unwritable output and unknown option, belong to
/// the tools; NaN and inf coordinates reach the library as points to drop).
template <int D>
std::vector<Bad_case> bad_cases() {
  const int n = D == 3 ? 600 : 100;
  std::vector<Bad_case> cases;
  const auto shape = round_shape<D>(n);
  const Eigen::Vector3d O = Eigen::Vector3d::Zero();
  auto add = [&](std::string name, std::vector<Eigen::Vector3d> pts, Bad_case::Expect e,
                 std::vector<std::pair<Eigen::Vector3d, double>> shapes = {}) {
    Bad_case c;
    c.name = std::move(name);
    c.points = std::move(pts);
    c.expect = e;
    c.shapes = std::move(shapes);
    cases.push_back(std::move(c));
    return &cases.back();
  };
  add("empty", {}, Bad_case::ALL_FAIL);
  add("1 point", {Eigen::Vector3d(0.5, 0.25, D == 3 ? 0.125 : 0)}, Bad_case::ALL_FAIL);
  add("2 points", {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)}, Bad_case::ALL_FAIL);
  add("3 points", {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}, Bad_case::ANY);
  add("all identical", std::vector<Eigen::Vector3d>(50, Eigen::Vector3d(1, 2, D == 3 ? 3 : 0)), Bad_case::ALL_FAIL);
  {
    std::vector<Eigen::Vector3d> line;
    for(int i = 0; i < 50; ++i) line.emplace_back(0.1 * i, 0.05 * i, D == 3 ? -0.02 * i : 0);
    // A line is a valid curve in 2D, but spans no plane in 3D.
    add("collinear", line, D == 3 ? Bad_case::ALL_FAIL : Bad_case::ANY);
  }
  if(D == 3) {
    std::vector<Eigen::Vector3d> plane;
    for(int i = 0; i < 20; ++i)
      for(int j = 0; j < 20; ++j) plane.emplace_back(0.05 * i, 0.05 * j, 0.3 * 0.05 * i - 0.2 * 0.05 * j + 1);
    add("coplanar", plane, Bad_case::ANY); // checked below: results on the plane
  }
  {
    std::vector<Eigen::Vector3d> two = shape;
    const Eigen::Vector3d far(1e5, D == 3 ? -1e5 : 1e5, 0);
    for(const auto& p : shape) two.push_back(p + far);
    add("two far clusters", two, Bad_case::ON_SHAPE, {{O, 1.}, {far, 1.}});
  }
  {
    const Eigen::Vector3d off(1e6, -1e6, D == 3 ? 1e6 : 0);
    std::vector<Eigen::Vector3d> pts;
    for(const auto& p : shape) pts.push_back(p + off);
    add("offset 1e6", pts, Bad_case::ON_SHAPE, {{off, 1.}});
  }
  {
    std::vector<Eigen::Vector3d> pts;
    for(const auto& p : shape) pts.push_back(1e-9 * p);
    add("scale 1e-9", pts, Bad_case::ON_SHAPE, {{O, 1e-9}});
  }
  {
    // NaN and inf coordinates are dropped by the sample set; the rest is the sphere.
    std::vector<Eigen::Vector3d> pts = shape;
    pts.insert(pts.begin() + 7, Eigen::Vector3d(nan_, 0, 0));
    pts.insert(pts.begin() + 30, Eigen::Vector3d(0, inf_, 0));
    pts.push_back(Eigen::Vector3d(-inf_, nan_, 0));
    add("NaN and inf coordinates", pts, Bad_case::ON_SHAPE, {{O, 1.}});
  }
  add("huge k", shape, Bad_case::ANY)->options.k = 1 << 30;
  add("negative h", shape, Bad_case::ON_SHAPE, {{O, 1.}})->options.bandwidth = -1;
  add("zero h", shape, Bad_case::ON_SHAPE, {{O, 1.}})->options.bandwidth = 0;
  add("tiny h", shape, Bad_case::ALL_FAIL)->options.bandwidth = 1e-12;
  add("huge h", shape, Bad_case::ANY)->options.bandwidth = 1e12;
  add("NaN h", shape, Bad_case::ON_SHAPE, {{O, 1.}})->options.bandwidth = nan_;
  return cases;
}

/// Queries for a case: about `count` input points, half as many points off them, and the
/// pathological queries (NaN, inf, 1e300), which are last.
template <int D>
std::vector<Eigen::Vector3d> queries_of(const Bad_case& c, std::size_t count, std::size_t& number_of_bad) {
  std::vector<Eigen::Vector3d> q;
  std::vector<Eigen::Vector3d> finite;
  for(const auto& p : c.points)
    if(p.allFinite()) finite.push_back(p);
  const std::size_t stride = (std::max<std::size_t>)(1, finite.size() / count);
  for(std::size_t i = 0; i < finite.size(); i += stride) q.push_back(finite[i]);
  std::mt19937 gen(5);
  std::normal_distribution<double> g;
  for(std::size_t i = 0; i < finite.size() && i < count / 2 * stride; i += stride) {
    // 5% of the local size off the input point, along a random direction
    double scale = 0.05;
    if(!c.shapes.empty()) scale *= c.shapes.front().second;
    Eigen::Vector3d d = mls_test::random_vector(g, gen);
    if(D == 2) d[2] = 0;
    q.push_back(finite[i] + scale * d.normalized());
  }
  if(finite.empty()) q.emplace_back(0.5, 0.5, 0.);
  const std::vector<Eigen::Vector3d> bad = {Eigen::Vector3d(nan_, 0, 0), Eigen::Vector3d(0, inf_, 0),
                                            Eigen::Vector3d(-inf_, nan_, 0), Eigen::Vector3d(1e300, -1e300, 0)};
  number_of_bad = 3; // NaN/inf ones must be INVALID_QUERY; 1e300 may fail or succeed
  q.insert(q.end(), bad.begin(), bad.end());
  return q;
}

/// The kind of the fits `Op` makes when it does not fall back (a mixed operator: either).
template <class Op> struct Own_fit_kind { static constexpr bool is_mixed = true; };
template <class GT, class S> struct Own_fit_kind<MLS::Levin_projection<GT, S>> {
  static constexpr bool is_mixed = false;
  static constexpr MLS::Local_fit_kind value = MLS::Local_fit_kind::LEVIN;
};
template <class GT, class S, MLS::Operator_kind kind> struct Own_fit_kind<MLS::Closest_point_projection<GT, S, kind>> {
  static constexpr bool is_mixed = false;
  static constexpr MLS::Local_fit_kind value = MLS::Local_fit_kind::CLOSEST_POINT;
};

/// Whether `r`, a result of `Op`, names the operator that made its fit: none for a failure,
/// Levin's for a fallback.
template <class Op, class Result>
bool has_expected_fit_kind(const Result& r) {
  if(!r.is_success()) return r.fit_kind == MLS::Local_fit_kind::NONE;
  if(r.status == MLS::Projection_status::LEVIN_FALLBACK) return r.fit_kind == MLS::Local_fit_kind::LEVIN;
  if constexpr(Own_fit_kind<Op>::is_mixed)
    return r.fit_kind == MLS::Local_fit_kind::LEVIN || r.fit_kind == MLS::Local_fit_kind::CLOSEST_POINT;
  else
    return r.fit_kind == Own_fit_kind<Op>::value;
}

/// Runs every case through `Op` and checks the properties listed at the top of this file.
/// `queries_per_case`: about as many input points are projected. The closest-point operators
/// cost about a second per query on these sets (tens of Levin projections each, and this test
/// also runs under the sanitizers), so they get 2 queries per case (`is_heavy`) and skip the
/// cases that give their sample set and options the same sphere as "offset 1e6" (NaN points,
/// negative, zero and NaN h): these are handled before any operator code (Sample_set,
/// Operator_base) and checked with Levin.
template <class Op>
void check_bad_inputs(const char* op_name, std::size_t queries_per_case, bool is_heavy = false) {
  constexpr int D = Op::dimension;
  using T = Dim<D>;
  for(const Bad_case& c : bad_cases<D>()) {
    if(is_heavy && (c.name == "NaN and inf coordinates" || c.name == "negative h" || c.name == "zero h" || c.name == "NaN h"))
      continue;
    const std::string where = std::string(op_name) + " " + std::to_string(D) + "D, " + c.name;
    std::vector<typename T::Point> pts;
    for(const auto& p : c.points) pts.push_back(T::make(p));
    std::optional<Op> op;
    try {
      op.emplace(pts, c.options);
    } catch(const std::exception& e) {
      MLS_CHECK_MSG(false, where + ": the constructor threw " + e.what());
      continue;
    }
    std::size_t number_of_invalid = 0;
    const auto start = std::chrono::steady_clock::now();
    const auto queries = queries_of<D>(c, queries_per_case, number_of_invalid);
    const std::size_t first_bad = queries.size() - 4;
    std::size_t successes = 0, finite_queries = 0;
    double worst = 0;
    for(std::size_t i = 0; i < queries.size(); ++i) {
      const std::string at = where + ", query " + std::to_string(i);
      const typename T::Point query = T::make(queries[i]);
      typename Op::Result r;
      try {
        r = op->project(query);
      } catch(const std::exception& e) {
        MLS_CHECK_MSG(false, at + ": project() threw " + e.what());
        continue;
      } catch(...) {
        MLS_CHECK_MSG(false, at + ": project() threw");
        continue;
      }
      const Eigen::Vector3d p = T::eigen(r.point), n = T::eigen(r.normal);
      const bool query_is_finite = queries[i].allFinite();
      // Never a NaN: the point is finite unless the query was not (then it is the query).
      if(query_is_finite) MLS_CHECK_MSG(p.allFinite(), at + ": non-finite point");
      MLS_CHECK_MSG(n.allFinite(), at + ": non-finite normal");
      MLS_CHECK_MSG(std::isfinite(r.energy), at + ": non-finite energy");
      if(i >= first_bad && i < first_bad + number_of_invalid)
        MLS_CHECK_MSG(r.status == MLS::Projection_status::INVALID_QUERY,
                      at + ": a non-finite query gives " + MLS::to_string(r.status));
      // The fit's kind names the operator that made it: a fallback's is Levin's, a failure has none.
      MLS_CHECK_MSG(has_expected_fit_kind<Op>(r), at + ": a " + std::string(MLS::to_string(r.status)) + " result has the wrong fit kind");
      if(r.is_success()) {
        MLS_CHECK_MSG(std::abs(n.norm() - 1) < 1e-9, at + ": the normal of a success is not unit");
        if(i < first_bad) ++successes;
      } else {
        MLS_CHECK_MSG(r.point == query || !query_is_finite, at + ": a failure moved the query");
        MLS_CHECK_MSG(n == Eigen::Vector3d::Zero(), at + ": a failure has a non-null normal");
      }
      if(i >= first_bad) continue;
      ++finite_queries;
      if(c.expect == Bad_case::ALL_FAIL)
        MLS_CHECK_MSG(!r.is_success(), at + ": expected a failure status, got " + MLS::to_string(r.status));
      if(r.is_success() && c.expect == Bad_case::ON_SHAPE) {
        double d = std::numeric_limits<double>::infinity(), radius = 1;
        for(const auto& [centre, R] : c.shapes) {
          const double e = std::abs((p - centre).norm() - R);
          if(e < d) d = e, radius = R;
        }
        worst = (std::max)(worst, d / radius);
      }
      if(r.is_success() && c.name == "coplanar") {
        // the plane z = 1 + 0.3 x - 0.2 y is in every function space: reproduced exactly
        const double d = std::abs(p[2] - (1 + 0.3 * p[0] - 0.2 * p[1])) / std::sqrt(1 + 0.09 + 0.04);
        worst = (std::max)(worst, d);
      }
    }
    if(c.expect == Bad_case::ON_SHAPE || c.name == "coplanar")
      std::cout << "  " << where << ": " << successes << "/" << finite_queries << " succeeded, worst distance "
                << mls_test::fmt(worst) << ", "
                << mls_test::fmt(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
                << " s\n";
    if(c.expect == Bad_case::ON_SHAPE || c.name == "coplanar") {
      // every query near a well-sampled shape must succeed and land on it
      MLS_CHECK_MSG(successes == finite_queries,
                    where + ": " + std::to_string(finite_queries - successes) + " of " +
                      std::to_string(finite_queries) + " queries failed");
      const bool is_plane_like = std::string(op_name).find("plane") != std::string::npos ||
                                 std::string(op_name).find("wedge") != std::string::npos;
      const double tol = c.name == "coplanar" ? 1e-6 : is_plane_like ? 0.1 : 0.01;
      MLS_CHECK_MSG(worst <= tol, where + ": distance to the shape " + mls_test::fmt(worst) + " > " + mls_test::fmt(tol));
    }
  }
}

using Levin_3 = MLS::Levin_projection<K, MLS::Polynomial_function_space<3>>;
using Levin_plane_3 = MLS::Levin_projection<K, MLS::Plane_function_space<3>>;
using Unified_quadratic_3 = MLS::Unified_projection<K, MLS::Paraboloid_function_space<3>>;
using Unified_wedge_3 = MLS::Unified_projection<K, MLS::Wedge_fan_function_space<3>>;
using Mixed_3 = MLS::Mixed_projection<K, 3>;
using Levin_2 = MLS::Levin_projection<K, MLS::Polynomial_function_space<2>>;
using Mixed_2 = MLS::Mixed_projection<K, 2>;

MLS_TEST(bad_input_levin_3) { check_bad_inputs<Levin_3>("levin quadratic", 40); }
MLS_TEST(bad_input_levin_plane_3) { check_bad_inputs<Levin_plane_3>("levin plane", 40); }
MLS_TEST(bad_input_unified_quadratic_3) { check_bad_inputs<Unified_quadratic_3>("unified quadratic", 2, true); }
MLS_TEST(bad_input_unified_wedge_3) { check_bad_inputs<Unified_wedge_3>("unified wedge", 2, true); }
MLS_TEST(bad_input_mixed_3) { check_bad_inputs<Mixed_3>("mixed", 2, true); }
MLS_TEST(bad_input_levin_2) { check_bad_inputs<Levin_2>("levin quadratic", 40); }
MLS_TEST(bad_input_mixed_2) { check_bad_inputs<Mixed_2>("mixed", 20); }

// Translation and scale: the offset and scaled sphere give the translated and scaled results.
template <class Op>
void check_offset_and_scale(const char* op_name, int queries) {
  constexpr int D = Op::dimension;
  using T = Dim<D>;
  const auto shape = round_shape<D>(D == 3 ? 600 : 100);
  const Eigen::Vector3d off(1e6, -1e6, D == 3 ? 1e6 : 0);
  std::vector<typename T::Point> base, moved, scaled;
  for(const auto& p : shape) {
    base.push_back(T::make(p));
    moved.push_back(T::make(p + off));
    scaled.push_back(T::make(1e-9 * p));
  }
  const Op P0(base), P1(moved), P2(scaled);
  double worst_offset = 0, worst_scale = 0;
  for(std::size_t i = 0; i < shape.size(); i += shape.size() / queries) {
    const Eigen::Vector3d q = 1.03 * shape[i];
    const auto r0 = P0.project(T::make(q));
    const auto r1 = P1.project(T::make(q + off));
    const auto r2 = P2.project(T::make(1e-9 * q));
    MLS_CHECK_MSG(r0.is_success() && r1.is_success() && r2.is_success(), std::string(op_name) + ": a failure");
    if(!(r0.is_success() && r1.is_success() && r2.is_success())) continue;
    worst_offset = (std::max)(worst_offset, (T::eigen(r1.point) - off - T::eigen(r0.point)).norm());
    worst_scale = (std::max)(worst_scale, (1e9 * T::eigen(r2.point) - T::eigen(r0.point)).norm());
    worst_offset = (std::max)(worst_offset, (T::eigen(r1.normal) - T::eigen(r0.normal)).norm());
    worst_scale = (std::max)(worst_scale, (T::eigen(r2.normal) - T::eigen(r0.normal)).norm());
  }
  MLS_CHECK_MSG(worst_offset <= 1e-5, std::string(op_name) + ": offset 1e6 changes a result by " + mls_test::fmt(worst_offset));
  MLS_CHECK_MSG(worst_scale <= 1e-5, std::string(op_name) + ": scale 1e-9 changes a result by " + mls_test::fmt(worst_scale));
}

MLS_TEST(bad_input_offset_and_scale_invariance) {
  check_offset_and_scale<Levin_3>("levin 3D", 25);
  check_offset_and_scale<Mixed_3>("mixed 3D", 3); // both closest-point operators, as in bad_input_mixed_3
  check_offset_and_scale<Levin_2>("levin 2D", 25);
  check_offset_and_scale<Mixed_2>("mixed 2D", 10);
}

// NaN and inf input points are dropped: the results are those of the clean input, bit for bit.
MLS_TEST(bad_input_non_finite_points_are_dropped) {
  const auto shape = round_shape<3>(600);
  std::vector<P3> clean, dirty;
  for(std::size_t i = 0; i < shape.size(); ++i) {
    clean.push_back(Dim<3>::make(shape[i]));
    dirty.push_back(Dim<3>::make(shape[i]));
    if(i % 100 == 3) dirty.emplace_back(nan_, 0, 1);
    if(i % 100 == 50) dirty.emplace_back(0, -inf_, 1);
  }
  const Mixed_3 A(clean), B(dirty);
  MLS_CHECK(B.samples().number_of_ignored_points() == 12);
  MLS_CHECK(B.samples().size() == clean.size());
  MLS_CHECK(A.bandwidth() == B.bandwidth());
  for(std::size_t i = 0; i < clean.size(); i += 200) {
    const P3 q(1.02 * clean[i].x(), 1.02 * clean[i].y(), 1.02 * clean[i].z());
    const auto a = A.project(q), b = B.project(q);
    MLS_CHECK(a.status == b.status && a.point == b.point && a.normal == b.normal);
  }
}

// ---------------------------------------------------------------------------------------------
// Determinism and thread safety.

/// A noisy sphere with a crease: the upper half of a sphere closed by a cone, so that the Mixed
/// operator keeps the wedge fan on some queries and the quadratic on others.
std::vector<P3> creased_sphere(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> noise(0, 0.003);
  std::vector<P3> pts;
  for(const auto& p : round_shape<3>(n)) {
    Eigen::Vector3d x = p;
    if(x[2] < 0) x[2] = -0.7 * (1 - std::hypot(x[0], x[1])); // a cone below the equator
    const Eigen::Vector3d e = mls_test::random_vector(noise, gen);
    pts.emplace_back(x[0] + e[0], x[1] + e[1], x[2] + e[2]);
  }
  return pts;
}

template <class Result>
bool same_result(const Result& a, const Result& b) {
  return a.status == b.status && a.point == b.point && a.normal == b.normal && a.energy == b.energy &&
         a.coefficients == b.coefficients && a.fit_kind == b.fit_kind && a.iterations == b.iterations &&
         a.number_of_neighbors == b.number_of_neighbors && a.is_on_feature == b.is_on_feature;
}

template <class Result>
std::size_t count_differences(const std::vector<Result>& a, const std::vector<Result>& b) {
  if(a.size() != b.size()) return (std::max)(a.size(), b.size());
  std::size_t d = 0;
  for(std::size_t i = 0; i < a.size(); ++i) d += same_result(a[i], b[i]) ? 0 : 1;
  return d;
}

/// project_points with at most `threads` TBB threads (0: sequential tag).
template <class Op, class Q>
std::vector<typename Op::Result> run_with_threads(const Op& op, const Q& queries, int threads) {
  std::vector<typename Op::Result> out;
  if(threads == 0) {
    MLS::project_points<CGAL::Sequential_tag>(op, queries, std::back_inserter(out));
    return out;
  }
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  MLS::project_points<CGAL::Parallel_if_available_tag>(op, queries, std::back_inserter(out));
  return out;
}

/// Sequential, 1 thread, 2 threads, and 2 threads again: all bit-identical; most succeed.
template <class Op>
void check_thread_determinism(const Op& op, const std::vector<P3>& queries, const char* name) {
  const auto seq = run_with_threads(op, queries, 0);
  const auto one = run_with_threads(op, queries, 1);
  const auto two = run_with_threads(op, queries, 2);
  const auto again = run_with_threads(op, queries, 2);
  MLS_CHECK(seq.size() == queries.size());
  MLS_CHECK_MSG(count_differences(seq, one) == 0, std::string(name) + ": sequential != 1 thread");
  MLS_CHECK_MSG(count_differences(seq, two) == 0, std::string(name) + ": sequential != 2 threads");
  MLS_CHECK_MSG(count_differences(two, again) == 0, std::string(name) + ": two runs with 2 threads differ");
  std::size_t ok = 0;
  for(const auto& r : seq) ok += r.is_success() ? 1 : 0;
  // the queries are near a well-sampled surface: a run that fails them all compares nothing
  MLS_CHECK_MSG(ok >= queries.size() * 9 / 10, std::string(name) + ": only " + std::to_string(ok) + " successes");
}

/// `n` queries near the crease of `creased_sphere` (the equator) and `n` near its smooth top.
std::vector<P3> crease_and_smooth_queries(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0, 0.01);
  std::vector<P3> q;
  for(std::size_t i = 0; i < n; ++i) {
    const double t = 2 * CGAL_PI * (i + 0.3) / n;
    const Eigen::Vector3d e = mls_test::random_vector(g, gen);
    q.emplace_back(std::cos(t) + e[0], std::sin(t) + e[1], e[2]);
    const double z = 0.8 + 0.02 * double(i), r = std::sqrt(1 - z * z);
    const Eigen::Vector3d f = mls_test::random_vector(g, gen);
    q.emplace_back(r * std::cos(t) + f[0], r * std::sin(t) + f[1], z + f[2]);
  }
  return q;
}

std::vector<P3> queries_near(const std::vector<P3>& pts, std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0, 0.02);
  std::vector<P3> q;
  for(std::size_t i = 0; i < n; ++i) {
    const P3& p = pts[(i * 7919) % pts.size()];
    const Eigen::Vector3d e = mls_test::random_vector(g, gen);
    q.emplace_back(p.x() + e[0], p.y() + e[1], p.z() + e[2]);
  }
  return q;
}

/// Wendland's compact weight: fewer neighbours, so the closest-point operators run faster; the
/// determinism does not depend on the weight.
MLS::Projection_options light() {
  MLS::Projection_options o;
  o.weight = MLS::Weight_kind::WENDLAND;
  return o;
}

MLS_TEST(threads_determinism_mixed) {
  const auto pts = creased_sphere(1500, 3);
  const Mixed_3 op(pts, light());
  const auto queries = crease_and_smooth_queries(6, 4);
  check_thread_determinism(op, queries, "mixed");
  // both fits are kept somewhere (the wedge at the crease, the quadratic on the smooth top), so
  // both code paths are compared
  std::size_t wedges = 0;
  for(const auto& r : run_with_threads(op, queries, 0)) wedges += r.fit_kind == CGAL::MLS::Local_fit_kind::CLOSEST_POINT ? 1 : 0;
  MLS_CHECK_MSG(wedges > 0 && wedges < queries.size(), "the wedge fan was kept " + std::to_string(wedges) + " times");
}

MLS_TEST(threads_determinism_levin_and_unified) {
  const auto pts = creased_sphere(1500, 5);
  check_thread_determinism(Levin_3(pts), queries_near(pts, 300, 6), "levin");
  check_thread_determinism(Unified_quadratic_3(pts, light()), queries_near(pts, 8, 7), "unified quadratic");
  check_thread_determinism(Unified_wedge_3(pts, light()), queries_near(pts, 8, 8), "unified wedge");
}

// Repeated construction from the same input gives the same operator: same h, same results.
MLS_TEST(threads_repeated_runs_are_identical) {
  const auto pts = creased_sphere(1500, 9);
  const auto queries = queries_near(pts, 4, 10);
  const Mixed_3 A(pts, light()), B(pts, light());
  MLS_CHECK(A.bandwidth() == B.bandwidth());
  std::size_t differ = 0;
  for(const auto& q : queries) differ += same_result(A.project(q), B.project(q)) ? 0 : 1;
  for(const auto& q : queries) differ += same_result(A.project(q), A.project(q)) ? 0 : 1;
  MLS_CHECK_MSG(differ == 0, std::to_string(differ) + " results differ");
}

/// One operator called concurrently from `threads` std::threads, each projecting every query:
/// each thread's results equal the sequential ones. Without TBB: ThreadSanitizer sees every
/// synchronisation, so it checks project() itself for data races.
template <class Op>
void check_concurrent_calls(const Op& op, const std::vector<P3>& queries, const char* name) {
  std::vector<typename Op::Result> reference;
  for(const auto& q : queries) reference.push_back(op.project(q));
  const int threads = 3;
  std::vector<std::vector<typename Op::Result>> results(threads, std::vector<typename Op::Result>(queries.size()));
  std::vector<std::thread> pool;
  for(int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      // each thread starts at another query, so that the same query runs concurrently at times
      for(std::size_t j = 0; j < queries.size(); ++j) {
        const std::size_t i = (j + t * queries.size() / threads) % queries.size();
        results[t][i] = op.project(queries[i]);
      }
    });
  for(auto& th : pool) th.join();
  for(int t = 0; t < threads; ++t)
    MLS_CHECK_MSG(count_differences(reference, results[t]) == 0, std::string(name) + ": thread " + std::to_string(t) + " differs");
}

MLS_TEST(threads_concurrent_calls_of_one_operator) {
  const auto pts = creased_sphere(1500, 11);
  check_concurrent_calls(Levin_3(pts), queries_near(pts, 90, 12), "levin");
  check_concurrent_calls(Mixed_3(pts, light()), queries_near(pts, 6, 13), "mixed");
  std::vector<P2> circle;
  for(const auto& p : round_shape<2>(200)) circle.push_back(Dim<2>::make(p));
  const Mixed_2 op2(circle);
  std::vector<typename Mixed_2::Result> reference;
  std::vector<P2> q2(circle.begin(), circle.begin() + 20);
  for(const auto& q : q2) reference.push_back(op2.project(q));
  std::vector<typename Mixed_2::Result> a(q2.size()), b(q2.size());
  std::thread ta([&] { for(std::size_t i = 0; i < q2.size(); ++i) a[i] = op2.project(q2[i]); });
  std::thread tb([&] { for(std::size_t i = q2.size(); i-- > 0;) b[i] = op2.project(q2[i]); });
  ta.join();
  tb.join();
  MLS_CHECK(count_differences(reference, a) == 0 && count_differences(reference, b) == 0);
}

} // namespace

int main(int argc, char** argv) { return mls_test::run_all(argc, argv); }
