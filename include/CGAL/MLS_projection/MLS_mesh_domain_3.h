// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MLS_MESH_DOMAIN_3_H
#define CGAL_MLS_PROJECTION_MLS_MESH_DOMAIN_3_H

#include <CGAL/MLS_projection/MLS_implicit_function.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/internal/meshing/evaluation_monitor.h>
#include <CGAL/MLS_projection/internal/meshing/protected_polylines.h>
#include <CGAL/MLS_projection/internal/meshing/surface_function.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/tags.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {
struct Mesh_domain_access; // builds the domain of the function the meshers evaluate (mesher_calls.h)
} // namespace internal

/// \ingroup PkgMLSProjectionRef
/// A model of `MeshDomainWithFeatures_3` for CGAL's `make_mesh_3()`: the inside of the closed
/// surface \f$f = 0\f$ of an `MLS_implicit_function`, within its bounding sphere, with the
/// surface's sharp features as polylines to protect. This is the domain that
/// `mls_surface_reconstruction()` meshes; with it, a program meshes the surface with its own
/// criteria (`Mesh_criteria_3`) and options.
///
/// The domain evaluates \f$\max(f, |p - c| - R)\f$ for the bounding sphere of centre \f$c\f$ and
/// radius \f$R\f$ (Mesh_3 evaluates points far outside the surface, where \f$f\f$ is defined by
/// the nearest seed alone), caching the values each thread evaluated recently (Mesh_3 evaluates
/// most points several times). Its initial points are where short segments across the surface at
/// up to 128 seeds cross it, and the intersection of a segment with the surface is found from the
/// values of \f$f\f$ (Illinois' regula falsi), not their signs alone.
///
/// The domain is empty when the surface is not closed inside the bounding sphere (\f$f \le 0\f$ on
/// the sphere: the points bound no volume, as coplanar points or an open scan), when \f$f\f$ has
/// no inside, or when the function is not valid: `is_closed()` is then `false`, and `make_mesh_3()`
/// returns a complex without facets at once (its initial points are then four points outside the
/// domain), where it would otherwise refine the sphere's intersection with the surface without
/// end. Open scans are meshed by `mls_surface_reconstruction()` with `open_surface`.
///
/// The feature polylines (`feature_polylines()`) are those of `detect_sharp_features()` on the
/// seeds' projections, fitted to \f$f = 0\f$ (see the manual, section
/// \ref MLSProjectionMeshingCriteria): a polyline whose vertices lie a median \f$|f|\f$ further than
/// the facet distance off the surface is dropped, and in the others the vertices further off are
/// removed and the rest moved onto the surface. Mesh_3 never moves the centres of its protecting
/// balls; next to a centre off the surface, its manifold refinement may not end. With polylines,
/// Mesh_3 starts from their protecting balls, and components of the surface away from them may be
/// missed (`mls_surface_reconstruction()` inserts the initial points it missed and refines again,
/// and removes the components of the mesh away from the data or smaller than a facet).
/// Use an edge size along the polylines of at most 0.75 facet sizes (with larger protecting balls,
/// the manifold refinement next to close polylines can loop without end), `manifold()`, and no
/// cell criterion when only the surface is wanted.
///
/// \tparam GeomTraits the kernel of Mesh_3's triangulation, with exact predicates (Mesh_3's
///         protection of polylines crashed with `Simple_cartesian<double>`); the implicit function
///         may use any kernel whose `FT` converts to `double`
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel>
class MLS_mesh_domain_3 : public Mesh_domain_with_polyline_features_3<Labeled_mesh_domain_3<GeomTraits>> {
  using Base = Mesh_domain_with_polyline_features_3<Labeled_mesh_domain_3<GeomTraits>>;
  using Labeled = Labeled_mesh_domain_3<GeomTraits>;
  using Function = internal::Monitored_function<GeomTraits>;

public:
  /// \name Types
  /// @{
  /// The kernel's point.
  using Point_3 = typename GeomTraits::Point_3;
  /// The kernel's segment.
  using Segment_3 = typename GeomTraits::Segment_3;
  /// The kernel's sphere.
  using Sphere_3 = typename GeomTraits::Sphere_3;
  /// A feature polyline.
  using Polyline = std::vector<Point_3>;
  /// @}
  /// \cond SKIP_IN_MANUAL
  using Intersection = typename Base::Intersection;
  /// \endcond

  /// The domain of the surface of `function`, its polylines detected and fitted.
  ///
  /// \tparam Projection the projection operator of the function
  /// \tparam NamedParameters a sequence of named parameters of this package's chain
  ///         (`CGAL::MLS::parameters::`)
  /// \param function the implicit function; the domain shares its data (copies are cheap)
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{features}
  ///     \cgalParamDescription{`bool`: detect the sharp-feature polylines and add them to the
  ///       domain (operators that find creases: a wedge fan, alone or mixed; none for the others)}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{facet_distance}
  ///     \cgalParamDescription{`double`: the facet distance of the mesh criteria, within which
  ///       the polylines are fitted to the surface}
  ///     \cgalParamDefault{\f$s/4\f$, \f$s\f$ the average spacing of the samples
  ///       (`compute_average_spacing()`, 6 neighbours), as in `mls_surface_reconstruction()`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <class Projection, class NamedParameters = parameters::Default_named_parameters>
  explicit MLS_mesh_domain_3(const MLS_implicit_function<Projection>& function,
                             const NamedParameters& np = parameters::default_values())
    : MLS_mesh_domain_3(make_parts(function, np)) {}

