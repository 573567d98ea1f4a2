// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Simulated scans of CAD parts, and their distances to the part, for the benchmark.
//
//   scan_part sample MESH.off N NOISE SEED OUT.xyz
//       N points drawn uniformly by area on the triangle mesh, plus isotropic Gaussian noise of
//       standard deviation NOISE times the diagonal of the mesh's bounding box on each
//       coordinate, written as "x y z" lines (no normals, as a scanner delivers them).
//       Deterministic: the same arguments give the same points on every machine, whatever the
//       order of the mesh's faces.
//   scan_part distance MESH.off POINTS
//       The distances of the points of POINTS (.xyz lines, or the vertices of an .off mesh) to
//       the mesh, as fractions of the diagonal: one line "rms R max M p99 P n N".
//   scan_part spacing POINTS
//       The average spacing of the points (CGAL's compute_average_spacing, 6 neighbours).
//   scan_part mesh PART.off MESH.off
//       The quality of a reconstructed mesh against the part, lengths as fractions of the part's
//       diagonal: one line "closed C manifold M components K self_intersecting S hausdorff H
//       rms R normal_deg A edge_distance E". Hausdorff: the larger of the mesh's vertices'
//       distance to the part and of the distance to the mesh of the part sampled at 200000
//       points (RMS: of the latter); normal error: mean angle, weighted by area, between each
//       facet's normal and the part's at the point closest to its centroid; edge distance: mean
//       distance to the mesh of the part's sharp edges (dihedral angle above 30 degrees) sampled
//       every 0.002 diagonal. Without a mesh (unreadable, empty): "none"; a mesh with an edge or a
//       vertex that is not manifold: "closed 0 manifold 0".

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>
#include <CGAL/compute_average_spacing.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Exact_point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

// Uniform and normal variates from mt19937_64's specified output (the standard distributions
// are implementation-defined).
class Random {
public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * (1.0 / 9007199254740992.0); }
  double normal() {
    double u = 0;
    while(u <= 0) u = uniform();
    return std::sqrt(-2. * std::log(u)) * std::cos(6.283185307179586 * uniform());
  }

private:
  std::mt19937_64 engine_;
};

Mesh read_mesh(const std::string& file) {
  Mesh mesh;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(file, mesh) || mesh.is_empty())
    throw std::runtime_error("cannot read the mesh " + file);
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  return mesh;
}

double diagonal(const Mesh& mesh) {
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

std::vector<Point> read_points(const std::string& file) {
  std::vector<Point> points;
  std::ifstream in(file);
  if(!in) throw std::runtime_error("cannot read " + file);
  std::string line;
  if(file.size() > 4 && file.substr(file.size() - 4) == ".off") {
    Mesh mesh;
    if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(file, mesh)) throw std::runtime_error("cannot read " + file);
    for(const auto v : mesh.vertices()) points.push_back(mesh.point(v));
    return points;
  }
  while(std::getline(in, line)) {
    std::istringstream s(line);
    double x, y, z;
    if(s >> x >> y >> z) points.emplace_back(x, y, z);
  }
  return points;
}

int sample(const std::string& file, std::size_t n, double noise, std::uint64_t seed, const std::string& out_file) {
  const Mesh mesh = read_mesh(file);
  const double sigma = noise * diagonal(mesh);
  // The triangles in a canonical order (each from its smallest vertex, then sorted): OpenSCAD
  // writes the same faces in another order from one export to the next.
  std::vector<std::array<Point, 3>> triangles;
  for(const auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    std::array<Point, 3> t = {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h)))};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  std::vector<double> area;
  double total = 0;
  for(const auto& t : triangles) {
    total += std::sqrt(CGAL::squared_area(t[0], t[1], t[2]));
    area.push_back(total);
  }
  Random rng(seed);
  std::ofstream out(out_file);
  out.precision(17);
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t k = std::size_t(std::lower_bound(area.begin(), area.end(), rng.uniform() * total) - area.begin());
    const auto& t = triangles[(std::min)(k, triangles.size() - 1)];
    double u = rng.uniform(), v = rng.uniform();
    if(u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    const Point p = t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
    const double dx = sigma * rng.normal(), dy = sigma * rng.normal(), dz = sigma * rng.normal();
    out << p.x() + dx << ' ' << p.y() + dy << ' ' << p.z() + dz << '\n';
  }
  return out ? 0 : 1;
}

int distance(const std::string& mesh_file, const std::string& points_file) {
  const Mesh mesh = read_mesh(mesh_file);
  const double diag = diagonal(mesh);
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  std::vector<double> d;
  for(const Point& p : read_points(points_file)) d.push_back(std::sqrt(tree.squared_distance(p)) / diag);
  if(d.empty()) throw std::runtime_error("no point in " + points_file);
  double sum = 0;
  for(double x : d) sum += x * x;
  std::sort(d.begin(), d.end());
  std::printf("rms %.4g max %.4g p99 %.4g n %zu\n", std::sqrt(sum / double(d.size())), d.back(), d[d.size() * 99 / 100],
              d.size());
  return 0;
}

