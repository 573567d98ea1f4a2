// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MESHING_REPORT_H
#define CGAL_MLS_PROJECTION_MESHING_REPORT_H

#include <cstddef>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// What `mls_surface_reconstruction()` did: its output parameter `report` (also filled on failure).
struct Meshing_report {
  /// Why the function returned `false` (empty on success): "cancelled", "too few points", ...
  const char* failure = "";
  /// The finite input points used.
  std::size_t points = 0;
  /// The finite input points removed as outliers (named parameter `remove_outliers`).
  std::size_t outliers = 0;
  /// The average spacing (CGAL's `compute_average_spacing`, 6 neighbours).
  double average_spacing = 0;
  /// The bandwidth \f$h\f$ of the projection.
  double bandwidth = 0;
  /// Points whose estimated normal was oriented by the fall-back (away from the centroid: points
  /// without a neighbour in the orientation's graph; 0 when the input has normals).
  std::size_t normals_by_fallback = 0;
  /// The estimated normals were oriented a second time, as one spanning tree: oriented with the
  /// votes of the free space splitting the tree (the default), they left the surface open (see
  /// the manual, "The Implicit Function: Local Fits").
  bool normals_as_one_tree = false;
  /// Seeds whose local fits are blended, seeds projected but not blended (see
  /// `MLS_implicit_function::number_of_unblended_seeds()`), failed seeds, and the blended seeds
  /// whose fit is P_L's in place of the operator's (`number_of_levin_fallbacks()`), and the
  /// blended seeds projected into the gaps of the sampling (`number_of_gap_seeds()`).
  /// @{
  std::size_t seeds = 0, unblended_seeds = 0, failed_seeds = 0, levin_fallback_seeds = 0, gap_seeds = 0;
  /// @}
  /// Seeds projected by the closest-point operator (the others by P_L, see
  /// `MLS_implicit_function`, "Screening by P_L").
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
  /// exceeded its budget, 4 times the expected number of evaluations or vertices, or stalled: then
  /// `feature_budget_exceeded` is set too): the mesh was made without them, so no feature is
  /// protected.
  /// @{
  bool features_dropped = false, feature_budget_exceeded = false;
  /// @}
  /// Connected components of the mesher's output removed as unsupported by the data (see
  /// `mls_surface_reconstruction()`).
  std::size_t removed_components = 0;
  /// With `open_surface`: the boundary cycles of the mesh (the borders of the
  /// scan and of its holes).
  std::size_t boundary_cycles = 0;
  /// The criteria used.
  /// @{
  double facet_size = 0, facet_distance = 0;
  /// @}
  /// Evaluations of the implicit function by the mesher, and the limit it ran under (see
  /// `mls_surface_reconstruction()`).
  /// @{
  std::size_t evaluations = 0, max_evaluations = 0;
  /// @}
  /// Wall-clock seconds of the stages.
  /// @{
  double seconds_normals = 0, seconds_seeds = 0, seconds_features = 0, seconds_meshing = 0;
  /// @}
};

/// \ingroup PkgMLSProjectionRef
/// A stage of `mls_surface_reconstruction()`: its name and its slice [begin, end) of the fraction
/// of the job that the `callback` reports.
struct Meshing_stage {
  const char* name; ///< "normals", "seeds", "features", "meshing" or "output"
  /// The stage's slice of the fraction.
  /// @{
  double begin, end;
  /// @}
};

namespace internal {
inline constexpr Meshing_stage meshing_stages[] = {
  {"normals", 0., 0.1}, {"seeds", 0.1, 0.5}, {"features", 0.5, 0.6}, {"meshing", 0.6, 0.98}, {"output", 0.98, 1.}};
enum Meshing_stage_index { NORMALS_STAGE, SEEDS_STAGE, FEATURES_STAGE, MESHING_STAGE, OUTPUT_STAGE };
} // namespace internal

/// \ingroup PkgMLSProjectionRef
/// The stage at `fraction` of the job: "normals" [0, 0.1), "seeds" [0.1, 0.5), "features"
/// [0.5, 0.6), "meshing" [0.6, 0.98), "output" [0.98, 1].
inline Meshing_stage meshing_stage(double fraction) {
  for(const Meshing_stage& stage : internal::meshing_stages)
    if(fraction < stage.end) return stage;
  return internal::meshing_stages[internal::OUTPUT_STAGE];
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MESHING_REPORT_H
