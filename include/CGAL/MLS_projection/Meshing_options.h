// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MESHING_OPTIONS_H
#define CGAL_MLS_PROJECTION_MESHING_OPTIONS_H

#include <cstddef>
#include <functional>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// How `MLS_implicit_function` evaluates \f$f(x)\f$.
enum class Implicit_function_mode {
  /// Blend the signed distances of \f$x\f$ to the local fits of the nearest seeds (projected
  /// once, at construction) with a partition of unity: some microseconds per evaluation, the
  /// default for meshing (see the manual's section "Meshing").
  LOCAL_FITS,
  /// Project \f$x\f$ at every evaluation: \f$f(x) = \pm|x - P(x)|\f$. The reference; as slow as
  /// the projection operator (0.5 ms to 0.2 s per evaluation).
  EXACT
};

/// \ingroup PkgMLSProjectionRef
/// The knobs of `MLS_implicit_function`. Lengths are in units of the bandwidth \f$h\f$ of the
/// projection operator.
struct Implicit_function_options {
  /// The evaluation mode.
  Implicit_function_mode mode = Implicit_function_mode::LOCAL_FITS;
  /// The seeds are the input samples thinned on a grid of this cell size (units of \f$h\f$):
  /// one seed per occupied cell. 0: every input sample is a seed.
  double seed_spacing = 0.5;
  /// The number of nearest seeds blended by the partition of unity (clamped to [2, 63]).
  int blend_neighbors = 8;
  /// Beyond this distance from the nearest seed (units of \f$h\f$), the value is blended
  /// towards the far value (distance to the nearest seed, signed by its local fit near the
  /// seed)...
  double far_start = 1.;
  /// ... which it reaches at this distance (units of \f$h\f$). The local fits are the
  /// surface within about \f$h\f$ of their data; further out, a wedge fan's sign is less reliable
  /// than the far value's (measured on the built-in solid, 11810 points, with the check of the fits
  /// at its earlier tolerance of 2%: of 112762 points of a grid of step h/2 at least h/2 off the
  /// surface, 1 had the wrong sign with 1 and 2, 4 with 1.5 and 3).
  double far_end = 2.;
  /// With an operator that finds creases (the wedge fan, alone or mixed): project every seed with
  /// Levin's operator first and hand only the seeds its quadratic cannot fit (near creases and
  /// corners) to the operator (see `MLS_implicit_function`, "Screening by P_L"). `false`: the
  /// operator projects every seed (10 to 200 ms each).
  bool levin_screening = true;
  /// The screening keeps P_L's fit when its weighted RMS residual is at most this (units of
  /// \f$h\f$)...
  double screening_residual = 0.01;
  /// ... or at most this factor times the estimated RMS of the noise (see
  /// `Mixed_projection::noise_variance()`; the default is the mixed operator's margin,
  /// \f$\sqrt{2.5}\f$, so that a seed gets the fit the mixed operator would give it).
  double screening_noise_factor = 1.58;
  /// Where the operator's fit of a seed is not blended (see `MLS_implicit_function`, "Seeds"),
  /// P_L's fit of the seed is blended in its place when its weighted RMS residual is at most this
  /// factor times the estimated RMS of the noise (about 0 without noise, so that no crease is
  /// rounded by a quadratic), and it passes the same test. 0: never.
  double fallback_noise_factor = 3.;
  /// The number of neighbours of the normal estimation and orientation (when the samples carry
  /// no normals): `pca_estimate_normals` and the orientation's neighbour graph.
  int normal_neighbors = 18;
  /// Project seeds into the gaps of the sampling (holes of a scan up to about \f$4h\f$ across),
  /// so that the local fits make the surface there (see `MLS_implicit_function`, "Gaps").
  /// `mls_surface_reconstruction()` turns it off for an open surface, which ends where its
  /// samples end.
  bool complete_gaps = true;
};

