// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Meshing with this package against CGAL's Poisson reconstruction, on the same points and normals
// in the same run.
//
// Inputs (analytic solids of tools/include/mls_tools/builtin_solid.h, sampled with a fixed seed at
// --spacing, with their exact outward normals):
//   - "solid": mls_mesh's built-in solid (a box with a cylindrical bore and a rounded edge:
//     15 sharp edges, 6 corners), noiseless;
//   - "solid+noise": the same with isotropic Gaussian noise of --noise (default 0.1 x spacing);
//   - "sphere": a sphere of radius 0.6 (no sharp edge);
//   - "fandisk", "fandisk+noise": a fandisk-like CAD block generated here (Fandisk_like_block below:
//     an extruded polygon with a slanted face, a concave step and a chamfer; 24 sharp edges at
//     90 to 149 degrees, convex and concave), without and with the same noise.
// Methods:
//   - MLS: CGAL::MLS::mls_surface_reconstruction<Parallel_if_available_tag> with the options of
//     mls_mesh's defaults (unified operator, mixed space, Mesh_3, features on, facet size 2 and
//     distance 0.25 times the average spacing), or --operator/--space;
//   - Poisson: CGAL::poisson_surface_reconstruction_delaunay with the average spacing
//     (compute_average_spacing, 6 neighbours, timed with it), twice: with its default criteria
//     (angle 20, radius 30, distance 0.375 spacings), as in CGAL's Poisson example, and with the
//     criteria of the MLS row (angle 25, radius 2, distance 0.25 spacings: the same resolution).
// Figures, against the exact surface (exact closest points, see builtin_solid.h):
//   - seconds: wall time of the call (the points and exact normals are given to both methods);
//   - vertices: maximum and RMS distance of the mesh's vertices to the surface;
//   - Hausdorff: symmetric, approximated on samples: the facets sampled at 30000 points per unit
//     area (CGAL::Polygon_mesh_processing::sample_triangle_mesh, random uniform, fixed seed) and
//     the vertices, to the exact surface; and a dense sample of the surface (spacing / 3) to the
//     mesh (AABB tree); RMS: of the facet samples' distances to the exact surface;
//   - normal error: mean angle (degrees, weighted by facet area) between each facet's normal and
//     the true normal at the point of the surface closest to its centroid;
//   - edge distance: mean distance to the mesh from points 0.005 apart along the true sharp edges.
// All lengths are in the unit of the shape (the solid is 2 x 1.2 x 0.8, the sphere's radius 0.6).
//
//   - cpu s: the process's CPU time (user + system, all threads, getrusage) over the call: on a
//     shared machine the more trustworthy time.
// Sanity checks printed on stderr (they should read about 0, or agree): the input points' distance
// to the surface (0 without noise, about the noise otherwise), the true edges' distance to the
// surface (0), the dense sample's (0), each mesh's volume against the solid's (Monte Carlo), and,
// for the sphere, the figures of an inscribed UV sphere whose Hausdorff distance is known.
//
// Usage: bench_meshing [--spacing S | --points N] [--noise SIGMA] [--shapes solid,solid+noise,sphere]
//                      [--methods mls,poisson] [--operator levin|unified]
//                      [--space plane|quadratic|wedge|mixed] [--features on|off] [--threads N]
//                      [--poisson-criteria default|matched|both]
//                      [--hole X,Y,Z,R] [--outliers FRACTION] [--mesh-dir DIR]
//                      [--max-meshing-seconds S]
// Shapes: solid, solid+noise, sphere (the default list), fandisk, fandisk+noise.
// --points N samples each shape at the spacing that gives about N points (sqrt(area / N)).
// Defects of the input, for the manual's case studies (scripts/figures):
//   --hole X,Y,Z,R removes the samples within R of (X, Y, Z);
//   --outliers F adds F x (number of samples) points uniform in the shape's bounding box enlarged
//     by 10% on every side, each with a uniformly random unit normal (fixed seed).
// --mesh-dir DIR writes each mesh as DIR/<shape>-mls.off, DIR/<shape>-poisson.off (default
// criteria) and DIR/<shape>-poisson-matched.off, and the input points as DIR/<shape>-input.xyz.
// --max-meshing-seconds S stops MLS's Mesh_3 after S seconds (the named parameter maximum_running_time;
// default 0: no limit), which then fails.

#include <CGAL/MLS_projection/Meshing_report.h>

#include <mls_tools/builtin_solid.h>
#include <mls_tools/mesh_job.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Point_with_normal = std::pair<Point, Vector>;
using Choice = mls_tools::Operator_choice;
namespace PMP = CGAL::Polygon_mesh_processing;

