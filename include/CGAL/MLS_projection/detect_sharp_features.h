// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_DETECT_SHARP_FEATURES_H
#define CGAL_MLS_PROJECTION_DETECT_SHARP_FEATURES_H

#include <CGAL/MLS_projection/Projection_result.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/internal/features/polyline_chaining.h>
#include <CGAL/MLS_projection/project_points.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctions
/// The sharp features found by `detect_sharp_features()`, in the form Mesh_3's
/// `Mesh_domain_with_polyline_features_3::add_features()` expects.
template <class GeomTraits>
struct Sharp_features {
  using Point_3 = typename GeomTraits::Point_3; ///< the kernel's point type
  /// The creases, each an ordered list of points on it. A polyline ending at a corner ends at
  /// exactly the point listed in `corners` (the same coordinates in every polyline meeting
  /// there); a closed crease repeats its first point at its end.
  std::vector<std::vector<Point_3>> polylines;
  /// The corners: apices of the local fits where at least two polyline ends meet.
  std::vector<Point_3> corners;

  /// What the detection did, for diagnostics.
  struct Statistics {
    std::size_t crease_samples = 0; ///< projected samples on a crease or apex
    std::size_t helper_queries = 0; ///< helper points projected
    std::size_t helper_hits = 0;    ///< helper projections that landed on a crease or apex
    std::size_t crease_nodes = 0;   ///< crease clusters (graph vertices besides the corners)
    std::size_t junction_corners = 0; ///< corners found where three branches or more meet, not at an apex point
    std::size_t dropped_polylines = 0; ///< polylines dropped as too short
    std::size_t too_close_polylines = 0; ///< polylines dropped as too close to a longer one (`minimum_separation`)
    std::size_t relaxation_queries = 0; ///< polyline vertices projected back onto the crease
    std::size_t relaxed = 0;        ///< of which landed on a crease and were moved
  } statistics; ///< what the detection did
};

