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
//   - "sphere": a sphere of radius 0.6 (no sharp edge).
// Methods:
//   - MLS: CGAL::MLS::mls_surface_reconstruction<Parallel_if_available_tag> with the options of
//     mls_mesh's defaults (unified operator, mixed space, Mesh_3, features on, facet size 2 and
//     distance 0.25 times the average spacing), or --operator/--space;
//   - Poisson: CGAL::poisson_surface_reconstruction_delaunay with the average spacing
//     (compute_average_spacing, 6 neighbours) and its default criteria (angle 20, radius 30,
//     distance 0.375 spacings), as in CGAL's Poisson example.
// Figures, against the exact surface (exact closest points, see builtin_solid.h):
//   - seconds: wall time of the call;
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
// Usage: bench_meshing [--spacing S] [--noise SIGMA] [--shapes solid,solid+noise,sphere]
//                      [--operator levin|unified] [--space plane|quadratic|wedge|mixed]
//                      [--threads N]

#include <CGAL/MLS_projection/Meshing_options.h>
#include <CGAL/MLS_projection/mls_surface_reconstruction.h>

#include <mls_tools/builtin_solid.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
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
using Options = CGAL::MLS::Meshing_options;
namespace PMP = CGAL::Polygon_mesh_processing;

mls_tools::Vec3 to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

struct Figures {
  bool ok = false;
  double seconds = 0;
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
    angle_sum += area * std::acos(cosine) * 180. / M_PI;
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

struct Settings {
  double spacing = 0.03;
  double noise = -1; // < 0: 0.1 x spacing
  std::vector<std::string> shapes = {"solid", "solid+noise", "sphere"};
  Options::Operator op = Options::Operator::UNIFIED;
  Options::Space space = Options::Space::MIXED;
  int threads = 0;
};

[[noreturn]] void usage(int code) {
  std::cout << "Usage: bench_meshing [--spacing S] [--noise SIGMA] [--shapes solid,solid+noise,sphere]\n"
               "                     [--operator levin|unified] [--space plane|quadratic|wedge|mixed] [--threads N]\n"
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
    else if(a == "--noise") s.noise = std::stod(value());
    else if(a == "--threads") s.threads = std::stoi(value());
    else if(a == "--shapes") {
      s.shapes.clear();
      std::stringstream ss(value());
      std::string item;
      while(std::getline(ss, item, ',')) s.shapes.push_back(item);
    } else if(a == "--operator") {
      const std::string v = value();
      if(v == "levin") s.op = Options::Operator::LEVIN;
      else if(v == "unified") s.op = Options::Operator::UNIFIED;
      else usage(2);
    } else if(a == "--space") {
      const std::string v = value();
      if(v == "plane") s.space = Options::Space::PLANE;
      else if(v == "quadratic") s.space = Options::Space::QUADRATIC;
      else if(v == "wedge") s.space = Options::Space::WEDGE;
      else if(v == "mixed") s.space = Options::Space::MIXED;
      else usage(2);
    } else
      usage(2);
  }
  if(s.noise < 0) s.noise = 0.1 * s.spacing;
  if(!(s.spacing > 0)) usage(2);
  return s;
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

} // namespace

