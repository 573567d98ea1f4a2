// Tests of detect_sharp_features(): the creases and corners found by the wedge-fan projection,
// chained into polylines for Mesh_3.
//
// Cost: a projection costs 10-100 ms, so every case projects a subsample of its input (the
// function's documented use) with Wendland's weight (the smaller support), and the shapes are
// coarse (an edge of the cube is about 7 h long). Whole test: 46 s on one loaded core (user
// time 22 s), the mixed cube (twice the cost per projection) half of it.

#include "test_framework.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/MLS_projection/detect_sharp_features.h>

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace MLS = CGAL::MLS;
using V3 = Eigen::Vector3d;
using Point = Epick::Point_3;
using Result = MLS::Projection_result<Epick, 3>;
using Features = MLS::Sharp_features<Epick>;

namespace {

V3 eig(const Point& p) { return V3(p.x(), p.y(), p.z()); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

MLS::Projection_options wendland() {
  MLS::Projection_options o;
  o.weight = MLS::Weight_kind::WENDLAND;
  return o;
}

// Every `stride`-th point, from a fixed offset: a regular subsample.
std::vector<Point> subsample(const std::vector<Point>& pts, std::size_t stride) {
  std::vector<Point> out;
  for(std::size_t i = stride / 2; i < pts.size(); i += stride) out.push_back(pts[i]);
  return out;
}

template <class Projection>
std::vector<Result> project(const Projection& P, const std::vector<Point>& queries) {
  std::vector<Result> out;
  MLS::project_points<CGAL::Parallel_if_available_tag>(P, queries, std::back_inserter(out));
  return out;
}

// A cube [-0.5, 0.5]^3 sampled on each face with a regular grid of spacing s (edges and corners
// included once), each coordinate perturbed by Gaussian noise of deviation `sigma`.
std::vector<Point> cube(double s, double sigma, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> noise(0., 1.);
  std::vector<Point> pts;
  const int n = int(std::lround(1. / s));
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
      for(int k = 0; k <= n; ++k)
        if(i == 0 || i == n || j == 0 || j == n || k == 0 || k == n) {
          V3 p(-0.5 + i * s, -0.5 + j * s, -0.5 + k * s);
          if(sigma > 0) p += mls_test::random_vector(noise, gen) * sigma;
          pts.emplace_back(p[0], p[1], p[2]);
        }
  return pts;
}

// Distance from x to the segment [a, b].
double segment_distance(const V3& x, const V3& a, const V3& b) {
  const V3 e = b - a;
  const double t = std::min(1., std::max(0., (x - a).dot(e) / e.squaredNorm()));
  return (x - (a + t * e)).norm();
}

struct Cube_report {
  int matched_edges = 0;
  double worst_vertex = 0;  // largest distance of a polyline vertex to its edge
  double worst_end = 0;     // largest distance of a polyline end to its edge's corner
  double worst_corner = 0;  // largest distance of a corner to the nearest true corner
  bool shared_ends = true;  // ends at corners are exactly a listed corner
};

// Matches each polyline to the true edge nearest to its middle vertex and measures it.
Cube_report measure_cube(const Features& f) {
  Cube_report rep;
  std::vector<std::pair<V3, V3>> edges;
  for(int axis = 0; axis < 3; ++axis)
    for(int a : {-1, 1})
      for(int b : {-1, 1}) {
        V3 p, q;
        p[axis] = -0.5;
        q[axis] = 0.5;
        p[(axis + 1) % 3] = q[(axis + 1) % 3] = 0.5 * a;
        p[(axis + 2) % 3] = q[(axis + 2) % 3] = 0.5 * b;
        edges.emplace_back(p, q);
      }
  std::vector<int> hits(edges.size(), 0);
  for(const auto& pl : f.polylines) {
    const V3 mid = eig(pl[pl.size() / 2]);
    std::size_t e = 0;
    for(std::size_t k = 1; k < edges.size(); ++k)
      if(segment_distance(mid, edges[k].first, edges[k].second) < segment_distance(mid, edges[e].first, edges[e].second)) e = k;
    ++hits[e];
    for(const Point& p : pl) rep.worst_vertex = std::max(rep.worst_vertex, segment_distance(eig(p), edges[e].first, edges[e].second));
    // the two ends are the two ends of the edge, in either order
    const V3 s = eig(pl.front()), t = eig(pl.back());
    const double direct = std::max((s - edges[e].first).norm(), (t - edges[e].second).norm());
    const double swapped = std::max((s - edges[e].second).norm(), (t - edges[e].first).norm());
    rep.worst_end = std::max(rep.worst_end, std::min(direct, swapped));
    for(const Point* end : {&pl.front(), &pl.back()}) {
      bool listed = false;
      for(const Point& c : f.corners) listed |= (c == *end);
      rep.shared_ends &= listed;
    }
  }
  for(int h : hits) rep.matched_edges += h == 1;
  for(const Point& c : f.corners) rep.worst_corner = std::max(rep.worst_corner, (eig(c).cwiseAbs() - V3::Constant(0.5)).norm());
  return rep;
}

void print(const char* name, const Features& f, double h, double t) {
  const auto& s = f.statistics;
  std::cout << "  " << name << ": " << f.polylines.size() << " polylines, " << f.corners.size() << " corners; "
            << s.crease_samples << " samples on features, " << s.helper_hits << "/" << s.helper_queries
            << " helpers on features, " << s.crease_nodes << " nodes, " << s.dropped_polylines << " dropped, "
            << s.relaxed << "/" << s.relaxation_queries << " relaxed; h = " << h << ", " << t << " s\n";
}

} // namespace

MLS_TEST(empty_input_gives_empty_result) {
  const std::vector<Point> none;
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(none, wendland());
  const Features f = MLS::detect_sharp_features<CGAL::Sequential_tag>(PU, std::vector<Result>());
  MLS_CHECK(f.polylines.empty() && f.corners.empty());
  // a valid projection but no projected samples
  const auto pts = cube(0.1, 0., 1);
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PC(pts, wendland());
  const Features g = MLS::detect_sharp_features<CGAL::Sequential_tag>(PC, std::vector<Result>());
  MLS_CHECK(g.polylines.empty() && g.corners.empty());
}

namespace {

struct Cube_run {
  Features features;
  double h = 0, seconds = 0;
  std::size_t samples = 0, projected = 0;
};

// The cube projected with `Projection` (the unified operator with the fan, or the mixed space
// of the tools and the meshing code).
template <class Projection>
Cube_run run_cube(double sigma, unsigned seed, std::size_t stride) {
  Cube_run run;
  const auto t0 = std::chrono::steady_clock::now();
  const auto pts = cube(0.0625, sigma, seed);
  const Projection P(pts, wendland());
  run.h = P.bandwidth();
  const auto sub = subsample(pts, stride);
  const auto projected = project(P, sub);
  const double tp = seconds_since(t0);
  run.features = MLS::detect_sharp_features<CGAL::Parallel_if_available_tag>(P, projected);
  run.seconds = seconds_since(t0);
  run.samples = pts.size();
  run.projected = sub.size();
  std::cout << "  " << pts.size() << " samples, " << sub.size() << " projected in " << tp << " s\n";
  return run;
}

void check_cube(const Cube_run& run, double vertex_tol, double end_tol, double corner_tol) {
  const Cube_report rep = measure_cube(run.features);
  std::cout << "  edges matched once " << rep.matched_edges << "/12, worst vertex " << rep.worst_vertex / run.h
            << " h, worst end " << rep.worst_end / run.h << " h, worst corner " << rep.worst_corner / run.h
            << " h, ends shared " << rep.shared_ends << "\n";
  const int before = mls_test::failures();
  MLS_CHECK(run.features.polylines.size() == 12);
  MLS_CHECK(run.features.corners.size() == 8);
  MLS_CHECK(rep.matched_edges == 12);
  MLS_CHECK_LE(rep.worst_vertex, vertex_tol);
  MLS_CHECK_LE(rep.worst_end, end_tol);
  MLS_CHECK_LE(rep.worst_corner, corner_tol);
  MLS_CHECK(rep.shared_ends);
  if(mls_test::failures() == before) return;
  for(const auto& pl : run.features.polylines)
    std::cout << "    polyline of " << pl.size() << " vertices: " << pl.front() << " -> " << pl.back() << "\n";
  for(const Point& c : run.features.corners) std::cout << "    corner " << c << "\n";
}

} // namespace

// Noiseless: every crease and apex point is a projection, exact to ~1e-13 h (test_unified_projection
// finds the same figures), and the resampled vertices between them lie on the straight edges, so
// 1e-6 (~1e-5 h) only allows for rounding.
MLS_TEST(noiseless_cube_mixed_gives_12_edges_and_8_corners) {
  // the mixed space (quadratic or fan per query; its fan fits' coefficients drive the helpers).
  // With every 16th sample only (96), one corner is missed: the tracing of two of its edges
  // stops 2.6 h and 3.1 h before it, beyond corner_link_radius, and the third edge's last crease
  // point, at the corner itself, is reported with a direction, not as an apex.
  const Cube_run run = run_cube<MLS::Mixed_projection<Epick, 3>>(0., 1, 8);
  print("noiseless cube", run.features, run.h, run.seconds);
  check_cube(run, 1e-6, 1e-6, 1e-6);
  // the named parameter sharpness_angle: above 90 degrees, no fan fit of the cube (whose faces
  // meet at 90) makes a crease for the helper points, and the crease samples alone make no
  // polyline (measured: 9 helpers projected instead of 97)
  const auto pts = cube(0.0625, 0., 1);
  const MLS::Mixed_projection<Epick, 3> P(pts, wendland());
  const Features blunt = MLS::detect_sharp_features<CGAL::Parallel_if_available_tag>(
    P, project(P, subsample(pts, 8)), CGAL::parameters::sharpness_angle(100.));
  std::cout << "  sharpness_angle 100: " << blunt.statistics.helper_queries << " helpers projected (20: "
            << run.features.statistics.helper_queries << "), " << blunt.polylines.size() << " polylines\n";
  MLS_CHECK(blunt.polylines.empty() && blunt.statistics.helper_queries < run.features.statistics.helper_queries);
}

// Noise of deviation sigma = 0.0025 (0.04 spacing, 0.018 h) on every coordinate: the creases are
// those of local fits to noisy points, about 0.05 h off (measured 0.052 h). The tolerance, 0.1 h,
// is below the clustering spacing (0.25 h), so a vertex chained from the wrong crease or a corner
// merged from the wrong apex fails it. The detection is fragile under more noise (issue of noisy
// scans; manual, section "Sharp Features"): over the samplings of seeds 2 to 4, at this noise
// seed 3's gets a 13th polyline; at 0.08 to 0.12 spacing, one or two lose an end or a corner; at
// 0.16 spacing, two of three miss an edge and a corner.
MLS_TEST(noisy_cube_gives_12_edges_and_8_corners) {
  const double sigma = 0.0025;
  const Cube_run run = run_cube<MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>>>(sigma, 2, 8);
  print("noisy cube", run.features, run.h, run.seconds);
  check_cube(run, 0.1 * run.h, 0.1 * run.h, 0.1 * run.h);
}

// A sphere is smooth: the mixed operator (the tools' default) keeps its quadratic fit, no
// projection is on a feature, so there is nothing to chain.
MLS_TEST(sphere_gives_no_polyline) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Point> sphere;
  const int n = 2000;
  for(int i = 0; i < n; ++i) { // Fibonacci sphere, radius 1
    const double z = 1 - (2 * i + 1.) / n, rho = std::sqrt(1 - z * z), a = i * CGAL_PI * (3 - std::sqrt(5.));
    sphere.emplace_back(rho * std::cos(a), rho * std::sin(a), z);
  }
  MLS::Mixed_projection<Epick, 3> PM(sphere, wendland());
  const auto projected = project(PM, subsample(sphere, 10));
  const Features f = MLS::detect_sharp_features<CGAL::Parallel_if_available_tag>(PM, projected);
  print("sphere", f, PM.bandwidth(), seconds_since(t0));
  MLS_CHECK(f.polylines.empty());
  MLS_CHECK(f.corners.empty());
}