// The quality figures of `scan_part mesh` (see the header).
int mesh_quality(const std::string& part_file, const std::string& mesh_file) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Mesh part = read_mesh(part_file);
  const double diag = diagonal(part);
  std::vector<Point> soup_points;
  std::vector<std::vector<std::size_t>> soup;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_soup(mesh_file, soup_points, soup) || soup.empty()) {
    std::printf("none\n");
    return 0;
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup)) { // an edge or a vertex that is not manifold
    std::printf("closed 0 manifold 0\n");
    return 0;
  }
  PMP::polygon_soup_to_polygon_mesh(soup_points, soup, mesh);
  const bool closed = CGAL::is_closed(mesh);
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:c", 0).first;
  const std::size_t components = PMP::connected_components(mesh, component);
  // with exact predicates: nearly coplanar facets fool the inexact kernel's tests
  std::vector<Exact_point> exact_points;
  for(const Point& p : soup_points) exact_points.emplace_back(p.x(), p.y(), p.z());
  CGAL::Surface_mesh<Exact_point> exact_mesh;
  PMP::polygon_soup_to_polygon_mesh(exact_points, soup, exact_mesh);
  const bool self_intersecting = PMP::does_self_intersect(exact_mesh);

  Tree part_tree(faces(part).first, faces(part).second, part), mesh_tree(faces(mesh).first, faces(mesh).second, mesh);
  part_tree.accelerate_distance_queries();
  mesh_tree.accelerate_distance_queries();
  double hausdorff = 0, sum2 = 0;
  for(const auto v : mesh.vertices()) hausdorff = (std::max)(hausdorff, std::sqrt(part_tree.squared_distance(mesh.point(v))));
  std::vector<Point> samples;
  PMP::sample_triangle_mesh(part, std::back_inserter(samples), CGAL::parameters::number_of_points_on_faces(200000).random_seed(1));
  for(const Point& p : samples) {
    const double d2 = mesh_tree.squared_distance(p);
    hausdorff = (std::max)(hausdorff, std::sqrt(d2));
    sum2 += d2;
  }
  double angle_area = 0, area = 0;
  for(const auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h)), c = mesh.point(mesh.target(mesh.next(h)));
    const double w = std::sqrt(CGAL::squared_area(a, b, c));
    if(!(w > 0)) continue;
    const auto closest = part_tree.closest_point_and_primitive(CGAL::centroid(a, b, c));
    const Kernel::Vector_3 n = PMP::compute_face_normal(f, mesh), m = PMP::compute_face_normal(closest.second, part);
    angle_area += w * std::acos(std::clamp(n * m, -1., 1.)) * 180. / CGAL_PI;
    area += w;
  }
  double edge_sum = 0;
  std::size_t edge_samples = 0;
  for(const auto e : part.edges()) {
    const auto h = part.halfedge(e);
    if(part.is_border(e)) continue;
    const auto n0 = PMP::compute_face_normal(part.face(h), part), n1 = PMP::compute_face_normal(part.face(part.opposite(h)), part);
    if(n0 * n1 > std::cos(30. * CGAL_PI / 180.)) continue;
    const Point a = part.point(part.source(h)), b = part.point(part.target(h));
    const int steps = (std::max)(1, int(std::sqrt(CGAL::squared_distance(a, b)) / (0.002 * diag)));
    for(int i = 0; i <= steps; ++i) {
      edge_sum += std::sqrt(mesh_tree.squared_distance(a + (double(i) / steps) * (b - a)));
      ++edge_samples;
    }
  }
  std::printf("closed %d manifold 1 components %zu self_intersecting %d hausdorff %.4g rms %.4g normal_deg %.3g "
              "edge_distance %.4g\n",
              int(closed), components, int(self_intersecting), hausdorff / diag,
              std::sqrt(sum2 / double(samples.size())) / diag, area > 0 ? angle_area / area : 0.,
              edge_samples > 0 ? edge_sum / double(edge_samples) / diag : 0.);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if(mode == "sample" && argc == 7)
      return sample(argv[2], std::stoul(argv[3]), std::stod(argv[4]), std::stoull(argv[5]), argv[6]);
    if(mode == "distance" && argc == 4) return distance(argv[2], argv[3]);
    if(mode == "spacing" && argc == 3) {
      const auto points = read_points(argv[2]);
      std::printf("%.6g\n", CGAL::compute_average_spacing<CGAL::Sequential_tag>(points, 6));
      return 0;
    }
    if(mode == "mesh" && argc == 4) return mesh_quality(argv[2], argv[3]);
    std::cerr << "usage: scan_part sample MESH.off N NOISE SEED OUT.xyz | distance MESH.off POINTS | spacing POINTS"
                 " | mesh PART.off MESH.off\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "scan_part: " << e.what() << "\n";
    return 1;
  }
}