mls_tools::Vec3 to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

struct Figures {
  bool ok = false;
  bool ran = false;
  double seconds = 0, cpu_seconds = 0;
  double volume = 0; // 0: not closed
  std::size_t vertices = 0, facets = 0;
  bool closed = false;
  double vertex_max = 0, vertex_rms = 0;
  double hausdorff = 0, rms = 0;
  double normal_error = 0; // degrees
  double edge_distance = -1; // < 0: no sharp edge
  std::size_t feature_polylines = 0, corners = 0;
};

Figures measure(const Mesh& mesh, const mls_tools::Analytic_solid& solid, double spacing) {
  Figures f;
  f.ok = !CGAL::is_empty(mesh) && mesh.number_of_faces() > 0;
  if(!f.ok) return f;
  f.vertices = mesh.number_of_vertices();
  f.facets = mesh.number_of_faces();
  f.closed = CGAL::is_closed(mesh);
  if(f.closed) f.volume = PMP::volume(mesh);
  double s2 = 0;
  for(auto v : mesh.vertices()) {
    const double d = std::abs(solid.signed_distance(to_vec(mesh.point(v))));
    f.vertex_max = (std::max)(f.vertex_max, d);
    s2 += d * d;
  }
  f.vertex_rms = std::sqrt(s2 / double(mesh.number_of_vertices()));

  // Mesh -> surface on facet samples.
  std::vector<Point> samples;
  PMP::sample_triangle_mesh(mesh, std::back_inserter(samples),
                            CGAL::parameters::number_of_points_per_area_unit(30000.).random_seed(20260415)
                              .use_random_uniform_sampling(true));
  double mesh_to_surface = 0;
  s2 = 0;
  for(const Point& p : samples) {
    const double d = std::abs(solid.signed_distance(to_vec(p)));
    mesh_to_surface = (std::max)(mesh_to_surface, d);
    s2 += d * d;
  }
  f.rms = std::sqrt(s2 / double((std::max)(std::size_t(1), samples.size())));
  mesh_to_surface = (std::max)(mesh_to_surface, f.vertex_max);

  // Surface -> mesh on a dense sample of the surface.
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  const mls_tools::Point_cloud dense = solid.sample(spacing / 3., 0., 77);
  double surface_to_mesh = 0;
  for(const auto& p : dense.points)
    surface_to_mesh = (std::max)(surface_to_mesh, std::sqrt(tree.squared_distance(Point(p[0], p[1], p[2]))));
  f.hausdorff = (std::max)(mesh_to_surface, surface_to_mesh);

  // Normals.
  double angle_sum = 0, area_sum = 0;
  for(auto face : mesh.faces()) {
    const auto h = mesh.halfedge(face);
    const Point& a = mesh.point(mesh.source(h));
    const Point& b = mesh.point(mesh.target(h));
    const Point& c = mesh.point(mesh.target(mesh.next(h)));
    const Vector cross = CGAL::cross_product(b - a, c - a);
    const double area = std::sqrt(cross.squared_length()) / 2;
    if(!(area > 0)) continue;
    const Vector n = cross / (2 * area);
    const Point centroid = CGAL::centroid(a, b, c);
    const mls_tools::Vec3 t = solid.closest_point(to_vec(centroid)).normal;
    const double cosine = std::clamp(n.x() * t[0] + n.y() * t[1] + n.z() * t[2], -1., 1.);
    angle_sum += area * std::acos(cosine) * 180. / CGAL_PI;
    area_sum += area;
  }
  f.normal_error = area_sum > 0 ? angle_sum / area_sum : 0;

  // Sharp edges.
  if(solid.number_of_sharp_edges() > 0) {
    double sum = 0;
    std::size_t count = 0;
    for(const auto& polyline : solid.sharp_edges(0.005))
      for(const auto& p : polyline) {
        sum += std::sqrt(tree.squared_distance(Point(p[0], p[1], p[2])));
        ++count;
      }
    f.edge_distance = sum / double(count);
  }
  return f;
}


/// A fandisk-like CAD block, generated here (CGAL's fandisk.off itself is not used): the polygon
/// P0..P7 of the (x, z) plane below extruded along y over [-0.5, 0.5]. Its profile has a slanted
/// face (dihedral angles 104 and 149 degrees with its neighbours), a concave step (270 degrees
/// inside: a concave 90-degree edge) and a 45-degree chamfer (two 135-degree edges); the caps
/// meet the sides at 90 degrees. Sharp: the 8 extrusion edges and the 16 cap edges; 16 corners.
/// Every face is planar; the caps are split into two convex pieces along z = 0.1 (not an edge).
/// Closest points are exact: the nearest of the faces' closest points, each the projection on the
/// face's plane when it falls inside the (convex) face, else the nearest point of its boundary.
class Fandisk_like_block : public mls_tools::Analytic_solid {
public:
  using Vec3 = mls_tools::Vec3;
  using Vec2 = std::array<double, 2>; // (x, z)

