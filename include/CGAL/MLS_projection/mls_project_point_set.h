// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MLS_PROJECT_POINT_SET_H
#define CGAL_MLS_PROJECTION_MLS_PROJECT_POINT_SET_H

#include <CGAL/MLS_projection/Operator_tags.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Projection_status.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/MLS_projection/internal/projection/operator_from_tag.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctions
/// Projects every point of `points` onto the MLS surface of `points`, in place, in the manner of
/// `CGAL::jet_smooth_point_set()`: the samples are the points as given, each point is replaced
/// by its projection, and its normal, when a normal map is given, by the projection's normal
/// (oriented like the point's normal). A point whose projection fails (see `Projection_status`:
/// e.g. too few neighbours within the support) or has a non-finite coordinate is left as it is.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; the result does not depend on the number of threads
/// \tparam PointRange a range of 3D points (read and written through `point_map`)
/// \param points the samples, and the points projected
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a `ReadWritePropertyMap` with the points of `PointRange`}
///     \cgalParamDefault{`CGAL::Identity_property_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a `ReadWritePropertyMap` with their normals: read to orient the
///       local fits, written with the projections' normals}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{projection_operator}
///     \cgalParamDescription{the projection operator and its function space (see
///       `mls_surface_reconstruction()`)}
///     \cgalParamDefault{`Mixed_operator_tag()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_radius}
///     \cgalParamDescription{the bandwidth \f$h\f$ of the projection's weight}
///     \cgalParamDefault{derived from the data (`Projection_options::bandwidth`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{a `std::function<bool(double)>` called from the calling thread with
///       the fraction of the points projected; returning `false` cancels}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the number of points projected (the others are left as they are); 0 when cancelled,
///         in which case no point is changed
template <class ConcurrencyTag = Sequential_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
std::size_t mls_project_point_set(PointRange& points, const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using NP_helper = Point_set_processing_3_np_helper<PointRange, NamedParameters>;
  using K = typename NP_helper::Geom_traits;
  constexpr bool has_normals = NP_helper::has_normal_map();

  Projection_options options;
  options.bandwidth = choose_parameter(get_parameter(np, internal_np::neighbor_radius), 0.);
  const auto projection = internal::make_operator<K>(
    choose_parameter(get_parameter(np, internal_np::mls_projection_operator), Mixed_operator_tag()),
    std::make_shared<const Sample_set<K, 3>>(points, np), options);

  const auto point_map = NP_helper::get_point_map(points, np);
  using Result = typename std::decay_t<decltype(projection)>::Result;
  std::vector<Result> results;
  results.reserve(points.size());
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());
  if(!project_points<ConcurrencyTag>(projection, points, std::back_inserter(results),
                                     parameters::point_map(point_map).callback(callback)))
    return 0;

  std::size_t projected = 0, i = 0;
  for(auto& v : points) {
    const Result& r = results[i++];
    if(!is_success(r.status)) continue;
    put(point_map, v, r.point);
    if constexpr(has_normals) put(NP_helper::get_normal_map(points, np), v, r.normal);
    ++projected;
  }
  return projected;
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MLS_PROJECT_POINT_SET_H
