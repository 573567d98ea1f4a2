// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Analytic solids for the meshing tool and its benchmark: the built-in input of mls_mesh (a box
// with a cylindrical bore and one rounded edge) and a sphere, each with
//  - its exact closest point, unit outward normal and signed distance (negative inside), to
//    measure the error of a reconstructed mesh;
//  - its true sharp edges as fine polylines (segments and circular arcs) and its corners, to
//    measure how well a mesh keeps them;
//  - a deterministic sampling (fixed seed, own variates as in <mls_tools/synthetic.h>) at a given
//    mean spacing, by area, with optional isotropic Gaussian noise and the exact outward normals
//    of the unperturbed positions.
// Every surface is a union of patches (planar regions, cylinder pieces); the closest point on the
// surface is the nearest of the patches' closest points, each computed exactly, so the distance
// is exact everywhere (inside, outside, near concave and convex edges), unlike min/max
// combinations of signed distance functions, which are only bounds near edges.

#ifndef MLS_TOOLS_BUILTIN_SOLID_H
#define MLS_TOOLS_BUILTIN_SOLID_H

#include <mls_tools/point_io.h>
#include <mls_tools/synthetic.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mls_tools {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// A point of a solid's surface with the unit outward normal there.
struct Surface_point {
  Vec3 point, normal;
};

/// A solid bounded by patches, with exact distances, sharp edges and a sampler.
class Analytic_solid {
public:
  /// One piece of the boundary: its area, a sampler of a uniform (by area) point with its outward
  /// normal from two uniform variates in [0, 1) (nullopt-like: `false` rejects the sample, for
  /// trimmed patches), and its exact closest point to any point of space.
  struct Patch {
    double area;
    std::function<bool(double, double, Surface_point&)> sample;
    std::function<Surface_point(const Vec3&)> closest;
  };

  virtual ~Analytic_solid() = default;
  virtual std::string name() const = 0;
  /// Whether `p` is inside the solid (the boundary's measure-zero ties do not matter).
  virtual bool contains(const Vec3& p) const = 0;
  /// An axis-aligned box holding the solid: min and max corners.
  virtual std::array<Vec3, 2> bounding_box() const = 0;

  const std::vector<Patch>& patches() const { return patches_; }
  double area() const {
    double a = 0;
    for(const Patch& p : patches_) a += p.area;
    return a;
  }

  /// The nearest surface point to `p`, with its outward normal.
  Surface_point closest_point(const Vec3& p) const {
    Surface_point best{p, {0., 0., 0.}};
    double best_d = std::numeric_limits<double>::infinity();
    for(const Patch& patch : patches_) {
      const Surface_point c = patch.closest(p);
      const double d = norm(c.point - p);
      if(d < best_d) {
        best_d = d;
        best = c;
      }
    }
    return best;
  }
  /// The signed distance from `p` to the surface, negative inside.
  double signed_distance(const Vec3& p) const {
    const double d = norm(closest_point(p).point - p);
    return contains(p) ? -d : d;
  }

  /// The true sharp edges (creases), each a polyline of points at most `step` apart.
  std::vector<std::vector<Vec3>> sharp_edges(double step = 0.01) const {
    std::vector<std::vector<Vec3>> polylines;
    for(const auto& curve : curves_) {
      const int n = std::max(1, int(std::ceil(curve.length / step)));
      std::vector<Vec3> polyline;
      for(int i = 0; i <= n; ++i) polyline.push_back(curve.at(double(i) / n));
      polylines.push_back(std::move(polyline));
    }
    return polylines;
  }
  std::size_t number_of_sharp_edges() const { return curves_.size(); }
  /// The corners: where three or more sharp edges meet.
  const std::vector<Vec3>& corners() const { return corners_; }