  /// \name Queries
  /// @{
  /// Whether the surface is closed inside the bounding sphere and the function valid with an
  /// inside; when not, the domain is empty.
  bool is_closed() const { return closed_; }
  /// The polylines added to the domain with `add_features()` by the constructor (a closed polyline
  /// repeats its first point).
  const std::vector<Polyline>& feature_polylines() const { return polylines_; }
  /// The corners that `detect_sharp_features()` found.
  std::size_t number_of_corners() const { return corners_; }
  /// The polylines dropped because the surface does not pass through them.
  std::size_t number_of_off_surface_polylines() const { return off_surface_; }
  /// The helper and relaxation points that the feature detection projected.
  std::size_t number_of_feature_queries() const { return feature_queries_; }
  /// The evaluations of the function so far (not counting the cached values).
  std::size_t number_of_evaluations() const { return function_.monitor->count.load(); }
  /// @}

  /// \cond SKIP_IN_MANUAL
  struct Construct_intersection {
    const MLS_mesh_domain_3* domain;
    Intersection operator()(const Segment_3& s) const { return domain->intersection(s.source(), s.target()); }
    template <class Query> // rays and lines: the labeled domain's bisection (rare: the convex hull's)
    Intersection operator()(const Query& q) const { return domain->Base::construct_intersection_object()(q); }
  };
  Construct_intersection construct_intersection_object() const { return Construct_intersection{this}; }

  struct Construct_initial_points {
    const MLS_mesh_domain_3* domain;
    template <class OutputIterator>
    OutputIterator operator()(OutputIterator pts, const int n = 12) const {
      if(!domain->closed_) return domain->outside_points(pts);
      int found = 0;
      for(const auto& s : domain->probes_) {
        const Segment_3 segment(s.first, s.second);
        const auto surface = domain->do_intersect_surface_object()(segment);
        if(!surface) continue;
        const Point_3 p = std::get<0>(domain->construct_intersection_object()(segment));
        *pts++ = std::make_pair(p, domain->index_from_surface_patch_index(*surface));
        ++found;
      }
      // Mesh_3's random segments from the centre, which search without end on an empty domain
      if(found == 0) return domain->Base::construct_initial_points_object()(pts, n);
      return pts;
    }
  };
  Construct_initial_points construct_initial_points_object() const { return Construct_initial_points{this}; }
  /// \endcond

private:
  friend struct internal::Mesh_domain_access;

  // The domain of a closed surface given as the meshers evaluate it (`function`; `monitor`
  // counts, stops and reports), bounded by `sphere`, with the intersections within
  // `relative_error` bounding radii of the surface.
  MLS_mesh_domain_3(std::function<double(const Point_3&)> function, const Sphere_3& sphere, double relative_error,
                    std::vector<std::pair<Point_3, Point_3>> probes, std::shared_ptr<internal::Evaluation_monitor> monitor)
    : MLS_mesh_domain_3([&] {
        Parts parts;
        parts.function = std::make_shared<const std::function<double(const Point_3&)>>(std::move(function));
        parts.monitor = std::move(monitor);
        parts.sphere = sphere;
        parts.relative_error = relative_error;
        parts.probes = std::move(probes);
        parts.closed = true;
        return parts;
      }()) {}

  struct Parts {
    std::shared_ptr<const std::function<double(const Point_3&)>> function;
    std::shared_ptr<internal::Evaluation_monitor> monitor = std::make_shared<internal::Evaluation_monitor>();
    Sphere_3 sphere;
    // intersections to 10^-6 of the bounding radius: Illinois' steps cost little (f is close to a
    // signed distance), and Mesh_3 places the surface vertices there
    double relative_error = 1e-6;
    std::vector<std::pair<Point_3, Point_3>> probes;
    std::vector<Polyline> polylines;
    bool closed = false;
    std::size_t corners = 0, off_surface = 0, feature_queries = 0;
  };

  explicit MLS_mesh_domain_3(Parts parts)
    : Base(Labeled::create_implicit_mesh_domain(Function{parts.function, parts.monitor}, parts.sphere,
                                                CGAL::parameters::relative_error_bound = parts.relative_error)),
      function_{parts.function, parts.monitor}, sphere_(parts.sphere),
      error_(parts.relative_error * std::sqrt(CGAL::to_double(parts.sphere.squared_radius()))),
      probes_(std::move(parts.probes)), polylines_(std::move(parts.polylines)), closed_(parts.closed),
      corners_(parts.corners), off_surface_(parts.off_surface), feature_queries_(parts.feature_queries) {
    if(!polylines_.empty()) this->add_features(polylines_.begin(), polylines_.end());
  }

