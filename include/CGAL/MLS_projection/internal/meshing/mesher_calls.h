// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// THE one file of the package that calls CGAL's meshers (Mesh_3 and Surface_mesher), so that
// the API changes of CGAL 6 (named parameters of Mesh_3, the removal of Surface_mesher) touch
// this file only. Everything here works on a type-erased implicit function
// (std::function<double(const Point_3&)>), in Epick (see reconstruct_items): the meshers are
// instantiated once per output mesh type, whatever the projection operator and the kernel.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESHER_CALLS_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESHER_CALLS_H

#include <CGAL/MLS_projection/MLS_mesh_domain_3.h>
#include <CGAL/MLS_projection/internal/meshing/evaluation_monitor.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>

#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Surface_mesh_complex_2_in_triangulation_3.h>
#include <CGAL/Surface_mesh_default_criteria_3.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/make_surface_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The parameters of one mesher run (absolute lengths).
template <class GeomTraits>
struct Mesher_input {
  using Point_3 = typename GeomTraits::Point_3;
  /// The implicit function, negative inside.
  std::function<double(const Point_3&)> function;
  /// A sphere enclosing the surface, \f$f > 0\f$ on its boundary.
  typename GeomTraits::Sphere_3 bounding_sphere;
  /// A point where \f$f < 0\f$ (the centre of Surface_mesher's sphere).
  Point_3 inner_point;
  /// Segments whose ends have opposite signs of \f$f\f$: Mesh_3's initial points are their
  /// intersections with the surface (one per connected component at least, if the caller
  /// provides them); when none crosses, Mesh_3's random segments are used.
  std::vector<std::pair<Point_3, Point_3>> probes;
  /// Feature polylines to protect (Mesh_3 only); a closed polyline repeats its first point.
  std::vector<std::vector<Point_3>> polylines;
  double facet_size = 0;
  double facet_distance = 0;
  double facet_angle = 25;
  /// Mesh_3's edge size along the polylines (0: `facet_size`).
  double edge_size = 0;
  /// The precision of the intersections with the surface, relative to the bounding sphere's radius.
  double relative_error_bound = 1e-6;
  /// Progress in [0, 1) over the meshing, polled from the calling thread every 1024 evaluations
  /// of the function; returning `false` stops the mesher (the output is then left empty).
  std::function<bool(double)> callback;
  /// The expected number of evaluations, which sets the pace of the reported fraction
  /// \f$1 - e^{-n/\mathrm{expected}}\f$.
  double expected_evaluations = 1e6;
  /// The mesher is stopped after this many evaluations (0: no limit): the run then fails.
  std::size_t max_evaluations = 0;
  /// Mesh_3 with polylines: the budget of evaluations, in units of `expected_evaluations`, and
  /// of vertices, in units of the expected number of vertices (`expected_evaluations` / 250),
  /// after which it meshes again without them (0: none).
  double feature_budget = 4;
  /// The mesher is stopped after this many seconds (0: no limit): the run then fails.
  double max_seconds = 0;
};

/// What one mesher run did.
struct Mesher_report {
  bool success = false;
  bool cancelled = false;
  /// Mesh_3 failed with the polylines, or exceeded its budget of evaluations with them
  /// (`feature_budget_exceeded`), and the mesh was made without them.
  bool features_dropped = false;
  bool feature_budget_exceeded = false;
  std::size_t evaluations = 0;
  const char* message = "";
};

// The report of a mesher stopped by the callback, the evaluation limit or the time limit.
inline Mesher_report& stopped(const Evaluation_monitor& monitor, Mesher_report& report) {
  if(monitor.limit_hit.load()) {
    report.message = "the mesher did not finish within the evaluation limit";
  } else if(monitor.stall_hit.load()) {
    report.message = "the mesher stalled (Mesh_3 slowed down to less than a tenth of its pace)";
  } else if(monitor.time_hit.load()) {
    report.message = "the mesher did not finish within the time limit (maximum_running_time)";
  } else {
    report.cancelled = true;
    report.message = "cancelled";
  }
  return report;
}