  /// About area / spacing^2 points uniform by area (fixed seed: the same points on every run and
  /// platform), moved by isotropic Gaussian noise of standard deviation `sigma`, with the exact
  /// outward normals of their unperturbed positions.
  Point_cloud sample(double spacing, double sigma = 0., std::uint64_t seed = 20260415) const {
    Random random(seed);
    Point_cloud cloud;
    cloud.dimension = 3;
    cloud.has_normals = true;
    for(const Patch& patch : patches_) {
      const std::size_t n = std::size_t(std::llround(patch.area / (spacing * spacing)));
      std::size_t made = 0;
      while(made < n) {
        Surface_point s;
        const double u = random.uniform(), v = random.uniform();
        if(!patch.sample(u, v, s)) continue;
        Vec3 p = s.point;
        if(sigma > 0)
          for(int k = 0; k < 3; ++k) p[k] += sigma * random.gaussian();
        cloud.points.push_back(p);
        cloud.normals.push_back(s.normal);
        ++made;
      }
    }
    return cloud;
  }

protected:
  struct Curve {
    double length;
    std::function<Vec3(double)> at; // t in [0, 1]
  };
  void add_segment(const Vec3& a, const Vec3& b) {
    curves_.push_back({norm(b - a), [a, b](double t) { return a + t * (b - a); }});
  }
  /// The arc centre + r (cos t u + sin t v), t in [t0, t1].
  void add_arc(const Vec3& centre, const Vec3& u, const Vec3& v, double r, double t0, double t1) {
    curves_.push_back({r * (t1 - t0), [=](double s) {
                         const double t = t0 + s * (t1 - t0);
                         return centre + (r * std::cos(t)) * u + (r * std::sin(t)) * v;
                       }});
  }

  // Patch helpers.
  /// The axis-aligned rectangle of the plane x[axis] = level, [lo, hi] in the two other
  /// coordinates (in increasing axis order), with outward normal sign * e_axis, minus an optional
  /// disk (centre and radius in the same two coordinates) lying inside the rectangle.
  void add_rectangle(int axis, double level, double sign, std::array<double, 2> lo, std::array<double, 2> hi,
                     std::array<double, 2> disk_centre = {0., 0.}, double disk_radius = 0.) {
    const int i = (axis + 1) % 3 < (axis + 2) % 3 ? (axis + 1) % 3 : (axis + 2) % 3;
    const int j = 3 - axis - i;
    Vec3 n{0., 0., 0.};
    n[std::size_t(axis)] = sign;
    const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]) - CGAL_PI * disk_radius * disk_radius;
    const auto in_disk = [=](double a, double b) {
      return disk_radius > 0 && std::hypot(a - disk_centre[0], b - disk_centre[1]) < disk_radius;
    };
    const auto make = [=](double a, double b) {
      Vec3 p;
      p[std::size_t(axis)] = level;
      p[std::size_t(i)] = a;
      p[std::size_t(j)] = b;
      return Surface_point{p, n};
    };
    patches_.push_back(
      {area,
       [=](double u, double v, Surface_point& s) {
         const double a = lo[0] + u * (hi[0] - lo[0]), b = lo[1] + v * (hi[1] - lo[1]);
         if(in_disk(a, b)) return false;
         s = make(a, b);
         return true;
       },
       [=](const Vec3& p) {
         double a = std::clamp(p[std::size_t(i)], lo[0], hi[0]), b = std::clamp(p[std::size_t(j)], lo[1], hi[1]);
         if(in_disk(a, b)) { // only when p projects inside the disk: the nearest point is on its circle
           double da = a - disk_centre[0], db = b - disk_centre[1];
           const double r = std::hypot(da, db);
           if(r > 0) {
             da /= r;
             db /= r;
           } else {
             da = 1;
             db = 0;
           }
           a = disk_centre[0] + disk_radius * da;
           b = disk_centre[1] + disk_radius * db;
         }
         return make(a, b);
       }});
  }

  std::vector<Patch> patches_;
  std::vector<Curve> curves_;
  std::vector<Vec3> corners_;
};