namespace internal {

/// The constants of `detect_sharp_features()`, two of which are its named parameters
/// (`neighbor_radius`, `sharpness_angle`). Lengths are in units of the bandwidth \f$h\f$ of the
/// projection (`neighbor_radius` overrides it), angles in degrees. The user manual's section
/// "Sharp Features" explains each step they control.
struct Feature_settings {
  /// The length unit \f$h\f$; 0 (default): the projection's `bandwidth()`.
  double bandwidth = 0;
  /// Crease points closer than this (and with directions within `link_angle`) are merged
  /// into one graph node; apex points within `corner_radius` into one corner.
  double cluster_spacing = 0.25;
  /// Crease and apex points further than this from every input sample are ignored: past the
  /// end of the data (the border of a scan, a crease running off it), a fit extrapolates its
  /// crease. The default exceeds the largest distance from the surface to the nearest sample
  /// (about \f$0.3h\f$ with the default bandwidth, \f$h \approx 2.2\f$ times the spacing).
  double support_radius = 0.75;
  /// Whether helper points are projected near the creases of the samples' local fits (needs a
  /// projection whose sharp function space is `Wedge_fan_function_space<3, N>`: the unified
  /// operator with the fan, or `Mixed_projection`).
  bool use_helper_points = true;
  /// A crease (or apex) of a sample's fan fit yields a helper point when it lies within this
  /// distance of the sample's projection.
  double helper_radius = 2.0;
  /// The helper points of a round are thinned to one per ball of this radius, and skipped within
  /// it of a crease point already found.
  double helper_spacing = 0.5;
  /// Helper points are moved this far off the fit's crease, to its reflex side: into the ball
  /// that the projection collapses onto the crease (the paper's Figure 4), so that a helper
  /// still lands on the crease when the helper's own fit puts the crease slightly elsewhere.
  double helper_offset = 0.2;
  /// The helper points are placed in rounds: first near the creases of the samples' fits, then
  /// near those of the helpers of the previous round that landed on a crease, one step
  /// (`2 * helper_spacing`) further along it; at most this many rounds.
  int max_helper_rounds = 50;
  /// Two faces of a fan fit make a crease for the helper points when their normals differ by at
  /// least this angle (degrees): smaller folds are the fan fitting noise on a flat region.
  double minimum_crease_angle = 20.;
  /// The largest length of a link between two crease nodes.
  double link_radius = 1.5;
  /// A second linking pass joins the free ends of two branches up to this distance apart (the
  /// same angle conditions): it closes the gaps where helper points missed the crease.
  double gap_radius = 3.0;
  /// Two crease nodes are linked only if their directions agree within this angle (degrees) and
  /// the link is within this angle of the crease direction.
  double link_angle = 30.;
  /// Apex points within this distance are one corner; crease nodes within it of a corner are
  /// dropped (the corner stands for them).
  double corner_radius = 1.0;
  /// The end of a branch is linked to a corner within this distance, if it points at it.
  double corner_link_radius = 2.5;
  /// The polylines are resampled at about this spacing before their relaxation.
  double resampling_spacing = 0.5;
  /// A resampled vertex is moved to its projection when that lands on a crease within this
  /// distance; otherwise it stays where the resampling put it.
  double relaxation_tolerance = 0.5;
  /// Polylines shorter than this are dropped, unless both their ends are corners.
  double minimum_polyline_length = 2.0;
  /// Two polylines may come no closer than this to each other, away from the corners where both
  /// end: otherwise the shorter one is dropped. Mesh_3 protects each polyline with balls that
  /// must not overlap the balls of another one, and fails ("already inserted on surface") on
  /// polylines nearly touching, e.g. two fragments of a strongly curved crease found side by side.
  double minimum_separation = 0.5;
};

template <class Space> struct is_wedge_fan_3 : std::false_type {};
template <int N> struct is_wedge_fan_3<Wedge_fan_function_space<3, N>> : std::true_type {
  static constexpr int number_of_vectors = N;
};

// The sharp function space of a projection: `Sharp_projection::Function_space` (Mixed_projection),
// else `Function_space` (Closest_point_projection), else void.
template <class P, class = void> struct projection_function_space { using type = void; };
template <class P> struct projection_function_space<P, std::void_t<typename P::Function_space>> {
  using type = typename P::Function_space;
};
template <class P, class = void> struct sharp_function_space : projection_function_space<P> {};
template <class P> struct sharp_function_space<P, std::void_t<typename P::Sharp_projection>> {
  using type = typename P::Sharp_projection::Function_space;
};

// The creases (and apex) of the wedge fan of a projection result, in world coordinates.
struct Fan_creases {
  Feature_vec apex;
  std::vector<Feature_vec> directions; // unit rays from the apex
  std::vector<Feature_vec> reflex;     // unit direction from each ray into its collapse region
};

// Decodes the fan of `coefficients` (Wedge_fan_function_space<3, N>: latitude, longitude per
// vector) in `frame`, and keeps the rays whose two adjacent cones' normals differ by at least
// `min_angle` (radians).
template <int N, class GeomTraits>
bool fan_creases(const Projection_result<GeomTraits, 3>& r, double min_angle, Fan_creases& out) {
  using KT = Kernel_types<GeomTraits, 3>;
  if(r.fit_kind != Local_fit_kind::CLOSEST_POINT || r.coefficients.size() != std::size_t(2 * N)) return false;
  const Feature_vec t0 = KT::to_eigen(r.frame.tangents[0]), t1 = KT::to_eigen(r.frame.tangents[1]),
                    nz = KT::to_eigen(r.frame.normal);
  if(!(nz.squaredNorm() > 0.5)) return false;
  std::array<double, N> lon;
  std::array<int, N> order;
  for(int i = 0; i < N; ++i) {
    double t = r.coefficients[2 * i + 1];
    t -= 2. * CGAL_PI * std::floor(t / (2. * CGAL_PI));
    if(t >= 2. * CGAL_PI) t -= 2. * CGAL_PI;
    lon[i] = t;
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lon[a] < lon[b]; });
  std::array<Feature_vec, N> v, fn;
  std::array<bool, N> ok;
  for(int j = 0; j < N; ++j) {
    const double la = r.coefficients[2 * order[j]], lo = r.coefficients[2 * order[j] + 1];
    v[j] = Feature_vec(std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la));
  }
  for(int j = 0; j < N; ++j) {
    const int k = (j + 1) % N;
    double gap = lon[order[k]] - lon[order[j]];
    if(k == 0) gap += 2. * CGAL_PI;
    const Feature_vec n = v[j].cross(v[k]);
    ok[j] = n.norm() > 1e-9;
    fn[j] = ok[j] ? Feature_vec((gap > CGAL_PI ? -1. : 1.) * n.normalized()) : Feature_vec::Zero();
  }
  const auto to_world = [&](const Feature_vec& a) { return Feature_vec(a[0] * t0 + a[1] * t1 + a[2] * nz); };
  out.apex = KT::to_eigen(r.frame.origin);
  out.directions.clear();
  out.reflex.clear();
  const double cos_min = std::cos(min_angle);
  for(int k = 0; k < N; ++k) {
    const int a = (k + N - 1) % N, b = (k + 1) % N; // cones (a, k) and (k, b)
    if(!ok[a] || !ok[k] || fn[a].dot(fn[k]) > cos_min) continue;
    // in-face directions perpendicular to the ray, into each adjacent cone
    Feature_vec ua = v[a] - v[a].dot(v[k]) * v[k], ub = v[b] - v[b].dot(v[k]) * v[k];
    if(!(ua.norm() > 1e-6) || !(ub.norm() > 1e-6)) continue;
    const Feature_vec reflex = -(ua.normalized() + ub.normalized());
    out.directions.push_back(to_world(v[k]).normalized());
    out.reflex.push_back(reflex.norm() > 1e-6 ? Feature_vec(to_world(reflex).normalized()) : Feature_vec::Zero());
  }
  return !out.directions.empty();
}

} // namespace internal