// Sets the monitor's stop flag after `seconds` of meshing (no limit when `seconds` is not
// positive), or when the mesher has stalled (with `stall_detection`): over the last 5 seconds
// and quarter of the time spent, it evaluated the function at less than a tenth of its fastest
// pace over one second (none at all, often), unless destroyed before. The meshers poll the flag
// in their loops. Next to protected polylines, Mesh_3's manifold refinement can loop without end
// on a point hidden by a protecting ball ("the facet is not in the conflict zone"), evaluating
// nothing new, or slow down as the vertices there gain thousands of incident facets (its test of
// a vertex's manifoldness walks all of them). Healthy runs measured kept more than half their pace.
class Meshing_watchdog {
public:
  Meshing_watchdog(Evaluation_monitor& monitor, double seconds, bool stall_detection) {
    const bool timed = seconds > 0 && std::isfinite(seconds);
    if(!timed && !stall_detection) return;
    thread_ = std::thread([this, &monitor, seconds, timed, stall_detection] {
      using Clock = std::chrono::steady_clock;
      const auto start = Clock::now();
      // the counts polled, with their times since the start
      std::vector<std::pair<double, std::size_t>> history{{0., monitor.count.load()}};
      double peak = 0; // evaluations per second, over one second at least
      std::unique_lock<std::mutex> lock(mutex_);
      // polled every 0.1 s, or at the time limit when sooner
      const auto poll = [&] {
        double wait = 0.1;
        if(timed) wait = (std::min)(wait, (std::max)(0., seconds - std::chrono::duration<double>(Clock::now() - start).count()));
        return std::chrono::duration<double>(wait);
      };
      // the last count polled at least `ago` seconds before `elapsed`
      const auto count_before = [&](double elapsed, double ago) {
        auto it = std::upper_bound(history.begin(), history.end(), elapsed - ago,
                                   [](double t, const std::pair<double, std::size_t>& h) { return t < h.first; });
        return it == history.begin() ? history.front() : *(it - 1);
      };
      while(!done_cv_.wait_for(lock, poll(), [this] { return done_; })) {
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const std::size_t count = monitor.count.load();
        history.emplace_back(elapsed, count);
        const auto second = count_before(elapsed, 1.);
        if(elapsed - second.first >= 1.) peak = (std::max)(peak, double(count - second.second) / (elapsed - second.first));
        const double window = (std::max)(5., 0.25 * elapsed);
        const auto earlier = count_before(elapsed, window);
        if(timed && elapsed >= seconds) {
          monitor.time_hit.store(true);
        } else if(stall_detection && elapsed >= window && double(count - earlier.second) <= 0.1 * peak * (elapsed - earlier.first)) {
          monitor.stall_hit.store(true);
        } else {
          continue;
        }
        monitor.stop.store(true, std::memory_order_release);
        return;
      }
    });
  }
  ~Meshing_watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_all();
    if(thread_.joinable()) thread_.join();
  }
  Meshing_watchdog(const Meshing_watchdog&) = delete;
  Meshing_watchdog& operator=(const Meshing_watchdog&) = delete;

private:
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::thread thread_;
};

// Mesh_3's complex, as a type of this namespace: when Mesh_3 fails on an error (e.g. "already
// inserted on surface"), CGAL 5.5's Refine_facets_3 first writes the complex to dump-bug.* files
// in the working directory through an unqualified call `dump_c3t3(c3t3, prefix)`; argument-
// dependent lookup then also finds the overload below, more specialised than CGAL's, which
// writes nothing (the error itself is caught by `mesh_with_mesh_3`).
template <class Tr, class CornerIndex, class CurveIndex>
struct Mesh_complex : Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex> {
  using Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>::Mesh_complex_3_in_triangulation_3;
};

template <class PolygonMesh>
auto has_clear_keeping_properties(PolygonMesh& mesh, int) -> decltype(mesh.clear_without_removing_property_maps(), std::true_type());
template <class PolygonMesh>
std::false_type has_clear_keeping_properties(PolygonMesh&, long);

