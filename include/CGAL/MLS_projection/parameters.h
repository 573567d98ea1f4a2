// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PARAMETERS_H
#define CGAL_MLS_PROJECTION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace internal_np {
enum mls_attribute_map_t { mls_attribute_map };
enum mls_vertex_attribute_map_t { mls_vertex_attribute_map };
} // namespace internal_np

namespace MLS {
/// The named parameters of CGAL and those of this package (`attribute_map`, `vertex_attribute_map`).
namespace parameters {
using namespace CGAL::parameters;

/// \ingroup PkgMLSProjectionFunctions
/// The named parameter of the per-point attributes (colours, intensities, any scalar channels)
/// of an input point range: a `ReadablePropertyMap` whose value type is a range of numbers
/// convertible to `double` (e.g. `std::array<double, 3>` or `std::vector<double>`), all of the
/// same size, the number of channels. CGAL 5.5's named parameters know no such tag: start the
/// chain with it (`CGAL::MLS::parameters::attribute_map(m).point_map(pm)`), or append it to an
/// existing chain with the second overload.
template <class AttributeMap>
Named_function_parameters<AttributeMap, internal_np::mls_attribute_map_t> attribute_map(const AttributeMap& map) {
  return Named_function_parameters<AttributeMap, internal_np::mls_attribute_map_t>(map);
}

/// `np` with the attribute map `map` appended.
template <class AttributeMap, class T, class Tag, class Base>
Named_function_parameters<AttributeMap, internal_np::mls_attribute_map_t, Named_function_parameters<T, Tag, Base>>
attribute_map(const AttributeMap& map, const Named_function_parameters<T, Tag, Base>& np) {
  return Named_function_parameters<AttributeMap, internal_np::mls_attribute_map_t, Named_function_parameters<T, Tag, Base>>(map, np);
}

/// \ingroup PkgMLSProjectionFunctions
/// The named parameter through which `mls_surface_reconstruction()` writes the attributes of
/// the output mesh's vertices: a `WritablePropertyMap` from the mesh's `vertex_descriptor` to
/// `std::vector<double>` (one value per channel of `attribute_map`).
template <class VertexAttributeMap>
Named_function_parameters<VertexAttributeMap, internal_np::mls_vertex_attribute_map_t>
vertex_attribute_map(const VertexAttributeMap& map) {
  return Named_function_parameters<VertexAttributeMap, internal_np::mls_vertex_attribute_map_t>(map);
}

/// `np` with the vertex attribute map `map` appended.
template <class VertexAttributeMap, class T, class Tag, class Base>
Named_function_parameters<VertexAttributeMap, internal_np::mls_vertex_attribute_map_t, Named_function_parameters<T, Tag, Base>>
vertex_attribute_map(const VertexAttributeMap& map, const Named_function_parameters<T, Tag, Base>& np) {
  return Named_function_parameters<VertexAttributeMap, internal_np::mls_vertex_attribute_map_t,
                                   Named_function_parameters<T, Tag, Base>>(map, np);
}

} // namespace parameters
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PARAMETERS_H