/// The built-in input of mls_mesh: the box [-a, a] x [-b, b] x [-c, c] (a = 1, b = 0.6, c = 0.4)
/// whose edge {x = a, z = c} is rounded by a quarter-cylinder fillet of radius rf = 0.25 (axis
/// along y), with a cylindrical bore of radius rb = 0.25 along z through it, centred at
/// (x, y) = (-0.35, 0). Sharp: 11 straight edges at 90 degrees, the two quarter-circle arcs where
/// the fillet meets the faces y = +-b, and the bore's two rims (90 degrees, concave along the
/// bore); 6 corners. The fillet meets the top face and the face x = a tangentially (no crease).
/// Area 10.63: spacing 0.03 gives about 11800 points.
class Bored_filleted_box : public Analytic_solid {
public:
  static constexpr double a = 1., b = 0.6, c = 0.4, rf = 0.25, rb = 0.25, xb = -0.35, yb = 0.;

  Bored_filleted_box() {
    const double xf = a - rf, zf = c - rf; // axis of the fillet
    // Planar faces.
    add_rectangle(2, c, 1., {-a, -b}, {xf, b}, {xb, yb}, rb);  // top, up to the fillet, minus the bore
    add_rectangle(2, -c, -1., {-a, -b}, {a, b}, {xb, yb}, rb); // bottom minus the bore
    add_rectangle(0, -a, -1., {-b, -c}, {b, c});               // x = -a
    add_rectangle(0, a, 1., {-b, -c}, {b, zf});                // x = a, up to the fillet
    for(double sign : {-1., 1.}) {                             // y = +-b: the rounded rectangle
      const Vec3 n{0., sign, 0.};
      const auto inside_2d = [=](double x, double z) {
        return std::abs(x) <= a && std::abs(z) <= c && !(x > xf && z > zf && std::hypot(x - xf, z - zf) > rf);
      };
      patches_.push_back(
        {4 * a * c - (rf * rf - CGAL_PI * rf * rf / 4),
         [=](double u, double v, Surface_point& s) {
           const double x = -a + 2 * a * u, z = -c + 2 * c * v;
           if(!inside_2d(x, z)) return false;
           s = {{x, sign * b, z}, n};
           return true;
         },
         [=](const Vec3& p) {
           double x = p[0], z = p[2];
           if(x > xf && z > zf && std::hypot(x - xf, z - zf) > rf) {
             const double r = std::hypot(x - xf, z - zf);
             x = xf + rf * (x - xf) / r;
             z = zf + rf * (z - zf) / r;
           } else {
             x = std::clamp(x, -a, a);
             z = std::clamp(z, -c, c);
           }
           return Surface_point{{x, sign * b, z}, n};
         }});
    }
    // The fillet: (xf + rf cos t, y, zf + rf sin t), t in [0, pi/2].
    patches_.push_back({CGAL_PI / 2 * rf * 2 * b,
                        [=](double u, double v, Surface_point& s) {
                          const double t = u * CGAL_PI / 2, y = -b + 2 * b * v;
                          s = {{xf + rf * std::cos(t), y, zf + rf * std::sin(t)}, {std::cos(t), 0., std::sin(t)}};
                          return true;
                        },
                        [=](const Vec3& p) {
                          const double t = std::clamp(std::atan2(p[2] - zf, p[0] - xf), 0., CGAL_PI / 2);
                          const double y = std::clamp(p[1], -b, b);
                          return Surface_point{{xf + rf * std::cos(t), y, zf + rf * std::sin(t)},
                                               {std::cos(t), 0., std::sin(t)}};
                        }});
    // The bore's wall, normal towards the bore's axis (out of the solid).
    patches_.push_back({2 * CGAL_PI * rb * 2 * c,
                        [=](double u, double v, Surface_point& s) {
                          const double t = 2 * CGAL_PI * u, z = -c + 2 * c * v;
                          s = {{xb + rb * std::cos(t), yb + rb * std::sin(t), z}, {-std::cos(t), -std::sin(t), 0.}};
                          return true;
                        },
                        [=](const Vec3& p) {
                          const double t = std::atan2(p[1] - yb, p[0] - xb);
                          const double z = std::clamp(p[2], -c, c);
                          return Surface_point{{xb + rb * std::cos(t), yb + rb * std::sin(t), z},
                                               {-std::cos(t), -std::sin(t), 0.}};
                        }});

    // Sharp edges.
    for(double sy : {-1., 1.}) {
      add_segment({-a, sy * b, -c}, {-a, sy * b, c}); // vertical edges of x = -a
      add_segment({a, sy * b, -c}, {a, sy * b, zf});  // vertical edges of x = a, up to the fillet
      add_segment({-a, sy * b, c}, {xf, sy * b, c});  // top edges along x, up to the fillet
      add_segment({-a, sy * b, -c}, {a, sy * b, -c}); // bottom edges along x
      add_arc({xf, sy * b, zf}, {1., 0., 0.}, {0., 0., 1.}, rf, 0., CGAL_PI / 2); // fillet ends
    }
    for(double sz : {-1., 1.}) add_segment({-a, -b, sz * c}, {-a, b, sz * c}); // edges of x = -a along y
    add_segment({a, -b, -c}, {a, b, -c});                                         // bottom edge of x = a
    for(double sz : {-1., 1.})                                                    // the bore's rims
      add_arc({xb, yb, sz * c}, {1., 0., 0.}, {0., 1., 0.}, rb, 0., 2 * CGAL_PI);
    for(double sy : {-1., 1.}) {
      for(double sz : {-1., 1.}) corners_.push_back({-a, sy * b, sz * c});
      corners_.push_back({a, sy * b, -c});
    }
  }