  Fandisk_like_block() {
    const std::vector<Vec2> profile = {{-1., -0.4}, {1., -0.4}, {1., -0.2}, {0.5, 0.1},
                                       {0.2, 0.1},  {0.2, 0.2}, {0., 0.4},  {-1., 0.4}};
    pieces_ = {{{-1., -0.4}, {1., -0.4}, {1., -0.2}, {0.5, 0.1}, {0.2, 0.1}, {-1., 0.1}},
               {{-1., 0.1}, {0.2, 0.1}, {0.2, 0.2}, {0., 0.4}, {-1., 0.4}}};
    const auto at = [](const Vec2& q, double y) { return Vec3{q[0], y, q[1]}; };
    // caps: y = +-b, each convex piece a face (outward normal +-y)
    for(double sy : {-1., 1.})
      for(const auto& piece : pieces_) {
        std::vector<Vec3> face;
        for(const Vec2& q : piece) face.push_back(at(q, sy * b));
        // the profile is counterclockwise in (x, z), i.e. seen from -y: reversed on the cap y = +b
        if(sy > 0) std::reverse(face.begin(), face.end()); // counterclockwise seen from outside
        add_convex_face(face);
      }
    // sides: the profile's edges extruded (the profile is counterclockwise in (x, z))
    const std::size_t n = profile.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Vec2 &p = profile[i], &q = profile[(i + 1) % n];
      add_convex_face({at(p, -b), at(p, b), at(q, b), at(q, -b)}); // counterclockwise seen from outside
      add_segment(at(p, -b), at(p, b));
      for(double sy : {-1., 1.}) add_segment(at(p, sy * b), at(q, sy * b));
      for(double sy : {-1., 1.}) corners_.push_back(at(p, sy * b));
    }
  }
  std::string name() const override { return "fandisk-like block"; }
  bool contains(const Vec3& p) const override {
    if(std::abs(p[1]) >= b) return false;
    for(const auto& piece : pieces_) {
      bool inside = true;
      for(std::size_t i = 0; i < piece.size() && inside; ++i) {
        const Vec2 &u = piece[i], &v = piece[(i + 1) % piece.size()];
        inside = (v[0] - u[0]) * (p[2] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]) > 0;
      }
      if(inside) return true;
    }
    return false;
  }
  std::array<Vec3, 2> bounding_box() const override { return {Vec3{-1., -b, -0.4}, Vec3{1., b, 0.4}}; }

private:
  static constexpr double b = 0.5;
  std::vector<std::vector<Vec2>> pieces_;

  static Vec3 cross(const Vec3& u, const Vec3& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  }
  /// A planar convex polygon, vertices counterclockwise seen from outside.
  void add_convex_face(const std::vector<Vec3>& v) {
    using mls_tools::dot;
    using mls_tools::norm;
    using mls_tools::operator-;
    using mls_tools::operator+;
    using mls_tools::operator*;
    Vec3 normal{0., 0., 0.};
    for(std::size_t i = 1; i + 1 < v.size(); ++i) {
      const Vec3 c = cross(v[i] - v[0], v[i + 1] - v[0]);
      normal = normal + c;
    }
    const double area = norm(normal) / 2;
    normal = (1. / norm(normal)) * normal;
    const auto inside = [v, normal](const Vec3& q) {
      for(std::size_t i = 0; i < v.size(); ++i)
        if(dot(cross(v[(i + 1) % v.size()] - v[i], q - v[i]), normal) < 0) return false;
      return true;
    };
    // sampling: uniform in the bounding box of the face's vertices, projected on the face's
    // plane along its largest normal coordinate (uniform by area too), rejected outside
    std::size_t k = 0;
    for(std::size_t c = 1; c < 3; ++c)
      if(std::abs(normal[c]) > std::abs(normal[k])) k = c;
    const std::size_t i0 = (k + 1) % 3, i1 = (k + 2) % 3;
    Vec3 lo = v[0], hi = v[0];
    for(const Vec3& q : v)
      for(std::size_t c = 0; c < 3; ++c) {
        lo[c] = (std::min)(lo[c], q[c]);
        hi[c] = (std::max)(hi[c], q[c]);
      }
    const Vec3 origin = v[0];
    patches_.push_back(
      {area,
       [=](double s, double t, mls_tools::Surface_point& out) {
         Vec3 q{0., 0., 0.};
         q[i0] = lo[i0] + s * (hi[i0] - lo[i0]);
         q[i1] = lo[i1] + t * (hi[i1] - lo[i1]);
         // the plane: dot(normal, q - origin) = 0, solved for q[k]
         q[k] = origin[k] - (normal[i0] * (q[i0] - origin[i0]) + normal[i1] * (q[i1] - origin[i1])) / normal[k];
         if(!inside(q)) return false;
         out = {q, normal};
         return true;
       },
       [=](const Vec3& p) {
         const Vec3 q = p - dot(p - origin, normal) * normal;
         if(inside(q)) return mls_tools::Surface_point{q, normal};
         Vec3 best = v[0];
         double best_d = std::numeric_limits<double>::infinity();
         for(std::size_t i = 0; i < v.size(); ++i) {
           const Vec3 a = v[i], e = v[(i + 1) % v.size()] - v[i];
           const double t = std::clamp(dot(p - a, e) / dot(e, e), 0., 1.);
           const Vec3 c = a + t * e;
           const double d = norm(p - c);
           if(d < best_d) {
             best_d = d;
             best = c;
           }
         }
         return mls_tools::Surface_point{best, normal};
       }});
  }
};

