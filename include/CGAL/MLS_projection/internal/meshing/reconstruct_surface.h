// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_RECONSTRUCT_SURFACE_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_RECONSTRUCT_SURFACE_H

#include <CGAL/MLS_projection/Implicit_function_options.h>
#include <CGAL/MLS_projection/MLS_implicit_function.h>
#include <CGAL/MLS_projection/Meshing_report.h>
#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/detect_sharp_features.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/internal/projection/Levin_screened_projection.h>
#include <CGAL/MLS_projection/internal/meshing/mesh_attributes.h>
#include <CGAL/MLS_projection/internal/meshing/mesher_calls.h>
#include <CGAL/MLS_projection/internal/projection/operator_from_tag.h>
#include <CGAL/MLS_projection/internal/meshing/open_surface.h>
#include <CGAL/MLS_projection/internal/meshing/oriented_normals.h>
#include <CGAL/MLS_projection/internal/meshing/outlier_points.h>
#include <CGAL/MLS_projection/internal/meshing/protected_polylines.h>
#include <CGAL/MLS_projection/internal/meshing/surface_function.h>
#include <CGAL/MLS_projection/internal/meshing/unsupported_components.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The settings of `mls_surface_reconstruction()`: its named parameters, and the constants that
/// the tests can change.
struct Reconstruction_settings {
  Mesher mesher = Mesher::MESH_3;
  bool parallel_mesher = false;
  bool remove_outliers = true;
  bool features = true;
  bool open_surface = false;
  /// 0: 2 average spacings.
  double facet_size = 0;
  /// 0: a quarter of the average spacing.
  double facet_distance = 0;
  /// The bandwidth \f$h\f$; 0: derived from the data (`Projection_options::bandwidth`).
  double bandwidth = 0;
  /// 0: no limit.
  double max_meshing_seconds = 0;
  Meshing_report* report = nullptr;
  /// Mesh_3's edge size along the feature polylines; 0: 0.75 facet sizes (with larger protecting
  /// balls, Mesh_3's manifold refinement next to close polylines can loop without end).
  double edge_size = 0;
  /// Degrees; at most 30 for the meshers to terminate.
  double facet_angle = 25;
  /// The evaluations of the function after which the mesher is stopped and the reconstruction
  /// fails: a bound on a refinement that keeps evaluating without end. 0: 100 times the expected
  /// number \f$250\,n\,(s/\mathrm{size})^2\f$ for \f$n\f$ points of average spacing \f$s\f$, at
  /// least \f$10^6\f$ (a 50000-point scan of a CAD part used 0.6 times the expected number).
  std::size_t max_evaluations = 0;
  /// Mesh_3 with the feature polylines is stopped after this many times the expected number of
  /// evaluations or of vertices (\f$n\,(s/\mathrm{size})^2\f$), or as soon as it stalls, and the
  /// surface is meshed again without them: its manifold refinement next to a protected polyline
  /// can loop without end. 0: no budget (the stall is still detected).
  double feature_evaluation_budget = 4;
  Implicit_function_options implicit_function;
};