  std::string name() const override { return "bored filleted box"; }
  bool contains(const Vec3& p) const override {
    const double xf = a - rf, zf = c - rf;
    const double x = p[0], y = p[1], z = p[2];
    if(std::abs(x) > a || std::abs(y) > b || std::abs(z) > c) return false;
    if(x > xf && z > zf && std::hypot(x - xf, z - zf) > rf) return false;
    return std::hypot(x - xb, y - yb) > rb;
  }
  std::array<Vec3, 2> bounding_box() const override { return {Vec3{-a, -b, -c}, Vec3{a, b, c}}; }
};

/// A sphere (no sharp edge): the smooth shape of the benchmark.
class Sphere_solid : public Analytic_solid {
public:
  explicit Sphere_solid(double radius = 0.6) : r_(radius) {
    patches_.push_back({4 * CGAL_PI * r_ * r_,
                        [r = r_](double u, double v, Surface_point& s) {
                          const double z = 1 - 2 * u, t = 2 * CGAL_PI * v, q = std::sqrt(std::max(0., 1 - z * z));
                          const Vec3 n{q * std::cos(t), q * std::sin(t), z};
                          s = {r * n, n};
                          return true;
                        },
                        [r = r_](const Vec3& p) {
                          const double l = norm(p);
                          const Vec3 n = l > 0 ? (1. / l) * p : Vec3{0., 0., 1.};
                          return Surface_point{r * n, n};
                        }});
  }
  std::string name() const override { return "sphere"; }
  bool contains(const Vec3& p) const override { return norm(p) < r_; }
  std::array<Vec3, 2> bounding_box() const override { return {Vec3{-r_, -r_, -r_}, Vec3{r_, r_, r_}}; }

private:
  double r_;
};

/// The built-in input of mls_mesh: the bored filleted box sampled at spacing 0.03 (about 11800
/// points), noiseless, with exact outward normals.
inline Point_cloud builtin_solid_points(double spacing = 0.03, double sigma = 0.) {
  return Bored_filleted_box().sample(spacing, sigma);
}

} // namespace mls_tools

#endif // MLS_TOOLS_BUILTIN_SOLID_H