struct Settings {
  double spacing = 0.03;
  std::size_t points = 0; // > 0: the spacing of each shape gives about this many points
  bool mls = true, poisson = true;
  bool space_given = false;
  bool features = true;
  bool poisson_default = true, poisson_matched = true;
  double noise = -1; // < 0: 0.1 x spacing
  std::vector<std::string> shapes = {"solid", "solid+noise", "sphere"};
  bool levin = false;
  int space = 3; // plane, quadratic, wedge, mixed
  int threads = 0;
  std::optional<std::array<double, 4>> hole; // centre, radius
  double outliers = 0;                       // fraction of the samples
  std::string mesh_dir;                      // empty: no output
  double max_meshing_seconds = 0;
};

[[noreturn]] void usage(int code) {
  std::cout << "Usage: bench_meshing [--spacing S | --points N] [--noise SIGMA] [--shapes solid,solid+noise,sphere]\n"
               "                     [--methods mls,poisson] [--operator levin|unified]\n"
               "                     [--space plane|quadratic|wedge|mixed] [--features on|off] [--threads N]\n"
               "                     [--poisson-criteria default|matched|both]\n"
               "                     [--hole X,Y,Z,R] [--outliers FRACTION] [--mesh-dir DIR]\n"
               "                     [--max-meshing-seconds S]\n"
               "--noise is absolute (default 0.1 x the spacing); with --operator levin the space defaults to quadratic.\n"
               "Meshes sampled analytic solids with mls_surface_reconstruction and with CGAL's Poisson\n"
               "reconstruction (same points and normals, same run) and prints their errors against the\n"
               "exact surface as a markdown table (see the top of bench_meshing.cpp for the figures).\n";
  std::exit(code);
}

Settings parse(int argc, char** argv) {
  Settings s;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if(i + 1 >= argc) usage(2);
      return argv[++i];
    };
    if(a == "--help" || a == "-h") usage(0);
    else if(a == "--spacing") s.spacing = std::stod(value());
    else if(a == "--points") s.points = std::size_t(std::stoul(value()));
    else if(a == "--features") {
      const std::string v = value();
      if(v == "on") s.features = true;
      else if(v == "off") s.features = false;
      else usage(2);
    } else if(a == "--poisson-criteria") {
      const std::string v = value();
      s.poisson_default = v == "default" || v == "both";
      s.poisson_matched = v == "matched" || v == "both";
      if(!s.poisson_default && !s.poisson_matched) usage(2);
    } else if(a == "--methods") {
      s.mls = s.poisson = false;
      std::stringstream ss(value());
      std::string item;
      while(std::getline(ss, item, ',')) {
        if(item == "mls") s.mls = true;
        else if(item == "poisson") s.poisson = true;
        else usage(2);
      }
    }
    else if(a == "--noise") s.noise = std::stod(value());
    else if(a == "--outliers") s.outliers = std::stod(value());
    else if(a == "--mesh-dir") s.mesh_dir = value();
    else if(a == "--max-meshing-seconds") s.max_meshing_seconds = std::stod(value());
    else if(a == "--hole") {
      std::array<double, 4> h;
      std::stringstream ss(value());
      std::string item;
      std::size_t n = 0;
      while(std::getline(ss, item, ',') && n < 4) h[n++] = std::stod(item);
      if(n != 4 || !(h[3] > 0)) usage(2);
      s.hole = h;
    }
    else if(a == "--threads") s.threads = std::stoi(value());
    else if(a == "--shapes") {
      s.shapes.clear();
      std::stringstream ss(value());
      std::string item;
      while(std::getline(ss, item, ',')) s.shapes.push_back(item);
    } else if(a == "--operator") {
      const std::string v = value();
      if(v == "levin") s.levin = true;
      else if(v == "unified") s.levin = false;
      else usage(2);
    } else if(a == "--space") {
      const std::string v = value();
      if(v == "plane") s.space = 0;
      else if(v == "quadratic") s.space = 1;
      else if(v == "wedge") s.space = 2;
      else if(v == "mixed") s.space = 3;
      else usage(2);
      s.space_given = true;
    } else
      usage(2);
  }
  if(s.levin && !s.space_given) s.space = 1;
  if(s.levin && s.space > 1) usage(2);
  if(!(s.spacing > 0) || !(s.outliers >= 0)) usage(2);
  return s;
}