/// \ingroup PkgMLSProjectionRef
/// What `mls_surface_reconstruction()` did, filled when `Meshing_options::report` points to one.
struct Meshing_report {
  /// Why the function returned `false` (empty on success): "cancelled", "too few points", ...
  const char* failure = "";
  /// The finite input points used.
  std::size_t points = 0;
  /// The finite input points removed as outliers (see `Meshing_options::remove_outliers`).
  std::size_t outliers = 0;
  /// The average spacing (CGAL's `compute_average_spacing`, 6 neighbours).
  double average_spacing = 0;
  /// The bandwidth \f$h\f$ of the projection.
  double bandwidth = 0;
  /// Points whose estimated normal was oriented by the fall-back (away from the centroid: points
  /// without a neighbour in the orientation's graph; 0 when the input has normals).
  std::size_t normals_by_fallback = 0;
  /// Seeds whose local fits are blended, seeds projected but not blended (see
  /// `MLS_implicit_function::number_of_unblended_seeds()`), failed seeds, and the blended seeds
  /// whose fit is P_L's in place of the operator's (`number_of_levin_fallbacks()`), and the
  /// blended seeds projected into the gaps of the sampling (`number_of_gap_seeds()`).
  /// @{
  std::size_t seeds = 0, unblended_seeds = 0, failed_seeds = 0, levin_fallback_seeds = 0, gap_seeds = 0;
  /// @}
  /// Seeds projected by the closest-point operator (the others by P_L, see
  /// `Implicit_function_options::levin_screening`).
  std::size_t operator_seeds = 0;
  /// Sharp features protected (Mesh_3).
  /// @{
  std::size_t feature_polylines = 0, corners = 0;
  /// @}
  /// Feature polylines dropped before meshing because the implicit surface does not pass through
  /// them: the median of \f$|f|\f$ over their vertices exceeds the facet distance (Mesh_3 could not
  /// protect them). Not counted in `feature_polylines`.
  std::size_t off_surface_polylines = 0;
  /// Points projected by the feature detection (helper points and polyline vertices).
  std::size_t feature_queries = 0;
  /// Mesh_3 failed with the feature polylines (a CGAL error, e.g. on polylines too close to each
  /// other that `detect_sharp_features()` did not separate), or did not finish with them (it
  /// exceeded `Meshing_options::feature_evaluation_budget` or stalled: then
  /// `feature_budget_exceeded` is set too): the mesh was made without them, so no feature is
  /// protected.
  /// @{
  bool features_dropped = false, feature_budget_exceeded = false;
  /// @}
  /// Connected components of the mesher's output removed as unsupported by the data (see
  /// `mls_surface_reconstruction()`).
  std::size_t removed_components = 0;
  /// With `Meshing_options::open_surface`: the boundary cycles of the mesh (the borders of the
  /// scan and of its holes).
  std::size_t boundary_cycles = 0;
  /// The criteria used.
  /// @{
  double facet_size = 0, facet_distance = 0;
  /// @}
  /// Evaluations of the implicit function by the mesher, and the limit it ran under (see
  /// `Meshing_options::max_evaluations`).
  /// @{
  std::size_t evaluations = 0, max_evaluations = 0;
  /// @}
  /// Wall-clock seconds of the stages.
  /// @{
  double seconds_normals = 0, seconds_seeds = 0, seconds_features = 0, seconds_meshing = 0;
  /// @}
};

/// \ingroup PkgMLSProjectionRef
/// The options of `mls_surface_reconstruction()`. Lengths are absolute (the unit of the input);
/// 0 means "derived from the data", as documented per field.
struct Meshing_options {
  /// The projection operator.
  enum class Operator {
    LEVIN,  ///< `Levin_projection` (\f$\mathcal{P}_L\f$): fast, smooth; `space` must be `PLANE` or `QUADRATIC`
    UNIFIED ///< `Unified_projection` or `Mixed_projection` (\f$\mathcal{P}_U\f$): exact at sampled creases with `WEDGE` or `MIXED`
  };
  /// The function space.
  enum class Space {
    PLANE,     ///< `Plane_function_space`
    QUADRATIC, ///< `Polynomial_function_space` with `LEVIN`, `Quadratic_function_space` with `UNIFIED`
    WEDGE,     ///< `Wedge_fan_function_space` (`UNIFIED` only)
    MIXED      ///< `Mixed_projection` (`UNIFIED` only)
  };
  /// The mesher.
  enum class Mesher {
    MESH_3,        ///< CGAL's Mesh_3 (`make_mesh_3` on a `Labeled_mesh_domain_3`), manifold output; parallel with `Parallel_tag` and `parallel_mesher`
    SURFACE_MESHER ///< CGAL's Surface_mesher (`make_surface_mesh` on an `Implicit_surface_3`), sequential, no feature protection
  };