  template <class Projection, class NamedParameters>
  static Parts make_parts(const MLS_implicit_function<Projection>& function, const NamedParameters& np) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using Function_point = typename MLS_implicit_function<Projection>::Point_3;
    Parts parts;
    const auto sphere = function.bounding_sphere();
    parts.sphere = Sphere_3(internal::point_as<Point_3>(sphere.center()), CGAL::to_double(sphere.squared_radius()));
    parts.closed = internal::closed_surface_failure(function) == nullptr;
    if(!parts.closed) {
      parts.function = std::make_shared<const std::function<double(const Point_3&)>>([](const Point_3&) { return 1.; });
      return parts;
    }
    parts.function =
      std::make_shared<const std::function<double(const Point_3&)>>(internal::clamped_to_sphere<Point_3>(function));
    const double h = function.bandwidth();
    parts.probes = internal::surface_probes<Point_3>(function.projected_seeds(), h, h);
    if(!choose_parameter(get_parameter(np, internal_np::mls_features), true)) return parts;
    double facet_distance = choose_parameter(get_parameter(np, internal_np::mls_facet_distance), 0.);
    if(!(facet_distance > 0)) facet_distance = 0.25 * average_spacing(function.projection().samples());
    std::vector<std::vector<Function_point>> polylines =
      internal::feature_polylines<Parallel_if_available_tag>(function, parts.corners, parts.feature_queries);
    parts.off_surface = internal::drop_polylines_off_surface(polylines, function, facet_distance);
    internal::fit_polylines_to_surface(polylines, function, facet_distance, 1e-4 * facet_distance);
    for(const auto& line : polylines) {
      parts.polylines.emplace_back();
      for(const Function_point& p : line) parts.polylines.back().push_back(internal::point_as<Point_3>(p));
    }
    return parts;
  }

  // The vertices of a tetrahedron in the sphere, outside the domain: on an empty domain, Mesh_3
  // starts from them (it asserts a triangulation of dimension 2 at least) and ends at once, with
  // no facet (Mesh_3's own random segments from the centre would search without end).
  template <class OutputIterator>
  OutputIterator outside_points(OutputIterator pts) const {
    const double r = 0.5 * std::sqrt(CGAL::to_double(sphere_.squared_radius()));
    const Point_3& c = sphere_.center();
    const auto index = this->index_from_surface_patch_index(typename Base::Surface_patch_index(0, 1));
    for(const int s : {1, -1})
      for(const int t : {1, -1})
        *pts++ = std::make_pair(Point_3(c.x() + s * r, c.y() + t * r, c.z() + s * t * r), index);
    return pts;
  }

  template <class Samples>
  static double average_spacing(const Samples& samples) {
    std::vector<typename Samples::Point> points(samples.size());
    for(std::size_t i = 0; i < samples.size(); ++i) points[i] = samples.to_world(samples.local_point(i));
    return CGAL::to_double(compute_average_spacing<Parallel_if_available_tag>(points, 6));
  }

  // A point of [a, b] where f changes sign, within `error_` of the crossing along the segment
  // (Illinois' regula falsi: the function is close to a signed distance, so few steps are needed);
  // no intersection when the labels of a and b agree.
  Intersection intersection(const Point_3& a, const Point_3& b) const {
    const auto patch = this->do_intersect_surface_object()(Segment_3(a, b)); // the ends' values, cached
    if(!patch) return Intersection();
    const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y()), az = CGAL::to_double(a.z());
    const double dx = CGAL::to_double(b.x()) - ax, dy = CGAL::to_double(b.y()) - ay, dz = CGAL::to_double(b.z()) - az;
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
    const auto f = [&](double t) { return function_.value(ax + t * dx, ay + t * dy, az + t * dz); };
    // the ends as the labels were computed (cached): a + (b - a) may differ from b by rounding
    double t0 = 0, t1 = 1, f0 = f(0.);
    double f1 = function_.value(CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z()));
    double t = 0.5;
    int side = 0;
    for(int it = 0; it < 64 && (t1 - t0) * length > error_; ++it) {
      t = (f1 - f0) != 0 ? (t0 * f1 - t1 * f0) / (f1 - f0) : 0.5 * (t0 + t1);
      if(!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
      const double ft = f(t);
      if(std::abs(ft) <= error_) break;
      if((ft < 0) == (f0 < 0)) {
        t0 = t;
        f0 = ft;
        if(side == -1) f1 *= 0.5; // Illinois: halve the end that stays
        side = -1;
      } else {
        t1 = t;
        f1 = ft;
        if(side == 1) f0 *= 0.5;
        side = 1;
      }
      t = 0.5 * (t0 + t1);
    }
    return Intersection(Point_3(ax + t * dx, ay + t * dy, az + t * dz), this->index_from_surface_patch_index(*patch), 2);
  }

  Function function_;
  Sphere_3 sphere_;
  double error_;
  std::vector<std::pair<Point_3, Point_3>> probes_;
  std::vector<Polyline> polylines_;
  bool closed_;
  std::size_t corners_, off_surface_, feature_queries_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MLS_MESH_DOMAIN_3_H