double cpu_now() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// The solid's volume by Monte Carlo in its bounding box (fixed seed), for the sanity check.
double monte_carlo_volume(const mls_tools::Analytic_solid& solid, std::size_t n = 1000000) {
  const auto box = solid.bounding_box();
  mls_tools::Random random(99);
  std::size_t in = 0;
  for(std::size_t i = 0; i < n; ++i) {
    mls_tools::Vec3 p;
    for(std::size_t k = 0; k < 3; ++k) p[k] = box[0][k] + random.uniform() * (box[1][k] - box[0][k]);
    if(solid.contains(p)) ++in;
  }
  double v = 1;
  for(std::size_t k = 0; k < 3; ++k) v *= box[1][k] - box[0][k];
  return v * double(in) / double(n);
}

/// A UV sphere of radius r centred at the origin, every vertex on the sphere, `rings` latitude bands
/// and 2 rings longitude bands: its facets lie inside the sphere, at most r (1 - cos(rho)) from it,
/// rho the largest angular circumradius of a facet, below pi / rings / sqrt(2) (half the diagonal
/// of the largest band cell). A reference for the distance measures.
Mesh uv_sphere(double r, int rings) {
  Mesh mesh;
  const int sectors = 2 * rings;
  std::vector<Mesh::Vertex_index> v;
  const auto top = mesh.add_vertex(Point(0, 0, r)), bottom = mesh.add_vertex(Point(0, 0, -r));
  for(int i = 1; i < rings; ++i)
    for(int j = 0; j < sectors; ++j) {
      const double t = CGAL_PI * i / rings, f = 2 * CGAL_PI * j / sectors;
      v.push_back(mesh.add_vertex(Point(r * std::sin(t) * std::cos(f), r * std::sin(t) * std::sin(f), r * std::cos(t))));
    }
  const auto at = [&](int i, int j) { return v[std::size_t((i - 1) * sectors + (j % sectors))]; };
  for(int j = 0; j < sectors; ++j) {
    mesh.add_face(top, at(1, j), at(1, j + 1));
    mesh.add_face(bottom, at(rings - 1, j + 1), at(rings - 1, j));
    for(int i = 1; i + 1 < rings; ++i) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return mesh;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string fmt(double v, const char* f = "%.3g") {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), f, v);
  return buffer;
}

std::string ratio(double poisson, double mls) {
  if(!(mls > 0)) return poisson > 0 ? "inf" : "-";
  return fmt(poisson / mls, "%.2f");
}

/// The input defects of the case studies: a hole (samples within the ball removed) and outliers
/// (uniform in the enlarged bounding box, random unit normals), with fixed seeds.
void apply_defects(mls_tools::Point_cloud& cloud, const mls_tools::Analytic_solid& solid, const Settings& s) {
  if(s.hole) {
    const auto& h = *s.hole;
    std::size_t kept = 0;
    for(std::size_t i = 0; i < cloud.size(); ++i) {
      const auto& p = cloud.points[i];
      const double d2 = (p[0] - h[0]) * (p[0] - h[0]) + (p[1] - h[1]) * (p[1] - h[1]) + (p[2] - h[2]) * (p[2] - h[2]);
      if(d2 <= h[3] * h[3]) continue;
      cloud.points[kept] = cloud.points[i];
      cloud.normals[kept] = cloud.normals[i];
      ++kept;
    }
    cloud.points.resize(kept);
    cloud.normals.resize(kept);
  }
  if(s.outliers > 0) {
    const auto box = solid.bounding_box();
    mls_tools::Random random(31337);
    const std::size_t n = std::size_t(std::lround(s.outliers * double(cloud.size())));
    for(std::size_t i = 0; i < n; ++i) {
      mls_tools::Vec3 p, normal;
      for(std::size_t k = 0; k < 3; ++k) {
        const double margin = 0.1 * (box[1][k] - box[0][k]);
        p[k] = box[0][k] - margin + random.uniform() * (box[1][k] - box[0][k] + 2 * margin);
      }
      double length = 0;
      do {
        for(std::size_t k = 0; k < 3; ++k) normal[k] = random.gaussian();
        length = mls_tools::norm(normal);
      } while(!(length > 1e-9));
      for(std::size_t k = 0; k < 3; ++k) normal[k] /= length;
      cloud.points.push_back(p);
      cloud.normals.push_back(normal);
    }
  }
}