/// The reconstruction of `items` (points with their normals when `has_normals`, otherwise with
/// any vector; all finite) with `channels` attribute values per item in `attributes`, into `mesh`,
/// with the settings `s` and the operator selected by `tag`. Fills `out`; on success with
/// `vertex_attributes`, the vertices' attributes, in the order of `vertices(mesh)`. Independent of
/// the caller's named parameters, it is compiled once per operator, kernel, mesh and concurrency tag.
template <class ConcurrencyTag, class GeomTraits, class PolygonMesh, class OperatorTag>
bool reconstruct_items(std::vector<std::pair<typename GeomTraits::Point_3, typename GeomTraits::Vector_3>>& items,
                       bool has_normals, std::vector<double>& attributes, std::size_t channels, PolygonMesh& mesh,
                       const Reconstruction_settings& s, OperatorTag tag, const std::function<bool(double)>& callback,
                       Meshing_report& out, std::vector<std::vector<double>>* vertex_attributes) {
  using K = GeomTraits;
  using Point_3 = typename K::Point_3;
  using Vector_3 = typename K::Vector_3;
  using Samples = Sample_set<K, 3>;
  using Item = std::pair<Point_3, Vector_3>;
  const auto fail = [&](const char* why) {
    clear_mesh(mesh);
    out.failure = why;
    return false;
  };
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  // the stages' slices [begin, end) of the overall fraction (see `meshing_stage()`)
  const auto report = [&](Meshing_stage_index i, double f) {
    const Meshing_stage& stage = meshing_stages[i];
    return !callback || callback(stage.begin + (stage.end - stage.begin) * std::clamp(f, 0., 1.));
  };
  const auto slice = [&](Meshing_stage_index i) {
    return std::function<bool(double)>([=, &report](double f) { return report(i, f); });
  };
  if(s.open_surface && s.mesher != Mesher::MESH_3)
    return fail("an open surface is meshed with Mesh_3 only");

  // 1. the outliers removed, oriented normals when none is given
  if(s.remove_outliers) {
    std::vector<Vec<3>> coordinates(items.size());
    for(std::size_t i = 0; i < items.size(); ++i)
      coordinates[i] = Vec<3>(CGAL::to_double(items[i].first.x()), CGAL::to_double(items[i].first.y()),
                                        CGAL::to_double(items[i].first.z()));
    const std::vector<bool> outlier = outlier_points<ConcurrencyTag>(coordinates);
    std::size_t kept = 0;
    for(std::size_t i = 0; i < items.size(); ++i) {
      if(outlier[i]) continue;
      items[kept] = items[i];
      std::copy_n(attributes.begin() + i * channels, channels, attributes.begin() + kept * channels);
      ++kept;
    }
    out.outliers = items.size() - kept;
    items.resize(kept);
    attributes.resize(kept * channels);
  }
  out.points = items.size();
  if(items.size() < 10) return fail("too few points");
  const double spacing = CGAL::to_double(CGAL::compute_average_spacing<Sequential_tag>(
    items, 6, parameters::point_map(First_of_pair_property_map<Item>()).geom_traits(K())));
  out.average_spacing = spacing;
  if(!(spacing > 0) || !std::isfinite(spacing)) return fail("no spacing (all points equal)");
  // Estimates the oriented normals when none is given: the orientation's spanning forest split by
  // the votes of the free space (`split_by_votes`), or one tree turned by their sum.
  const auto orient_normals = [&](bool split_by_votes) {
    const auto t_normals = Clock::now();
    if(has_normals) return true;
    std::vector<Point_3> pts(items.size());
    std::vector<Vector_3> normals;
    for(std::size_t i = 0; i < items.size(); ++i) pts[i] = items[i].first;
    if(!report(NORMALS_STAGE, 0.)) return false;
    const auto r = estimate_oriented_normals<ConcurrencyTag, K>(pts, normals, normal_neighbors, slice(NORMALS_STAGE),
                                                                split_by_votes);
    if(!r.completed || normals.size() != items.size()) return false;
    for(std::size_t i = 0; i < items.size(); ++i) items[i].second = normals[i];
    out.normals_by_fallback = r.oriented_by_fallback;
    out.seconds_normals += since(t_normals);
    return true;
  };
  // the sample set reads the items by index (the attributes are stored apart)
  std::vector<std::size_t> indices(items.size());
  for(std::size_t i = 0; i < items.size(); ++i) indices[i] = i;
  const auto attribute_of = [&](std::size_t i) {
    return Attribute_span{attributes.data() + i * channels, attributes.data() + (i + 1) * channels};
  };
  const auto make_samples = [&] {
    return std::make_shared<const Samples>(
      indices, MLS::parameters::attribute_map(boost::make_function_property_map<std::size_t>(attribute_of))
                 .point_map(boost::make_function_property_map<std::size_t>([&](std::size_t i) { return items[i].first; }))
                 .normal_map(boost::make_function_property_map<std::size_t>([&](std::size_t i) { return items[i].second; })));
  };
  std::shared_ptr<const Samples> samples;
  Projection_options projection_options;
  projection_options.bandwidth = s.bandwidth;
  projection_options.one_sided = true;
  // Open scans: the surface is kept within `margin` of the data. The slab is 2 facet sizes deep
  // (Mesh_3 refines thinner sheets at length) and reaches a facet size beyond the margin, so
  // that its wall's facets are cut away whole, and a spacing beyond its depth, so that the data
  // do not pierce it.
  const double facet_size = s.facet_size > 0 ? s.facet_size : 2. * spacing, margin = 2. * spacing;
  const double depth = 2. * facet_size;
  const Open_surface_slab slab{depth, (std::max)(margin + facet_size, depth + spacing)};

  bool not_closed = false; // set by run(): the surface is not closed
  const auto run = [&](const auto& projection) -> bool {
    using Projection = std::decay_t<decltype(projection)>;
    using Function = MLS_implicit_function<Projection>;
    // 2. the implicit function (the seeds are projected once)
    const auto t_seeds = Clock::now();
    if(!report(SEEDS_STAGE, 0.)) return fail("cancelled");
    // In an open scan's slab, f is the blend of the local fits (continuous), not the far value,
    // whose sign comes from votes that change abruptly beyond the scan's border.
    Implicit_function_options function_options = s.implicit_function;
    if(s.open_surface) function_options.complete_gaps = false;
    if(s.open_surface && projection.bandwidth() > 0) {
      function_options.far_start = (std::max)(function_options.far_start, slab.reach / projection.bandwidth() + 1.);
      function_options.far_end = (std::max)(function_options.far_end, function_options.far_start + 1.);
    }
    const Function function(projection, function_options, ConcurrencyTag(), slice(SEEDS_STAGE));
    out.seconds_seeds = since(t_seeds);
    out.bandwidth = function.bandwidth();
    out.seeds = function.number_of_seeds();
    out.operator_seeds = function.number_of_operator_seeds();
    out.unblended_seeds = function.number_of_unblended_seeds();
    out.failed_seeds = function.number_of_failed_seeds();
    out.levin_fallback_seeds = function.number_of_levin_fallbacks();
    out.gap_seeds = function.number_of_gap_seeds();
    if(function.status() == Function::Status::CANCELLED) return fail("cancelled");
    if(!function.is_valid()) return fail("no implicit function (too few seeds could be projected: degenerate data)");
    if(!s.open_surface)
      if(const char* why = closed_surface_failure(function)) {
        not_closed = true;
        return fail(why);
      }
    const double h = function.bandwidth();
    // 3. sharp features
    const auto t_features = Clock::now();
    if(!report(FEATURES_STAGE, 0.)) return fail("cancelled");
    std::size_t corners = 0;
    std::vector<std::vector<Point_3>> polylines;
    if(s.features && s.mesher == Mesher::MESH_3)
      polylines = feature_polylines<ConcurrencyTag>(function, corners, out.feature_queries);
    const double facet_distance = s.facet_distance > 0 ? s.facet_distance : 0.25 * spacing;
    out.off_surface_polylines = drop_polylines_off_surface(polylines, function, facet_distance);
    // the distance to the nearest input point
    const auto data_distance = [samples](const Point_3& p) { return samples->kth_neighbor_distance(samples->to_local(p), 1); };
    if(s.open_surface) cut_polylines(polylines, [&](const Point_3& p) { return data_distance(p) <= margin; });
    fit_polylines_to_surface(polylines, function, facet_distance, 1e-4 * facet_distance);
    out.feature_polylines = polylines.size();
    out.corners = corners;
    out.seconds_features = since(t_features);
    if(!report(FEATURES_STAGE, 1.)) return fail("cancelled");
    // 4. meshing, in Epick whatever K: CGAL's meshers need exact predicates (Mesh_3's protection
    // of the polylines crashed with Simple_cartesian<double>)
    using Mesher_point = Epick::Point_3;
    Mesher_input<Epick> in;
    const auto sphere = function.bounding_sphere();
    in.bounding_sphere = Epick::Sphere_3(point_as<Mesher_point>(sphere.center()), CGAL::to_double(sphere.squared_radius()));
    // For an open scan, the slab, without evaluating f where its function is positive whatever f is.
    if(s.open_surface)
      in.function = [function, data_distance, slab, centre = sphere.center(),
                     radius = std::sqrt(CGAL::to_double(sphere.squared_radius()))](const Mesher_point& q) {
        const Point_3 p = point_as<Point_3>(q);
        const double outside = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, centre))) - radius;
        if(outside > 0) return outside;
        const double d = data_distance(p);
        if(d > slab.reach) return d - slab.reach;
        return (std::max)(slab.value(CGAL::to_double(function(p)), d), outside);
      };
    else
      in.function = clamped_to_sphere<Mesher_point>(function);
    const auto& seeds = function.projected_seeds();
    // for the slab, half a spacing under a seed (a thin part may be thinner than the slab is deep)
    in.inner_point = point_as<Mesher_point>(s.open_surface && !seeds.empty()
                                              ? seeds[0].point - seeds[0].normal * (0.5 * spacing)
                                              : function.get_inner_point());
    if(!(in.function(in.inner_point) < 0)) return fail("the implicit function has no inside");
    // from inside to outside across the surface (for the slab, from its middle), and across the
    // slab's back: the points on a flat scan alone are coplanar, and Mesh_3 finds no cell to refine
    // in their triangulation
    in.probes = s.open_surface ? surface_probes<Mesher_point>(seeds, 0.5 * slab.depth, h, 1.5 * slab.depth)
                               : surface_probes<Mesher_point>(seeds, h, h);
    for(const auto& line : polylines) {
      in.polylines.emplace_back();
      for(const Point_3& p : line) in.polylines.back().push_back(point_as<Mesher_point>(p));
    }
    in.facet_size = facet_size;
    in.facet_distance = facet_distance;
    in.edge_size = s.edge_size > 0 ? s.edge_size : 0.75 * in.facet_size;
    in.facet_angle = s.facet_angle;
    // the pace of the meshing progress: measured, 126000 evaluations (537 vertices) for 2000
    // samples of a sphere with the default size 2s: 250 n (s / size)^2
    const double ratio = spacing / in.facet_size;
    in.expected_evaluations = (std::max)(1e4, 250. * double(items.size()) * ratio * ratio);
    in.max_evaluations = s.max_evaluations > 0
                           ? s.max_evaluations
                           : std::size_t((std::max)(1e6, 100. * in.expected_evaluations));
    out.max_evaluations = in.max_evaluations;
    in.max_seconds = s.max_meshing_seconds;
    in.feature_budget = s.feature_evaluation_budget;
    in.callback = slice(MESHING_STAGE);
    out.facet_size = in.facet_size;
    out.facet_distance = in.facet_distance;
    const auto t_meshing = Clock::now();
    if(!report(MESHING_STAGE, 0.)) return fail("cancelled");
    Mesher_report r;
    // Mesh_3's parallel refinement is not deterministic (the order of the insertions follows
    // the threads' scheduling): opt-in only.
    if(s.mesher == Mesher::MESH_3 && s.parallel_mesher)
      r = mesh_with_mesh_3<ConcurrencyTag>(in, mesh);
    else if(s.mesher == Mesher::MESH_3)
      r = mesh_with_mesh_3<Sequential_tag>(in, mesh);
    else
      r = mesh_with_surface_mesher(in, mesh);
    out.seconds_meshing = since(t_meshing);
    out.evaluations = r.evaluations;
    out.features_dropped = r.features_dropped;
    out.feature_budget_exceeded = r.feature_budget_exceeded;
    if(!r.success) return fail(r.cancelled ? "cancelled" : r.message);
    const auto to_point = [](const auto& q) { return Point_3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())); };
    if(s.open_surface) {
      // the facets on the surface (not on the back), clipped where the distance to the data is
      // `margin`, the new vertices on the surface
      const auto vpm = get(CGAL::vertex_point, mesh);
      const auto on_surface = [&](const auto f) {
        const auto h0 = halfedge(f, mesh);
        const Point_3 c = CGAL::centroid(to_point(get(vpm, source(h0, mesh))), to_point(get(vpm, target(h0, mesh))),
                                         to_point(get(vpm, target(next(h0, mesh), mesh))));
        return slab.on_surface(CGAL::to_double(function(c)));
      };
      const auto level = [&](const auto& q) { return data_distance(to_point(q)) - margin; };
      const auto place = [&](const auto& q) {
        const Point_3 p = snap_to_surface(to_point(q), function, 1e-3 * facet_distance, 1e-4 * facet_distance);
        return typename std::decay_t<decltype(q)>(p.x(), p.y(), p.z());
      };
      if(clip_mesh(mesh, on_surface, level, place, 0.1 * spacing) == 0)
        return fail("empty mesh (no facet on the surface within reach of the data)");
    }
    out.removed_components = remove_unsupported_components(
      mesh, [&](const auto& q) { return data_distance(to_point(q)); }, 0.5 * h, in.facet_size);
    if(s.open_surface) {
      std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> cycles;
      Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
      out.boundary_cycles = cycles.size();
    }
    if(vertex_attributes)
      *vertex_attributes = interpolate_vertex_attributes<ConcurrencyTag>(function.seed_projection(),
                                                                         function.projected_seeds(), mesh);
    if(!report(OUTPUT_STAGE, 1.)) return fail("cancelled");
    return true;
  };

  if(!orient_normals(!s.open_surface)) return fail("cancelled");
  samples = make_samples();
  if(run(make_operator<K>(tag, samples, projection_options))) return true;
  // Estimated normals that leave the surface open: the votes may have split the forest into trees
  // turned opposite ways (the walls of bores a few spacings wide, which the votes' wall seals on a
  // sparse scan). Oriented again as one tree, turned outward by the sum of the votes.
  if(!not_closed || has_normals || s.open_surface) return false;
  not_closed = false;
  out.failure = "";
  out.normals_as_one_tree = true;
  if(!orient_normals(false)) return fail("cancelled");
  samples = make_samples();
  return run(make_operator<K>(tag, samples, projection_options));
}