namespace {

// A single 90-degree ridge along the x axis, x in [-1, 1]: the faces z = -|y| (each a strip of
// width 1 from the crease), sampled on a grid of spacing s.
std::vector<Point> ridge(double s) {
  std::vector<Point> pts;
  const int nx = int(std::lround(2. / s)), nt = int(std::lround(1. / s));
  const double c = std::sqrt(0.5);
  for(int i = 0; i <= nx; ++i) {
    const double x = -1. + i * s;
    pts.emplace_back(x, 0., 0.);
    for(int j = 1; j <= nt; ++j)
      for(int side : {-1, 1}) pts.emplace_back(x, side * c * j * s, -c * j * s);
  }
  return pts;
}

} // namespace

MLS_TEST(single_edge_gives_one_polyline_and_is_deterministic) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto pts = ridge(0.0625);
  MLS::Unified_projection<Epick, MLS::Wedge_fan_function_space<3>> PU(pts, wendland());
  const double h = PU.bandwidth();
  const auto projected = project(PU, subsample(pts, 8));
  const Features f = MLS::detect_sharp_features<CGAL::Sequential_tag>(PU, projected);
  print("ridge", f, h, seconds_since(t0));
  MLS_CHECK(f.polylines.size() == 1);
  MLS_CHECK(f.corners.empty());
  if(f.polylines.size() == 1) {
    const auto& pl = f.polylines.front();
    double worst = 0, worst_inside = 0, lo = 1e9, hi = -1e9, where = 0;
    for(const Point& p : pl) {
      if(std::hypot(p.y(), p.z()) > worst) where = p.x();
      if(std::abs(p.x()) <= 1) worst_inside = std::max(worst_inside, std::hypot(p.y(), p.z()));
      worst = std::max(worst, std::hypot(p.y(), p.z()));
      lo = std::min(lo, p.x());
      hi = std::max(hi, p.x());
    }
    std::cout << "  ridge: " << pl.size() << " vertices, x from " << lo << " to " << hi << ", max distance to the crease "
              << worst / h << " h (at x = " << where << "), on the data's crease " << worst_inside / h << " h\n";
    // Noiseless: on the data's crease (|x| <= 1) the vertices are exact (1e-9 as in
    // test_unified_projection). An end may run up to `support_radius` (0.75 h) past the data,
    // where the fit extrapolates the crease from one side only: measured 2.3e-3 h off; 0.01 h.
    MLS_CHECK_LE(worst_inside, 1e-9);
    MLS_CHECK_LE(worst, 0.01 * h);
    // covers the data's crease, x in [-1, 1], up to 2 h at each end (the fits near the end of
    // the data see one side only) and runs no further than `support_radius` (0.75 h) beyond it
    MLS_CHECK_LE(lo, -1. + 2 * h);
    MLS_CHECK_LE(1. - 2 * h, hi);
    MLS_CHECK_LE(-1. - h, lo);
    MLS_CHECK_LE(hi, 1. + h);
  }
  // the same with the parallel tag: bit-identical
  const Features g = MLS::detect_sharp_features<CGAL::Parallel_if_available_tag>(PU, projected);
  bool same = g.polylines == f.polylines && g.corners == f.corners;
  MLS_CHECK(same);
}