/// \ingroup PkgMLSProjectionFunctions
/// Finds the sharp creases and corners of the MLS surface of `projection` as polylines and
/// points, ready for Mesh_3's `add_features()`.
///
/// The algorithm (user manual, section "Sharp Features", which gives the constants named here):
/// 1. the projected samples on a crease (`is_on_feature` with a direction) or an apex (a null
///    direction) are collected;
/// 2. near the creases and apices of the samples' wedge-fan fits, helper points are placed
///    (moved by `helper_offset` into the ball the projection collapses onto the crease),
///    thinned, projected, and those landing on a crease or apex are collected too;
/// 3. crease points are clustered (`cluster_spacing`), apex points into corners (`corner_radius`);
/// 4. crease nodes are linked to their nearest node on each side along their direction (mutual
///    choices only, within `link_radius` and `link_angle`), branch ends to nearby corners;
/// 5. the graph is split into polylines at the corners and at the vertices of degree other than
///    2 (`CGAL::split_graph_into_polylines()`), short polylines are dropped;
/// 6. each polyline is resampled at `resampling_spacing` and every vertex but the corners is
///    projected again and moved to its projection when that lies on a crease.
///
/// Only the crease information of the results is used: with a projection that finds no
/// features (a smooth function space), the result is empty. The result is deterministic and
/// does not depend on `ConcurrencyTag` or on the number of threads (the projections are).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: how the helper and relaxation points are projected
/// \tparam Projection a 3D operator of this package (`Unified_projection` with
///         `Wedge_fan_function_space<3>`, `Mixed_projection<K, 3>`, ...)
/// \param projection the operator whose MLS surface is analysed
/// \param projected_samples the projections by `projection` of the input samples, or of a
///        subsample of them (order matters for ties only, never for validity)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{neighbor_radius}
///     \cgalParamDescription{the length unit \f$h\f$ of the detection's radii and spacings (see
///       the manual)}
///     \cgalParamDefault{the projection's `bandwidth()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sharpness_angle}
///     \cgalParamDescription{the smallest angle, in degrees, between the normals of two faces of a
///       fan fit that makes a crease for the helper points (below it, the fan fits a fold into
///       noise on a flat region)}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class ConcurrencyTag, class Projection, class GeomTraits,
          class NamedParameters = parameters::Default_named_parameters>