/// `mls_surface_reconstruction()` with the settings `s` and the operator selected by `tag`; `np`:
/// the maps and the callback.
template <class ConcurrencyTag, class PointRange, class PolygonMesh, class OperatorTag, class NamedParameters>
bool reconstruct_surface(const PointRange& points, PolygonMesh& mesh, const Reconstruction_settings& s, OperatorTag tag,
                         const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using NP_helper = Point_set_processing_3_np_helper<PointRange, NamedParameters>;
  using K = typename NP_helper::Geom_traits;
  using Point_3 = typename K::Point_3;
  using Vector_3 = typename K::Vector_3;
  constexpr bool has_normals = !parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value;
  constexpr bool has_attributes =
    !parameters::is_default_parameter<NamedParameters, internal_np::mls_attribute_map_t>::value &&
    !parameters::is_default_parameter<NamedParameters, internal_np::mls_vertex_attribute_map_t>::value;

  clear_mesh(mesh);
  Meshing_report local_report;
  Meshing_report& out = s.report ? *s.report : local_report;
  out = Meshing_report();
  // the finite points, with their normals and attributes
  const auto point_map = NP_helper::get_const_point_map(points, np);
  std::vector<std::pair<Point_3, Vector_3>> items;
  std::vector<double> attributes; // `channels` per item
  std::size_t channels = 0;
  for(const auto& v : points) {
    const Point_3 p = get(point_map, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      continue;
    Vector_3 n(0, 0, 0);
    if constexpr(has_normals) n = get(get_parameter(np, internal_np::normal_map), v);
    items.emplace_back(p, n);
    if constexpr(has_attributes) {
      const auto& values = get(get_parameter(np, internal_np::mls_attribute_map), v);
      const std::size_t before = attributes.size();
      for(const auto& a : values) attributes.push_back(static_cast<double>(a));
      if(items.size() == 1) channels = attributes.size();
      if(attributes.size() - before != channels) {
        out.failure = "the attribute values do not all have the same number of channels";
        return false;
      }
    }
  }
  std::vector<std::vector<double>> vertex_attributes;
  if(!reconstruct_items<ConcurrencyTag, K>(
       items, has_normals, attributes, channels, mesh, s, tag,
       choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>()), out,
       has_attributes ? &vertex_attributes : nullptr))
    return false;
  if constexpr(has_attributes) {
    if(vertex_attributes.empty()) return true; // no channel
    const auto map = get_parameter(np, internal_np::mls_vertex_attribute_map);
    std::size_t i = 0;
    for(const auto v : vertices(mesh)) put(map, v, std::move(vertex_attributes[i++]));
  }
  return true;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_RECONSTRUCT_SURFACE_H