int main(int argc, char** argv) {
  const Settings s = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> limit;
  if(s.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(s.threads));
#endif
  const char* const space_names[] = {"plane", "quadratic", "wedge", "mixed"};
  std::printf("bench_meshing: spacing %g, noise %g, MLS = %s/%s, Mesh_3, features on; Poisson = "
              "poisson_surface_reconstruction_delaunay (default criteria)\n\n",
              s.spacing, s.noise, s.op == Options::Operator::LEVIN ? "levin" : "unified", space_names[int(s.space)]);

  struct Row {
    std::string shape;
    std::size_t points;
    Figures mls, poisson;
  };
  std::vector<Row> rows;
  for(const std::string& shape : s.shapes) {
    std::unique_ptr<mls_tools::Analytic_solid> solid;
    double sigma = 0;
    if(shape == "solid") solid = std::make_unique<mls_tools::Bored_filleted_box>();
    else if(shape == "solid+noise") {
      solid = std::make_unique<mls_tools::Bored_filleted_box>();
      sigma = s.noise;
    } else if(shape == "sphere") solid = std::make_unique<mls_tools::Sphere_solid>(0.6);
    else {
      std::cerr << "bench_meshing: unknown shape '" << shape << "'\n";
      return 2;
    }
    const mls_tools::Point_cloud cloud = solid->sample(s.spacing, sigma);
    std::vector<Point_with_normal> points;
    for(std::size_t i = 0; i < cloud.size(); ++i)
      points.emplace_back(Point(cloud.points[i][0], cloud.points[i][1], cloud.points[i][2]),
                          Vector(cloud.normals[i][0], cloud.normals[i][1], cloud.normals[i][2]));
    const auto point_map = CGAL::First_of_pair_property_map<Point_with_normal>();
    const auto normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>();
    Row row{shape, points.size(), {}, {}};

    {
      Options options;
      options.projection_operator = s.op;
      options.space = s.space;
      CGAL::MLS::Meshing_report report;
      options.report = &report;
      Mesh mesh;
      const auto t = std::chrono::steady_clock::now();
      const bool ok = CGAL::MLS::mls_surface_reconstruction<CGAL::Parallel_if_available_tag>(
        points, mesh, options, CGAL::parameters::point_map(point_map).normal_map(normal_map));
      const double seconds = seconds_since(t);
      row.mls = measure(mesh, *solid, s.spacing);
      row.mls.ok = ok && row.mls.ok;
      row.mls.seconds = seconds;
      row.mls.feature_polylines = report.feature_polylines;
      row.mls.corners = report.corners;
      std::fprintf(stderr, "%s: MLS %.1f s%s%s (seeds %.1f s, features %.1f s, meshing %.1f s)\n", shape.c_str(),
                   seconds, ok ? "" : ", failed: ", ok ? "" : report.failure, report.seconds_seeds,
                   report.seconds_features, report.seconds_meshing);
    }
    {
      Mesh mesh;
      const double spacing = CGAL::compute_average_spacing<CGAL::Sequential_tag>(
        points, 6, CGAL::parameters::point_map(point_map));
      const auto t = std::chrono::steady_clock::now();
      const bool ok = CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), point_map, normal_map,
                                                                   mesh, spacing);
      const double seconds = seconds_since(t);
      row.poisson = measure(mesh, *solid, s.spacing);
      row.poisson.ok = ok && row.poisson.ok;
      row.poisson.seconds = seconds;
      std::fprintf(stderr, "%s: Poisson %.1f s%s\n", shape.c_str(), seconds, ok ? "" : ", failed");
    }
    rows.push_back(row);
  }

  std::printf("| shape | points | method | seconds | vertices | facets | closed | vertex max | vertex RMS | Hausdorff | RMS "
              "| normal error (deg) | edge distance | features |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const auto print = [](const Row& r, const char* method, const Figures& f) {
    if(!f.ok) {
      std::printf("| %s | %zu | %s | %.1f | failed | | | | | | | | | |\n", r.shape.c_str(), r.points, method, f.seconds);
      return;
    }
    std::printf("| %s | %zu | %s | %.1f | %zu | %zu | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.shape.c_str(), r.points,
                method, f.seconds, f.vertices, f.facets, f.closed ? "yes" : "no", fmt(f.vertex_max).c_str(),
                fmt(f.vertex_rms).c_str(), fmt(f.hausdorff).c_str(), fmt(f.rms).c_str(), fmt(f.normal_error, "%.2f").c_str(),
                f.edge_distance < 0 ? "-" : fmt(f.edge_distance).c_str(),
                std::string(method) == "Poisson" ? "-"
                                                 : (std::to_string(f.feature_polylines) + " polylines, " +
                                                    std::to_string(f.corners) + " corners").c_str());
  };
  for(const Row& r : rows) {
    print(r, "MLS", r.mls);
    print(r, "Poisson", r.poisson);
  }
  std::printf("\nRatios Poisson / MLS (> 1: MLS better; for seconds, > 1: MLS faster):\n\n");
  std::printf("| shape | seconds | vertex max | vertex RMS | Hausdorff | RMS | normal error | edge distance |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for(const Row& r : rows) {
    if(!r.mls.ok || !r.poisson.ok) {
      std::printf("| %s | (a method failed) | | | | | | |\n", r.shape.c_str());
      continue;
    }
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", r.shape.c_str(), ratio(r.poisson.seconds, r.mls.seconds).c_str(),
                ratio(r.poisson.vertex_max, r.mls.vertex_max).c_str(), ratio(r.poisson.vertex_rms, r.mls.vertex_rms).c_str(),
                ratio(r.poisson.hausdorff, r.mls.hausdorff).c_str(), ratio(r.poisson.rms, r.mls.rms).c_str(),
                ratio(r.poisson.normal_error, r.mls.normal_error).c_str(),
                r.mls.edge_distance < 0 ? "-" : ratio(r.poisson.edge_distance, r.mls.edge_distance).c_str());
  }
  return 0;
}
