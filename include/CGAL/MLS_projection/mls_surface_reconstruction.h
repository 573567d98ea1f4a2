// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MLS_SURFACE_RECONSTRUCTION_H
#define CGAL_MLS_PROJECTION_MLS_SURFACE_RECONSTRUCTION_H

#include <CGAL/MLS_projection/Meshing_report.h>
#include <CGAL/MLS_projection/Operator_tags.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/internal/meshing/reconstruct_surface.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctions
/// Reconstructs a closed triangle mesh of the MLS surface of `points`: the outliers removed,
/// oriented normals (the input normals, or estimated and oriented, see `MLS_implicit_function`),
/// the implicit function of the selected operator's local fits (`MLS_implicit_function`), the
/// sharp-feature polylines found by the operator (`detect_sharp_features()`; those the surface
/// \f$f = 0\f$ does not pass through, within the facet distance, are dropped: see
/// `Meshing_report::off_surface_polylines`; the others are fitted to it), then CGAL's Mesh_3
/// (manifold output, the polylines protected) or Surface_mesher. A connected component of the mesh
/// whose median vertex distance to the nearest input point exceeds \f$h/2\f$, or whose bounding
/// box has a diagonal shorter than the facet size, is removed (a bubble of the function's sign
/// away from the data or below the mesh's resolution, not a sampled surface; see
/// `Meshing_report::removed_components`); when every component would go, the one nearest to the
/// data is kept.
///
/// The average spacing \f$s\f$ is CGAL's `compute_average_spacing` with 6 neighbours.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the normal estimation, the projection of the
///         seeds and the feature detection run in parallel, with results that do not depend on
///         the number of threads; Mesh_3 too with `parallel_mesher` (its output then depends on
///         the threads' scheduling). Surface_mesher is always sequential. By default the output
///         is bit-identical for any tag, any number of threads and across runs.
/// \tparam PointRange a range of points (read through `point_map`)
/// \tparam PolygonMesh a model of `MutableFaceGraph` (e.g. `CGAL::Surface_mesh`)
/// \tparam NamedParameters a sequence of named parameters: CGAL's (`CGAL::parameters::`) or this
///         package's chain (`CGAL::MLS::parameters::`), which knows the names below
/// \param points the input samples; points with a non-finite coordinate are ignored
/// \param mesh the output; cleared first (its property maps are kept), and left empty when the
///        function returns `false`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map with the points of `PointRange`}
///     \cgalParamDefault{`CGAL::Identity_property_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map with their oriented normals}
///     \cgalParamDefault{none: the normals are estimated (PCA) and oriented (see `MLS_implicit_function`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{projection_operator}
///     \cgalParamDescription{the projection operator and its function space: `Mixed_operator_tag()`;
///       `Unified_operator_tag<Space>()` with a 3D model of `MLSFunctionSpace` (e.g.
///       `Wedge_fan_function_space<3>`); `Levin_operator_tag<Space>()` with `Plane_function_space<3>`
///       or `Polynomial_function_space<3>`. Only the selected operator is compiled.}
///     \cgalParamDefault{`Mixed_operator_tag()`: a quadratic where the data are smooth and a
///       wedge fan at creases and corners}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_radius}
///     \cgalParamDescription{the bandwidth \f$h\f$ of the projection's weight}
///     \cgalParamDefault{derived from the data (`Projection_options::bandwidth`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{features}
///     \cgalParamDescription{`bool`: protect the sharp-feature polylines (Mesh_3 with an operator
///       that finds creases: a wedge fan, alone or mixed)}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_size}
///     \cgalParamDescription{`double`: the facet size criterion of the mesher}
///     \cgalParamDefault{\f$2s\f$}
///   \cgalParamNEnd
///   \cgalParamNBegin{facet_distance}
///     \cgalParamDescription{`double`: the facet distance criterion of the mesher}
///     \cgalParamDefault{\f$s/4\f$}
///   \cgalParamNEnd
///   \cgalParamNBegin{mesher}
///     \cgalParamDescription{a `Mesher`: `Mesher::MESH_3` or `Mesher::SURFACE_MESHER` (no feature
///       protection)}
///     \cgalParamDefault{`Mesher::MESH_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{parallel_mesher}
///     \cgalParamDescription{`bool`: Mesh_3 refines in parallel too with a parallel
///       `ConcurrencyTag`: faster on large meshes, but the mesh then differs from run to run
///       and with the number of threads}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{remove_outliers}
///     \cgalParamDescription{`bool`: remove the outliers first: the isolated points, whose 6 nearest
///       neighbours lie at a root-mean-square distance more than 3 times the median of that
///       distance over the 6 neighbours or 4 times its median over all points; and the points
///       off their local surface, further from the plane of their 20 nearest neighbours than that
///       median and than 3 times the 90th percentile of the neighbours' distances to it}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{open_surface}
///     \cgalParamDescription{`bool`: the input is an open scan (a part of a surface, e.g. scanned
///       from one side): mesh the surface only where there is data, up to 2 average spacings
///       beyond the last points, as a mesh with a boundary (Mesh_3 only; see the manual, "Open
///       Scans")}
///     \cgalParamDefault{`false`: the surface is closed}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{`double`: the seconds of meshing after which the mesher is stopped and
///       the reconstruction fails ("the mesher did not finish within the time limit")}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a `std::function<bool(double)>` called from the calling thread with
///       the fraction of the whole job done, in [0, 1] (the stage: `meshing_stage()`); returning
///       `false` cancels: the function then returns `false` and `mesh` stays empty}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{report}
///     \cgalParamDescription{a `Meshing_report&` filled with what the reconstruction did, also on
///       failure}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{attribute_map}
///     \cgalParamDescription{the per-point attributes (see `CGAL::MLS::parameters::attribute_map()`);
///       with `vertex_attribute_map`, each vertex of the mesh gets the attributes of the input
///       points interpolated on the local fit of its nearest seed (see `interpolate_attributes()`)}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_attribute_map}
///     \cgalParamDescription{a `WritablePropertyMap` from the mesh's vertices to `std::vector<double>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `true` on success; `false` when cancelled, when there are fewer than 10 finite
///         points, when the implicit function cannot be built (degenerate data) or has no inside,
///         when the surface is not closed (without `open_surface`), when the mesher produced no
///         facet or did not finish within its limits, or when the attribute values do not all
///         have the same number of channels; `Meshing_report::failure` says which
template <class ConcurrencyTag = Sequential_tag, class PointRange, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
bool mls_surface_reconstruction(const PointRange& points, PolygonMesh& mesh,
                                const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::Reconstruction_settings s;
  s.mesher = choose_parameter(get_parameter(np, internal_np::mls_mesher), Mesher::MESH_3);
  s.parallel_mesher = choose_parameter(get_parameter(np, internal_np::mls_parallel_mesher), false);
  s.remove_outliers = choose_parameter(get_parameter(np, internal_np::mls_remove_outliers), true);
  s.features = choose_parameter(get_parameter(np, internal_np::mls_features), true);
  s.open_surface = choose_parameter(get_parameter(np, internal_np::mls_open_surface), false);
  s.facet_size = choose_parameter(get_parameter(np, internal_np::mls_facet_size), 0.);
  s.facet_distance = choose_parameter(get_parameter(np, internal_np::mls_facet_distance), 0.);
  s.bandwidth = choose_parameter(get_parameter(np, internal_np::neighbor_radius), 0.);
  s.max_meshing_seconds = choose_parameter(get_parameter(np, internal_np::maximum_running_time), 0.);
  s.report = choose_parameter(get_parameter(np, internal_np::mls_report), static_cast<Meshing_report*>(nullptr));
  return internal::reconstruct_surface<ConcurrencyTag>(
    points, mesh, s, choose_parameter(get_parameter(np, internal_np::mls_projection_operator), Mixed_operator_tag()), np);
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MLS_SURFACE_RECONSTRUCTION_H