// The chaining alone, on synthetic crease nodes (units of h = 1): three straight branches along
// the axes ending 0.5 from the origin, with no apex point there, meet at a junction corner; the
// polylines end at it. A fourth, isolated node is left out (no polyline of one vertex).
MLS_TEST(chaining_finds_a_junction_corner_without_apex) {
  namespace I = CGAL::MLS::internal;
  std::vector<I::Crease_point> nodes;
  for(int axis = 0; axis < 3; ++axis)
    for(double t = 0.5; t <= 3.01; t += 0.25) {
      I::Feature_vec p = I::Feature_vec::Zero(), d = I::Feature_vec::Zero();
      p[axis] = t;
      d[axis] = axis == 1 ? -1. : 1.; // the sign of a direction does not matter
      nodes.push_back({p, d});
    }
  nodes.push_back({I::Feature_vec(5, 5, 5), I::Feature_vec(1, 0, 0)});
  std::vector<I::Feature_vec> corners;
  const I::Chaining_parameters prm{1.5, std::cos(CGAL_PI / 6), 1.0, 2.5, 3.0};
  const auto chains = I::chain_features(nodes, corners, prm);
  MLS_CHECK(corners.size() == 1);
  MLS_CHECK(chains.size() == 3);
  if(corners.size() == 1) MLS_CHECK_LE(corners[0].norm(), 1e-12);
  for(const auto& c : chains) {
    MLS_CHECK(c.size() == 12); // 11 nodes and the corner
    MLS_CHECK(c.front() == nodes.size() || c.back() == nodes.size());
  }
}