template <class Tr, class CornerIndex, class CurveIndex>
void dump_c3t3(const Mesh_complex<Tr, CornerIndex, CurveIndex>&, std::string) {}

// Empties `mesh`, keeping the property maps the caller added (a `Surface_mesh`'s `clear()` removes
// them, and the caller's output maps, e.g. `vertex_attribute_map`, would dangle).
template <class PolygonMesh>
void clear_mesh(PolygonMesh& mesh) {
  if constexpr(std::is_same<decltype(has_clear_keeping_properties(mesh, 0)), std::true_type>::value)
    mesh.clear_without_removing_property_maps();
  else
    CGAL::clear(mesh);
}

// The report of a mesher that ended with `mesh`: a success when it has facets and only finite
// vertices (a mesh with a non-finite vertex is cleared).
template <class PolygonMesh>
Mesher_report& finished(PolygonMesh& mesh, Mesher_report& report) {
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh)) {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z()))) {
      clear_mesh(mesh);
      report.message = "non-finite vertex";
      return report;
    }
  }
  report.success = num_faces(mesh) > 0;
  if(!report.success) report.message = "empty mesh";
  return report;
}

/// Inserts into `c3t3` the domain's initial points (the probes' intersections with the surface)
/// that lie further than `distance` from every surface vertex of the complex, as surface vertices;
/// returns how many. With polylines, Mesh_3 starts from their protecting balls and adds the initial
/// points only when those give no surface facet: the components of the surface away from the
/// polylines were missed, or all of it (on a noisy scan of OpenSCAD's example009, with two short
/// polylines, the mesh was empty).
template <class C3t3, class Domain>
std::size_t insert_missed_initial_points(C3t3& c3t3, const Domain& domain, double distance) {
  using Point_3 = typename Domain::Point_3;
  std::vector<std::pair<Point_3, typename Domain::Index>> initial;
  domain.construct_initial_points_object()(std::back_inserter(initial));
  auto& tr = c3t3.triangulation();
  std::vector<Point_3> surface;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    if(c3t3.in_dimension(v) <= 2 && c3t3.has_incident_facets_in_complex(v)) surface.push_back(tr.point(v).point());
  const auto cwp = tr.geom_traits().construct_weighted_point_3_object();
  const double d2 = distance * distance;
  std::size_t inserted = 0;
  for(const auto& [point, index] : initial) {
    const Point_3& p = point; // a structured binding cannot be captured in C++17
    if(std::any_of(surface.begin(), surface.end(),
                   [&](const Point_3& q) { return CGAL::to_double(CGAL::squared_distance(p, q)) <= d2; }))
      continue;
    const auto v = tr.insert(cwp(p));
    if(v == decltype(v)()) continue; // hidden by a protecting ball
    c3t3.set_dimension(v, 2);
    c3t3.set_index(v, index);
    ++inserted;
  }
  return inserted;
}

// Builds MLS_mesh_domain_3's domain of a function as the meshers evaluate it (a private constructor).
struct Mesh_domain_access {
  template <class Domain, class... Args>
  static Domain make(Args&&... args) { return Domain(std::forward<Args>(args)...); }
};

