// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PARAMETERS_H
#define CGAL_MLS_PROJECTION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace internal_np {
enum mls_attribute_map_t { mls_attribute_map };
enum mls_vertex_attribute_map_t { mls_vertex_attribute_map };
enum mls_projection_operator_t { mls_projection_operator };
enum mls_features_t { mls_features };
enum mls_facet_size_t { mls_facet_size };
enum mls_facet_distance_t { mls_facet_distance };
enum mls_open_surface_t { mls_open_surface };
enum mls_remove_outliers_t { mls_remove_outliers };
enum mls_mesher_t { mls_mesher };
enum mls_parallel_mesher_t { mls_parallel_mesher };
enum mls_report_t { mls_report };
} // namespace internal_np

namespace MLS {

struct Meshing_report;

/// \ingroup PkgMLSProjectionRef
/// The mesher of `mls_surface_reconstruction()` (named parameter `mesher`).
enum class Mesher {
  MESH_3,        ///< CGAL's Mesh_3 (`make_mesh_3` on an `MLS_mesh_domain_3`): manifold output, sharp features protected
  SURFACE_MESHER ///< CGAL's Surface_mesher (`make_surface_mesh` on an `Implicit_surface_3`): sequential, no feature protection
};

/// \ingroup PkgMLSProjectionRef
/// A chain of named parameters that knows the names of this package besides those of CGAL that
/// its functions read (CGAL 5.5's own chain cannot learn new names). It is a
/// `CGAL::Named_function_parameters`, so it goes wherever CGAL's chains go. Start a chain in
/// `CGAL::MLS::parameters` (e.g. `CGAL::MLS::parameters::point_map(pm).facet_size(0.1)`); a
/// CGAL name that this class does not list returns CGAL's chain, which no longer knows this
/// package's names: put it last.
template <class T, class Tag, class Base = internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base> {
  /// The chain of CGAL that this chain is.
  using CGAL_chain = CGAL::Named_function_parameters<T, Tag, Base>;
  /// This chain's type.
  using self = Named_function_parameters<T, Tag, Base>;
  using CGAL_chain::CGAL_chain;

  /// This chain with one more named parameter (the functions that read them say what they mean).
  /// @{

#define CGAL_MLS_NAMED_PARAMETER(TAG, NAME)                                                                            \
  template <class V>                                                                                                   \
  Named_function_parameters<V, internal_np::TAG, self> NAME(const V& v) const {                                        \
    return Named_function_parameters<V, internal_np::TAG, self>(v, *this);                                             \
  }
  CGAL_MLS_NAMED_PARAMETER(point_t, point_map)
  CGAL_MLS_NAMED_PARAMETER(normal_t, normal_map)
  CGAL_MLS_NAMED_PARAMETER(geom_traits_t, geom_traits)
  CGAL_MLS_NAMED_PARAMETER(callback_t, callback)
  CGAL_MLS_NAMED_PARAMETER(neighbor_radius_t, neighbor_radius)
  CGAL_MLS_NAMED_PARAMETER(maximum_running_time_t, maximum_running_time)
  CGAL_MLS_NAMED_PARAMETER(mls_attribute_map_t, attribute_map)
  CGAL_MLS_NAMED_PARAMETER(mls_vertex_attribute_map_t, vertex_attribute_map)
  CGAL_MLS_NAMED_PARAMETER(mls_projection_operator_t, projection_operator)
  CGAL_MLS_NAMED_PARAMETER(mls_facet_size_t, facet_size)
  CGAL_MLS_NAMED_PARAMETER(mls_facet_distance_t, facet_distance)
  CGAL_MLS_NAMED_PARAMETER(mls_mesher_t, mesher)
#undef CGAL_MLS_NAMED_PARAMETER
  /// This chain with `features`.
  Named_function_parameters<bool, internal_np::mls_features_t, self> features(bool b) const { return {b, *this}; }
  /// This chain with `open_surface`.
  Named_function_parameters<bool, internal_np::mls_open_surface_t, self> open_surface(bool b) const { return {b, *this}; }
  /// This chain with `remove_outliers`.
  Named_function_parameters<bool, internal_np::mls_remove_outliers_t, self> remove_outliers(bool b) const {
    return {b, *this};
  }
  /// This chain with `parallel_mesher`.
  Named_function_parameters<bool, internal_np::mls_parallel_mesher_t, self> parallel_mesher(bool b) const {
    return {b, *this};
  }
  /// This chain with the output parameter `report`.
  Named_function_parameters<Meshing_report*, internal_np::mls_report_t, self> report(Meshing_report& r) const {
    return {&r, *this};
  }
  /// @}
};

/// The named parameters of CGAL, and those of this package (see
/// `CGAL::MLS::Named_function_parameters`).
namespace parameters {
using namespace CGAL::parameters;

/// The empty chain of this package, to start a chain: `CGAL::MLS::parameters::begin().facet_size(0.1)`.
inline Named_function_parameters<bool, internal_np::all_default_t> begin() {
  return Named_function_parameters<bool, internal_np::all_default_t>();
}

/// A chain of this package with one named parameter.
/// @{
#define CGAL_MLS_NAMED_PARAMETER(NAME)                                                                                 \
  template <class V>                                                                                                   \
  auto NAME(const V& v) {                                                                                              \
    return begin().NAME(v);                                                                                            \
  }
CGAL_MLS_NAMED_PARAMETER(point_map)
CGAL_MLS_NAMED_PARAMETER(normal_map)
CGAL_MLS_NAMED_PARAMETER(geom_traits)
CGAL_MLS_NAMED_PARAMETER(callback)
CGAL_MLS_NAMED_PARAMETER(neighbor_radius)
CGAL_MLS_NAMED_PARAMETER(maximum_running_time)
CGAL_MLS_NAMED_PARAMETER(projection_operator)
CGAL_MLS_NAMED_PARAMETER(facet_size)
CGAL_MLS_NAMED_PARAMETER(facet_distance)
CGAL_MLS_NAMED_PARAMETER(mesher)
CGAL_MLS_NAMED_PARAMETER(features)
CGAL_MLS_NAMED_PARAMETER(open_surface)
CGAL_MLS_NAMED_PARAMETER(remove_outliers)
CGAL_MLS_NAMED_PARAMETER(parallel_mesher)
#undef CGAL_MLS_NAMED_PARAMETER
/// @}
/// A chain of this package with the output parameter `report`.
inline auto report(Meshing_report& r) { return begin().report(r); }

/// \ingroup PkgMLSProjectionFunctions
/// The named parameter of the per-point attributes (colours, intensities, any scalar channels)
/// of an input point range: a `ReadablePropertyMap` whose value type is a range of numbers
/// convertible to `double` (e.g. `std::array<double, 3>` or `std::vector<double>`), all of the
/// same size, the number of channels.
template <class AttributeMap>
auto attribute_map(const AttributeMap& map) {
  return begin().attribute_map(map);
}

/// \ingroup PkgMLSProjectionFunctions
/// The named parameter through which `mls_surface_reconstruction()` writes the attributes of
/// the output mesh's vertices: a `WritablePropertyMap` from the mesh's `vertex_descriptor` to
/// `std::vector<double>` (one value per channel of `attribute_map`).
template <class VertexAttributeMap>
auto vertex_attribute_map(const VertexAttributeMap& map) {
  return begin().vertex_attribute_map(map);
}

} // namespace parameters
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PARAMETERS_H