  /// The projection operator (default `UNIFIED`).
  Operator projection_operator = Operator::UNIFIED;
  /// The function space (default `MIXED`).
  Space space = Space::MIXED;
  /// The mesher (default `MESH_3`).
  Mesher mesher = Mesher::MESH_3;
  /// Run Mesh_3's own refinement in parallel when `mls_surface_reconstruction()` is called with
  /// `CGAL::Parallel_tag` (default `false`: Mesh_3 refines sequentially, the other stages are
  /// parallel). Faster on large meshes, but the output mesh then depends on the scheduling of
  /// the threads: it differs from run to run and with the number of threads. Without it, the
  /// output is bit-identical for any number of threads and across runs.
  bool parallel_mesher = false;
  /// Remove the outliers first: the isolated points, whose 6 nearest neighbours lie at a
  /// root-mean-square distance more than 3 times the median of that distance over the 6 neighbours,
  /// or 4 times its median over all points (also a region sampled more than 4 times as sparsely
  /// as the median); and the points off their local surface, further from the plane of their 20
  /// nearest neighbours than that median and than 3 times the 90th percentile of the neighbours'
  /// distances to it.
  /// Default `true`; see `Meshing_report::outliers`.
  bool remove_outliers = true;
  /// Protect sharp-feature polylines (Mesh_3 with a space that finds creases: `WEDGE`, `MIXED`).
  bool features = true;
  /// The input is an open scan (a part of a surface, e.g. scanned from one side): mesh the
  /// surface only where there is data, up to 2 average spacings beyond the last points, as a mesh
  /// with a boundary (`Mesh_3` only; see the manual, "Open Scans"). Default `false`: the surface
  /// is closed.
  bool open_surface = false;
  /// The facet size criterion; 0: 2 times the average spacing of the input.
  double facet_size = 0;
  /// The facet distance criterion; 0: 0.25 times the average spacing.
  double facet_distance = 0;
  /// Mesh_3's edge size criterion along the feature polylines; 0: 0.75 times the facet size (with
  /// larger protecting balls, Mesh_3's manifold refinement next to close polylines can loop without
  /// end: see the manual, "Criteria and Meshers").
  double edge_size = 0;
  /// The facet angle criterion, in degrees (at most 30 for the meshers to terminate).
  double facet_angle = 25;
  /// The bandwidth \f$h\f$ of the projection; 0: derived from the data (`Projection_options`).
  double bandwidth = 0;
  /// The mesher is stopped, and the reconstruction fails ("the mesher did not finish within the
  /// evaluation limit"), after this many evaluations of the implicit function: a bound on the
  /// work of a refinement that keeps evaluating without end. 0 (default): 100 times the expected
  /// number, \f$250\,n\,(s/\mathrm{size})^2\f$ for \f$n\f$ points of average spacing \f$s\f$, at least
  /// \f$10^6\f$ (a 50000-point scan of a CAD part used 0.6 times the expected number).
  std::size_t max_evaluations = 0;
  /// Mesh_3 with the feature polylines is stopped after this many times the expected number of
  /// evaluations (see `max_evaluations`) or of vertices (\f$n\,(s/\mathrm{size})^2\f$), or as
  /// soon as it stalls (over the last 5 seconds and quarter of the meshing time, it evaluated the
  /// function at less than a tenth of its fastest pace over one second): its manifold refinement
  /// next to a protected polyline can loop without end, evaluating little or nothing, or slow
  /// down more and more. The surface is then meshed again without them
  /// (`Meshing_report::feature_budget_exceeded`). 0: no budget (the stall is still detected).
  double feature_evaluation_budget = 4;
  /// The mesher is stopped, and the reconstruction fails ("the mesher did not finish within the
  /// time limit"), after this many seconds of meshing; 0 (default): no limit. (Mesh_3 is also
  /// stopped when it stalls, see `feature_evaluation_budget`: without polylines the
  /// reconstruction then fails, "the mesher stalled".)
  double max_meshing_seconds = 0;
  /// The options of the implicit function (seeds, blending, normals).
  Implicit_function_options implicit_function;
  /// Called from the calling thread at the start of each stage ("normals", "seeds", "features",
  /// "meshing", "output") with the fraction of that stage done; may be empty.
  std::function<void(const char* stage, double fraction)> stage_progress;
  /// When not null, filled with what the reconstruction did (also on failure).
  Meshing_report* report = nullptr;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MESHING_OPTIONS_H