/// Meshes the surface \f$f = 0\f$ with Mesh_3 (`make_mesh_3` on `Labeled_mesh_domain_3::
/// create_implicit_mesh_domain`, polylines added with `add_features`), criteria facet angle,
/// size and distance (edge size along the polylines), no cell criteria, no perturbation nor
/// exudation (only the surface is kept), `manifold()`; the surface facets are written to `mesh`
/// with `facets_in_complex_3_to_triangle_mesh`. `CGAL::Parallel_tag` runs the parallel Mesh_3
/// (TBB). When Mesh_3 fails with the polylines (a CGAL error, e.g. on polylines too close to each
/// other), it meshes again without them and says so in `features_dropped`. On failure or
/// cancellation, `mesh` is cleared.
template <class ConcurrencyTag, class GeomTraits, class PolygonMesh>
Mesher_report mesh_with_mesh_3(const Mesher_input<GeomTraits>& in, PolygonMesh& mesh) {
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  using Domain = MLS_mesh_domain_3<GeomTraits>;
  using Tr = typename Mesh_triangulation_3<Domain, Default, ConcurrencyTag>::type;
  using C3t3 = Mesh_complex<Tr, typename Domain::Corner_index, typename Domain::Curve_index>;
  using Criteria = Mesh_criteria_3<Tr>;
  using Point_3 = typename GeomTraits::Point_3;
  namespace params = CGAL::parameters;

  Mesher_report report;
  clear_mesh(mesh);
  const auto monitor = std::make_shared<Evaluation_monitor>();
  monitor->callback = &in.callback;
  monitor->expected = in.expected_evaluations > 0 ? in.expected_evaluations : 1e6;
  monitor->limit = in.max_evaluations;
  const auto start = std::chrono::steady_clock::now();
  // a watchdog per run of Mesh_3, under the time limit of the whole meshing
  const auto watch = [&] {
    double seconds = 0;
    if(in.max_seconds > 0)
      seconds = (std::max)(1e-9, in.max_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return std::make_unique<Meshing_watchdog>(*monitor, seconds, true);
  };
  Domain domain = Mesh_domain_access::make<Domain>(in.function, in.bounding_sphere, in.relative_error_bound, in.probes, monitor);
  // the domain with the polylines, when there are any (`domain` stays without: the fall-back)
  std::optional<Domain> featured;
  std::vector<std::vector<Point_3>> polylines;
  for(const auto& l : in.polylines)
    if(l.size() >= 2) polylines.push_back(l);
  if(!polylines.empty()) {
    featured.emplace(domain);
    featured->add_features(polylines.begin(), polylines.end());
  }
  bool has_features = featured.has_value();
  const double edge_size = in.edge_size > 0 ? in.edge_size : in.facet_size;
  Criteria criteria(params::edge_size = edge_size, params::facet_angle = in.facet_angle,
                    params::facet_size = in.facet_size, params::facet_distance = in.facet_distance);
  C3t3 c3t3;
  const auto options = params::mesh_3_options(params::pointer_to_stop_atomic_boolean = &monitor->stop);
  if(has_features) {
    // The run with polylines gets a budget of `feature_budget` times the expected evaluations
    // and vertices, and stops when it stalls (see `Meshing_watchdog`): Mesh_3's refinement
    // around a protected polyline can go on without end, evaluating little (on a plate 3
    // spacings thick, its manifold refinement kept inserting vertices for more than 5 minutes,
    // neither stalled nor over the budget of evaluations). Then the surface is meshed again
    // without them.
    const std::size_t user_limit = monitor->limit;
    const std::size_t budget = std::size_t(in.feature_budget * monitor->expected);
    const bool budgeted = in.feature_budget > 0 && (user_limit == 0 || budget < user_limit);
    if(budgeted) monitor->limit = budget;
    // measured: about 250 evaluations per vertex (see `Mesher_input::expected_evaluations`)
    const std::size_t max_vertices = in.feature_budget > 0 ? std::size_t(in.feature_budget * monitor->expected / 250) + 1 : 0;
    auto watchdog = watch();
    try {
      const auto featured_options = params::mesh_3_options(params::pointer_to_stop_atomic_boolean = &monitor->stop,
                                                           params::maximal_number_of_vertices = max_vertices);
      c3t3 = make_mesh_3<C3t3>(*featured, criteria, params::features(*featured), params::no_perturb(), params::no_exude(),
                               params::manifold(), featured_options);
      if(!monitor->stop.load() && insert_missed_initial_points(c3t3, *featured, in.facet_size) > 0)
        refine_mesh_3(c3t3, *featured, criteria, params::no_perturb(), params::no_exude(), params::no_reset_c3t3(),
                      params::manifold(), featured_options);
    } catch(const Failure_exception&) {
      report.features_dropped = true;
      has_features = false;
    }
    watchdog.reset();
    const bool too_many_vertices = max_vertices > 0 && c3t3.triangulation().number_of_vertices() >= max_vertices;
    if(((budgeted && monitor->limit_hit.load()) || monitor->stall_hit.load() || too_many_vertices) &&
       !monitor->time_hit.load()) {
      report.features_dropped = true;
      report.feature_budget_exceeded = true;
      has_features = false;
      c3t3 = C3t3();
      monitor->count.store(0);
      monitor->limit_hit.store(false);
      monitor->stall_hit.store(false);
      monitor->stop.store(false);
    }
    monitor->limit = user_limit;
  }
  if(!has_features && !monitor->stop.load()) {
    auto watchdog = watch();
    c3t3 = make_mesh_3<C3t3>(domain, criteria, params::no_features(), params::no_perturb(), params::no_exude(),
                             params::manifold(), options);
  }
  report.evaluations = monitor->count.load();
  if(monitor->stop.load()) return stopped(*monitor, report);
  facets_in_complex_3_to_triangle_mesh(c3t3, mesh);
  return finished(mesh, report);
}

/// Meshes the surface \f$f = 0\f$ with Surface_mesher (`make_surface_mesh` on an
/// `Implicit_surface_3` whose sphere is centred at the inner point and encloses the bounding
/// sphere, `Surface_mesh_default_criteria_3` with the facet angle, size (Delaunay-ball radius)
/// and distance, `Manifold_tag`), written to `mesh` with `facets_in_complex_2_to_triangle_mesh`.
/// Sequential; no feature protection; the initial points come from rays from the inner point, so
/// a surface made of several components may lose some. On failure or cancellation, `mesh` is
/// cleared.
template <class GeomTraits, class PolygonMesh>
Mesher_report mesh_with_surface_mesher(const Mesher_input<GeomTraits>& in, PolygonMesh& mesh) {
  using STr = Surface_mesh_default_triangulation_3;
  using C2t3 = Surface_mesh_complex_2_in_triangulation_3<STr>;
  using SGT = STr::Geom_traits;
  using Function = Monitored_function<GeomTraits, typename SGT::Point_3>;
  using Surface = Implicit_surface_3<SGT, Function>;

  Mesher_report report;
  clear_mesh(mesh);
  const auto monitor = std::make_shared<Evaluation_monitor>();
  monitor->callback = &in.callback;
  monitor->expected = in.expected_evaluations > 0 ? in.expected_evaluations : 1e6;
  monitor->limit = in.max_evaluations;
  std::optional<Meshing_watchdog> watchdog(std::in_place, *monitor, in.max_seconds, false);
  monitor->throw_on_stop = true;
  const Function function{std::make_shared<const std::function<double(const typename GeomTraits::Point_3&)>>(in.function), monitor};

  const auto& c = in.bounding_sphere.center();
  const typename SGT::Point_3 inner(CGAL::to_double(in.inner_point.x()), CGAL::to_double(in.inner_point.y()),
                                    CGAL::to_double(in.inner_point.z()));
  const typename SGT::Point_3 centre(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
  const double radius = std::sqrt(CGAL::to_double(in.bounding_sphere.squared_radius())) +
                        std::sqrt(CGAL::squared_distance(inner, centre));
  const double error = in.relative_error_bound;
  try {
    STr tr;
    C2t3 c2t3(tr);
    Surface surface(function, typename SGT::Sphere_3(inner, radius * radius), error);
    Surface_mesh_default_criteria_3<STr> criteria(in.facet_angle, in.facet_size, in.facet_distance);
    make_surface_mesh(c2t3, surface, criteria, Manifold_tag());
    watchdog.reset();
    report.evaluations = monitor->count.load();
    facets_in_complex_2_to_triangle_mesh(c2t3, mesh);
  } catch(const Meshing_cancelled&) {
    watchdog.reset();
    clear_mesh(mesh);
    report.evaluations = monitor->count.load();
    return stopped(*monitor, report);
  }
  return finished(mesh, report);
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_MESHER_CALLS_H
