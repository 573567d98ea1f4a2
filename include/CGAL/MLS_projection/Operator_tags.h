// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_OPERATOR_TAGS_H
#define CGAL_MLS_PROJECTION_OPERATOR_TAGS_H

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// Selects Levin's operator \f$\mathcal{P}_L\f$ (`Levin_projection<K, FunctionSpace>`) for the
/// named parameter `projection_operator`: fast and smooth, creases rounded. `FunctionSpace`: a
/// space of graphs, `Plane_function_space<3>` or `Polynomial_function_space<3>`.
template <class FunctionSpace>
struct Levin_operator_tag {};

/// \ingroup PkgMLSProjectionRef
/// Selects the unified operator \f$\mathcal{P}_U\f$ (`Unified_projection<K, FunctionSpace>`) for
/// the named parameter `projection_operator`: `Wedge_fan_function_space<3>` reproduces sampled
/// creases and corners, `Paraboloid_function_space<3>` or `Plane_function_space<3>` fit smooth
/// surfaces, and a model of `MLSFunctionSpace` of your own brings its own prior.
template <class FunctionSpace>
struct Unified_operator_tag {};

/// \ingroup PkgMLSProjectionRef
/// Selects `Mixed_projection<K, 3>` for the named parameter `projection_operator` (the default):
/// \f$\mathcal{P}_U\f$ with a quadratic where the data are smooth and a wedge fan where they have
/// creases.
struct Mixed_operator_tag {};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_OPERATOR_TAGS_H