void write_mesh(const Settings& s, const std::string& name, const Mesh& mesh) {
  if(s.mesh_dir.empty()) return;
  const std::string path = s.mesh_dir + "/" + name + ".off";
  if(!CGAL::IO::write_OFF(path, mesh, CGAL::parameters::stream_precision(17)))
    std::cerr << "bench_meshing: cannot write " << path << "\n";
}

} // namespace

int main(int argc, char** argv) {
  const Settings s = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> limit;
  if(s.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(s.threads));
#endif
  const char* const space_names[] = {"plane", "quadratic", "wedge", "mixed"};
  const std::string mls_name = std::string("MLS ") + (s.levin ? "levin" : "unified") + "/" +
                               space_names[s.space];
  std::printf("bench_meshing: %s, noise %s, MLS = %s, Mesh_3, features %s; Poisson = "
              "poisson_surface_reconstruction_delaunay; threads %s\n\n",
              s.points > 0 ? ("about " + std::to_string(s.points) + " points per shape").c_str()
                           : ("spacing " + fmt(s.spacing)).c_str(),
              s.noise < 0 ? "0.1 x spacing" : fmt(s.noise).c_str(), mls_name.c_str(), s.features ? "on" : "off",
              s.threads > 0 ? std::to_string(s.threads).c_str() : "all");

  struct Row {
    std::string shape;
    std::size_t points;
    double spacing, noise;
    Figures mls, poisson, poisson_matched;
  };
  std::vector<Row> rows;
  for(const std::string& shape : s.shapes) {
    std::unique_ptr<mls_tools::Analytic_solid> solid;
    bool noisy = false;
    if(shape == "solid") solid = std::make_unique<mls_tools::Bored_filleted_box>();
    else if(shape == "solid+noise") {
      solid = std::make_unique<mls_tools::Bored_filleted_box>();
      noisy = true;
    } else if(shape == "fandisk") solid = std::make_unique<Fandisk_like_block>();
    else if(shape == "fandisk+noise") {
      solid = std::make_unique<Fandisk_like_block>();
      noisy = true;
    } else if(shape == "sphere") solid = std::make_unique<mls_tools::Sphere_solid>(0.6);
    else {
      std::cerr << "bench_meshing: unknown shape '" << shape << "'\n";
      return 2;
    }
    const double spacing = s.points > 0 ? std::sqrt(solid->area() / double(s.points)) : s.spacing;
    const double sigma = noisy ? (s.noise < 0 ? 0.1 * spacing : s.noise) : 0.;
    mls_tools::Point_cloud cloud = solid->sample(spacing, sigma);
    apply_defects(cloud, *solid, s);
    std::vector<Point_with_normal> points;
    for(std::size_t i = 0; i < cloud.size(); ++i)
      points.emplace_back(Point(cloud.points[i][0], cloud.points[i][1], cloud.points[i][2]),
                          Vector(cloud.normals[i][0], cloud.normals[i][1], cloud.normals[i][2]));
    const auto point_map = CGAL::First_of_pair_property_map<Point_with_normal>();
    const auto normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>();
    Row row{shape, points.size(), spacing, sigma, {}, {}, {}};
    if(!s.mesh_dir.empty()) {
      const std::string path = s.mesh_dir + "/" + shape + "-input.xyz";
      std::ofstream out(path);
      out.precision(17);
      for(const auto& [p, n] : points) out << p << ' ' << n << '\n';
      if(!out) {
        std::cerr << "bench_meshing: cannot write " << path << "\n";
        return 1;
      }
    }

    // Sanity checks of the analytic side: all of these should be about 0 or agree.
    {
      double input_max = 0, input_s2 = 0;
      for(const auto& p : cloud.points) {
        const double d = std::abs(solid->signed_distance(p));
        input_max = (std::max)(input_max, d);
        input_s2 += d * d;
      }
      double edge_max = 0;
      for(const auto& polyline : solid->sharp_edges(0.005))
        for(const auto& p : polyline) edge_max = (std::max)(edge_max, std::abs(solid->signed_distance(p)));
      double dense_max = 0;
      for(const auto& p : solid->sample(spacing / 3., 0., 77).points)
        dense_max = (std::max)(dense_max, std::abs(solid->signed_distance(p)));
      std::fprintf(stderr,
                   "%s: %zu points, spacing %.4g, noise %.3g; sanity: input to surface max %.3g RMS %.3g (noise "
                   "sigma %.3g), true edges to surface max %.2g, dense sample to surface max %.2g, volume %.4f (Monte "
                   "Carlo)\n",
                   shape.c_str(), points.size(), spacing, sigma, input_max,
                   std::sqrt(input_s2 / double(cloud.points.size())), sigma, edge_max, dense_max,
                   monte_carlo_volume(*solid));
      if(shape == "sphere") {
        const int rings = 40;
        const Figures f = measure(uv_sphere(0.6, rings), *solid, spacing);
        const double bound = 0.6 * (1 - std::cos(CGAL_PI / rings / std::sqrt(2.)));
        std::fprintf(stderr,
                     "sphere: sanity: inscribed UV sphere (%d bands): vertex max %.2g, Hausdorff %.3g (bound %.3g), "
                     "RMS %.3g, normal error %.3f deg, volume %.4f (exact %.4f)\n",
                     rings, f.vertex_max, f.hausdorff, bound, f.rms, f.normal_error, f.volume,
                     4. / 3. * CGAL_PI * 0.6 * 0.6 * 0.6);
      }
    }

    if(s.mls) {
      mls_tools::Mesh_settings settings;
      settings.projection_operator =
        s.levin ? (s.space == 0 ? Choice::LEVIN_PLANE : Choice::LEVIN_QUADRATIC)
                : std::array<Choice, 4>{Choice::UNIFIED_PLANE, Choice::UNIFIED_QUADRATIC, Choice::UNIFIED_WEDGE, Choice::MIXED}[s.space];
      settings.features = s.features;
      settings.time_limit = s.max_meshing_seconds;
      CGAL::MLS::Meshing_report report;
      const auto start = std::chrono::steady_clock::now();
      const char* last_stage = "";
      settings.callback = [&](double fraction) {
        const char* stage = CGAL::MLS::meshing_stage(fraction).name;
        if(std::strcmp(stage, last_stage) != 0) {
          last_stage = stage;
          std::fprintf(stderr, "%s: MLS stage %s at %.1f s\n", shape.c_str(), stage, seconds_since(start));
        }
        return true;
      };
      mls_tools::Mesh_input job;
      job.points = points;
      Mesh mesh;
      const double cpu = cpu_now();
      const auto t = std::chrono::steady_clock::now();
      const bool ok = mls_tools::reconstruct_with_normals(job, mesh, settings, report);
      const double seconds = seconds_since(t);
      const double cpu_seconds = cpu_now() - cpu;
      row.mls = measure(mesh, *solid, spacing);
      write_mesh(s, shape + "-mls", mesh);
      row.mls.ran = true;
      row.mls.ok = ok && row.mls.ok;
      row.mls.seconds = seconds;
      row.mls.cpu_seconds = cpu_seconds;
      row.mls.feature_polylines = report.feature_polylines;
      row.mls.corners = report.corners;
      std::fprintf(stderr,
                   "%s: MLS %.1f s (cpu %.1f s)%s%s (normals %.1f s, seeds %.1f s: %zu seeds blended (%zu with P_L's fit), "
                   "%zu unblended, %zu failed; features "
                   "%.1f s%s; meshing %.1f s, %zu evaluations; h %.4g, facet size %.4g, distance %.4g); volume %.4f\n",
                   shape.c_str(), seconds, cpu_seconds, ok ? "" : ", failed: ", ok ? "" : report.failure,
                   report.seconds_normals, report.seconds_seeds, report.seeds, report.levin_fallback_seeds,
                   report.unblended_seeds, report.failed_seeds,
                   report.seconds_features,                    report.features_dropped ? (report.feature_budget_exceeded ? ", features dropped: over budget" : ", features dropped") : "",
                   report.seconds_meshing, report.evaluations, report.bandwidth,
                   report.facet_size, report.facet_distance, row.mls.volume);
    }
    if(s.poisson) {
      // default: CGAL's example (angle 20, radius 30, distance 0.375 average spacings);
      // matched: the criteria of mls_surface_reconstruction's defaults (angle 25, radius 2,
      // distance 0.25 average spacings), the same resolution as the MLS mesh
      for(int variant = 0; variant < 2; ++variant) {
        if(variant == 0 ? !s.poisson_default : !s.poisson_matched) continue;
        const double angle = variant == 0 ? 20. : 25., radius = variant == 0 ? 30. : 2.,
                     distance = variant == 0 ? 0.375 : 0.25;
        Mesh mesh;
        const double cpu = cpu_now();
        const auto t = std::chrono::steady_clock::now();
        // the average spacing is part of Poisson's pipeline (as in CGAL's example), so it is timed
        const double average_spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(
          points, 6, CGAL::parameters::point_map(point_map));
        const bool ok = CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), point_map,
                                                                     normal_map, mesh, average_spacing, angle,
                                                                     radius, distance);
        const double seconds = seconds_since(t);
        const double cpu_seconds = cpu_now() - cpu;
        Figures& f = variant == 0 ? row.poisson : row.poisson_matched;
        f = measure(mesh, *solid, spacing);
        write_mesh(s, shape + (variant == 0 ? "-poisson" : "-poisson-matched"), mesh);
        f.ran = true;
        f.ok = ok && f.ok;
        f.seconds = seconds;
        f.cpu_seconds = cpu_seconds;
        std::fprintf(stderr, "%s: Poisson (%s criteria) %.1f s (cpu %.1f s)%s; average spacing %.4g; volume %.4f\n",
                     shape.c_str(), variant == 0 ? "default" : "matched", seconds, cpu_seconds, ok ? "" : ", failed",
                     average_spacing, f.volume);
      }
    }
    rows.push_back(row);
  }

  std::printf("| shape | points | method | seconds | cpu s | vertices | facets | closed | vertex max | vertex RMS | "
              "Hausdorff | RMS | normal error (deg) | edge distance | features |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const auto print = [](const Row& r, const std::string& method, const Figures& f, bool is_mls) {
    if(!f.ran) return;
    if(!f.ok) {
      std::printf("| %s | %zu | %s | %.1f | %.1f | failed | | | | | | | | | |\n", r.shape.c_str(), r.points,
                  method.c_str(), f.seconds, f.cpu_seconds);
      return;
    }
    std::printf("| %s | %zu | %s | %.1f | %.1f | %zu | %zu | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.shape.c_str(),
                r.points, method.c_str(), f.seconds, f.cpu_seconds, f.vertices, f.facets, f.closed ? "yes" : "no",
                fmt(f.vertex_max).c_str(), fmt(f.vertex_rms).c_str(), fmt(f.hausdorff).c_str(), fmt(f.rms).c_str(),
                fmt(f.normal_error, "%.2f").c_str(), f.edge_distance < 0 ? "-" : fmt(f.edge_distance).c_str(),
                !is_mls ? "-"
                        : (std::to_string(f.feature_polylines) + " polylines, " + std::to_string(f.corners) + " corners")
                            .c_str());
  };
  for(const Row& r : rows) {
    print(r, mls_name, r.mls, true);
    print(r, "Poisson (default criteria)", r.poisson, false);
    print(r, "Poisson (matched criteria)", r.poisson_matched, false);
  }
  if(!s.mls || !s.poisson) return 0;
  std::printf("\nRatios Poisson / MLS (> 1: MLS better; for the times, > 1: MLS faster):\n\n");
  std::printf("| shape | Poisson criteria | seconds | cpu s | vertex max | vertex RMS | Hausdorff | RMS | normal error | "
              "edge distance |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Row& r : rows)
    for(int variant = 0; variant < 2; ++variant) {
      const Figures& p = variant == 0 ? r.poisson : r.poisson_matched;
      const char* name = variant == 0 ? "default" : "matched";
      if(!p.ran) continue;
      if(!r.mls.ok || !p.ok) {
        std::printf("| %s | %s | (a method failed) | | | | | | | |\n", r.shape.c_str(), name);
        continue;
      }
      std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.shape.c_str(), name,
                  ratio(p.seconds, r.mls.seconds).c_str(), ratio(p.cpu_seconds, r.mls.cpu_seconds).c_str(),
                  ratio(p.vertex_max, r.mls.vertex_max).c_str(), ratio(p.vertex_rms, r.mls.vertex_rms).c_str(),
                  ratio(p.hausdorff, r.mls.hausdorff).c_str(), ratio(p.rms, r.mls.rms).c_str(),
                  ratio(p.normal_error, r.mls.normal_error).c_str(),
                  r.mls.edge_distance < 0 ? "-" : ratio(p.edge_distance, r.mls.edge_distance).c_str());
    }
  return 0;
}