Sharp_features<GeomTraits> detect_sharp_features(const Projection& projection,
                                                 const std::vector<Projection_result<GeomTraits, 3>>& projected_samples,
                                                 const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::Feature_settings options;
  options.bandwidth = choose_parameter(get_parameter(np, internal_np::neighbor_radius), options.bandwidth);
  options.minimum_crease_angle =
    choose_parameter(get_parameter(np, internal_np::sharpness_angle), options.minimum_crease_angle);
  using KT = internal::Kernel_types<GeomTraits, 3>;
  using V = internal::Feature_vec;
  using Point = typename GeomTraits::Point_3;
  using Result = Projection_result<GeomTraits, 3>;
  using Space = typename internal::sharp_function_space<Projection>::type;

  Sharp_features<GeomTraits> out;
  const double h = options.bandwidth > 0 ? options.bandwidth : double(projection.bandwidth());
  if(projected_samples.empty() || !(h > 0) || !std::isfinite(h)) return out;
  const double deg = CGAL_PI / 180.;
  const double cos_link = std::cos(options.link_angle * deg);
  const double support = options.support_radius * h;

  std::vector<internal::Crease_point> creases;
  std::vector<V> apices;
  const auto collect = [&](const Result& r) {
    if(!r.is_success() || !r.is_on_feature) return false;
    const V p = KT::to_eigen(r.point), d = KT::to_eigen(r.feature_direction);
    if(!p.allFinite() || !d.allFinite()) return false;
    // a crease extrapolated beyond the end of the data is not a feature of the data
    if(!(projection.samples().kth_neighbor_distance(projection.samples().to_local(r.point), 1) <= support)) return false;
    if(d.norm() > 0.5) creases.push_back({p, d.normalized()});
    else apices.push_back(p);
    return true;
  };

  // 1. crease and apex points among the projected samples
  for(const Result& r : projected_samples) out.statistics.crease_samples += collect(r);

  // 2. helper points near the creases of the fan fits
  if constexpr(internal::is_wedge_fan_3<Space>::value) {
    if(options.use_helper_points) {
      constexpr int N = internal::is_wedge_fan_3<Space>::number_of_vectors;
      const double radius = options.helper_radius * h, spacing = options.helper_spacing * h,
                   offset = options.helper_offset * h;
      // Helpers are skipped near the crease points known and near the helpers of the same
      // round, not near the helpers of earlier rounds that missed the crease: on noisy data, a
      // few per cent of the queries near a crease end in a fit whose C(r) lies off its crease
      // (the fan fits the noise; a lower energy), and such a miss must not stop the tracing.
      internal::Point_grid taken(spacing);
      for(const auto& c : creases) taken.add(c.point);
      for(const V& a : apices) taken.add(a);
      internal::Point_grid proposed(spacing);
      std::vector<Point> helpers;
      std::vector<std::size_t> near;
      const auto propose = [&](const V& x) {
        if(!x.allFinite()) return;
        taken.near(x, spacing, near);
        if(!near.empty()) return;
        proposed.near(x, spacing, near);
        if(!near.empty()) return;
        proposed.add(x);
        helpers.push_back(KT::to_point(x));
      };
      // apex helpers are thinned among themselves only: a corner must not be hidden by the
      // crease helpers around it
      internal::Point_grid taken_apex(spacing);
      for(const V& a : apices) taken_apex.add(a);
      const auto propose_apex = [&](const V& x) {
        if(!x.allFinite()) return;
        taken_apex.near(x, spacing, near);
        if(!near.empty()) return;
        taken_apex.add(x);
        helpers.push_back(KT::to_point(x));
      };
      // Round 0 looks at the fits of the samples; each later round at the fits of the helpers
      // of the previous round that landed on a feature (tracing the creases), until no new
      // helper point is proposed or `max_helper_rounds` is reached.
      const double step = 2. * spacing;
      internal::Fan_creases fan;
      const auto propose_from = [&](const Result& r) {
        if(!r.is_success() || !internal::fan_creases<N>(r, options.minimum_crease_angle * deg, fan)) return;
        const V p = KT::to_eigen(r.point);
        // an apex where creases in two non-opposite directions meet: a corner candidate
        bool corner = false;
        V sum = V::Zero();
        for(std::size_t a = 0; a < fan.directions.size(); ++a) {
          sum += fan.directions[a];
          for(std::size_t b = a + 1; b < fan.directions.size(); ++b)
            corner |= fan.directions[a].dot(fan.directions[b]) > -cos_link;
        }
        if(corner && (p - fan.apex).norm() <= radius)
          propose_apex(sum.norm() > 1e-6 ? V(fan.apex - offset * sum.normalized()) : fan.apex);
        for(std::size_t a = 0; a < fan.directions.size(); ++a) {
          const double t = (p - fan.apex).dot(fan.directions[a]);
          if(!(t > 0)) continue;
          if((p - (fan.apex + t * fan.directions[a])).norm() > radius) continue;
          // the foot of the projection on the crease, and one step along it on either side
          for(const double u : {t, t - step, t + step})
            if(u > 0) propose(fan.apex + u * fan.directions[a] + offset * fan.reflex[a]);
        }
      };
      std::vector<Result> sources;
      for(int round = 0; round < options.max_helper_rounds; ++round) {
        helpers.clear();
        proposed = internal::Point_grid(spacing);
        if(round == 0)
          for(const Result& r : projected_samples) propose_from(r);
        else
          for(const Result& r : sources) propose_from(r);
        if(helpers.empty()) break;
        std::vector<Result> projected;
        projected.reserve(helpers.size());
        project_points<ConcurrencyTag>(projection, helpers, std::back_inserter(projected));
        out.statistics.helper_queries += helpers.size();
        sources.clear();
        for(const Result& r : projected)
          if(collect(r)) {
            ++out.statistics.helper_hits;
            sources.push_back(r);
            taken.add(KT::to_eigen(r.point));
          }
      }
    }
  }

  // 3. clusters
  std::vector<internal::Crease_point> nodes =
    internal::cluster_crease_points(creases, options.cluster_spacing * h, cos_link);
  std::vector<V> corners = internal::cluster_apex_points(apices, options.corner_radius * h);

  // 4-5. the graph and its polylines
  internal::Chaining_parameters prm;
  prm.link_radius = options.link_radius * h;
  prm.cos_link_angle = cos_link;
  prm.corner_radius = options.corner_radius * h;
  prm.corner_link_radius = options.corner_link_radius * h;
  prm.gap_radius = options.gap_radius * h;
  const std::size_t apex_corners = corners.size();
  const std::vector<std::vector<std::size_t>> chains = internal::chain_features(nodes, corners, prm);
  // Corners found at junctions of branches (no apex point there): moved to their projection
  // when that is an apex within `relaxation_tolerance`.
  if(corners.size() > apex_corners) {
    std::vector<Point> queries;
    for(std::size_t c = apex_corners; c < corners.size(); ++c) queries.push_back(KT::to_point(corners[c]));
    std::vector<Result> snapped;
    project_points<ConcurrencyTag>(projection, queries, std::back_inserter(snapped));
    for(std::size_t q = 0; q < snapped.size(); ++q) {
      const Result& r = snapped[q];
      V& x = corners[apex_corners + q];
      if(!r.is_success() || !r.is_on_feature || r.feature_direction != NULL_VECTOR) continue;
      const V p = KT::to_eigen(r.point);
      if(p.allFinite() && (p - x).norm() <= options.relaxation_tolerance * h) x = p;
    }
    out.statistics.junction_corners = corners.size() - apex_corners;
  }
  out.statistics.crease_nodes = nodes.size();
  const std::size_t first_corner = nodes.size();
  const auto position = [&](std::size_t v) { return v < first_corner ? nodes[v].point : corners[v - first_corner]; };

  struct Line {
    std::vector<V> points;
    std::size_t front, back; // graph vertices of the ends
  };
  std::vector<Line> lines;
  for(const auto& chain : chains) {
    Line line;
    for(std::size_t v : chain) line.points.push_back(position(v));
    line.front = chain.front();
    line.back = chain.back();
    const bool corner_to_corner = line.front >= first_corner && line.back >= first_corner;
    if(!corner_to_corner && internal::polyline_length(line.points) < options.minimum_polyline_length * h) {
      ++out.statistics.dropped_polylines;
      continue;
    }
    line.points = internal::resample_polyline(line.points, options.resampling_spacing * h);
    lines.push_back(std::move(line));
  }

  // 6. relaxation: every vertex but the corners (and the repeated end of a closed polyline)
  std::vector<Point> queries;
  std::vector<std::pair<std::size_t, std::size_t>> where;
  for(std::size_t l = 0; l < lines.size(); ++l) {
    const Line& line = lines[l];
    const bool closed = line.front == line.back;
    for(std::size_t i = 0; i < line.points.size(); ++i) {
      if(i == 0 && line.front >= first_corner) continue;
      if(i + 1 == line.points.size() && (closed || line.back >= first_corner)) continue;
      queries.push_back(KT::to_point(line.points[i]));
      where.emplace_back(l, i);
    }
  }
  std::vector<Result> relaxed;
  relaxed.reserve(queries.size());
  project_points<ConcurrencyTag>(projection, queries, std::back_inserter(relaxed));
  out.statistics.relaxation_queries = queries.size();
  for(std::size_t q = 0; q < relaxed.size(); ++q) {
    const Result& r = relaxed[q];
    if(!r.is_success() || !r.is_on_feature) continue;
    const V p = KT::to_eigen(r.point);
    V& x = lines[where[q].first].points[where[q].second];
    if(!p.allFinite() || (p - x).norm() > options.relaxation_tolerance * h) continue;
    x = p;
    ++out.statistics.relaxed;
  }

  // 7. separation: the longest polylines first; a polyline closer than `minimum_separation` to
  // one kept before, away from the corners where both end, is dropped.
  {
    std::vector<std::size_t> order(lines.size());
    std::vector<double> length(lines.size());
    for(std::size_t l = 0; l < lines.size(); ++l) {
      order[l] = l;
      length[l] = internal::polyline_length(lines[l].points);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return length[a] > length[b]; });
    std::vector<bool> keep(lines.size(), false);
    std::vector<std::size_t> kept;
    for(std::size_t l : order) {
      bool too_close = false;
      for(std::size_t k : kept) {
        std::vector<V> shared;
        for(std::size_t end : {lines[l].front, lines[l].back})
          if(end >= first_corner && (end == lines[k].front || end == lines[k].back)) shared.push_back(position(end));
        if(internal::polylines_come_closer(lines[l].points, lines[k].points, options.minimum_separation * h, shared)) {
          too_close = true;
          break;
        }
      }
      if(too_close) {
        ++out.statistics.too_close_polylines;
        continue;
      }
      keep[l] = true;
      kept.push_back(l);
    }
    std::vector<Line> separated;
    for(std::size_t l = 0; l < lines.size(); ++l)
      if(keep[l]) separated.push_back(std::move(lines[l]));
    lines = std::move(separated);
  }

  // output: corners as the same Point_3 in every polyline; corners with two ends or more listed
  std::vector<int> ends(corners.size(), 0);
  std::vector<Point> corner_points;
  for(const V& c : corners) corner_points.push_back(KT::to_point(c));
  for(Line& line : lines) {
    std::vector<Point> pl;
    for(const V& x : line.points) pl.push_back(KT::to_point(x));
    if(line.front >= first_corner) {
      pl.front() = corner_points[line.front - first_corner];
      ++ends[line.front - first_corner];
    }
    if(line.back >= first_corner) {
      pl.back() = corner_points[line.back - first_corner];
      ++ends[line.back - first_corner];
    }
    if(line.front == line.back) pl.back() = pl.front();
    out.polylines.push_back(std::move(pl));
  }
  for(std::size_t c = 0; c < corners.size(); ++c)
    if(ends[c] >= 2) out.corners.push_back(corner_points[c]);
  return out;
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_DETECT_SHARP_FEATURES_H