// The separation test behind `internal::Feature_settings::minimum_separation` (units of h = 1): two
// creases meeting at a corner at 90 degrees are not too close (their vertices near the shared
// corner do not count), but they are when the corner is not shared; a parallel polyline 0.3
// away is too close for a separation of 0.5 and not for 0.25, and so is a short segment running
// 0.3 from the middle of a long one (no vertex of the long one near it), in either order.
MLS_TEST(separation_of_polylines) {
  namespace I = CGAL::MLS::internal;
  std::vector<I::Feature_vec> a, b, c, d;
  for(int i = 0; i <= 10; ++i) {
    a.emplace_back(0.5 * i, 0, 0);
    b.emplace_back(0, 0.5 * i, 0);
    c.emplace_back(0.5 * i, 0.3, 0);
  }
  const std::vector<I::Feature_vec> long_one{I::Feature_vec::Zero(), I::Feature_vec(5, 0, 0)};
  d = {I::Feature_vec(2.4, 0, 0.3), I::Feature_vec(2.6, 0, 0.3)};
  const std::vector<I::Feature_vec> corner{I::Feature_vec::Zero()}, none;
  MLS_CHECK(!I::polylines_come_closer(a, b, 0.5, corner));
  MLS_CHECK(I::polylines_come_closer(a, b, 0.5, none));
  MLS_CHECK(I::polylines_come_closer(a, c, 0.5, none));
  MLS_CHECK(!I::polylines_come_closer(a, c, 0.25, none));
  MLS_CHECK(I::polylines_come_closer(long_one, d, 0.5, none));
  MLS_CHECK(I::polylines_come_closer(d, long_one, 0.5, none));
  MLS_CHECK(!I::polylines_come_closer(long_one, d, 0.25, none));
}

int main(int argc, char** argv) { return mls_test::run_all(argc, argv); }
