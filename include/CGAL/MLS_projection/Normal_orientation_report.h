// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_NORMAL_ORIENTATION_REPORT_H
#define CGAL_MLS_PROJECTION_NORMAL_ORIENTATION_REPORT_H

#include <cstddef>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// What the estimation and orientation of the samples' normals did, when the samples carry no
/// normals (`MLS_implicit_function::normals_report()`; see the manual, section "Meshing").
struct Normal_orientation_report {
  /// Points oriented along the spanning forest (in a tree of at least two points).
  std::size_t oriented_by_mst = 0;
  /// Points without a usable neighbour (trees of one point), oriented away from the centroid.
  std::size_t oriented_by_fallback = 0;
  /// Points whose estimated normal was not finite or null, replaced by the direction from the
  /// centroid (or +z when the point is the centroid).
  std::size_t replaced = 0;
  /// Trees of the spanning forest (the connected parts of the neighbour graph).
  std::size_t components = 0;
  /// Trees turned over by their votes or by the outwardness test.
  std::size_t flipped_components = 0;
  /// `false` when cancelled by the callback.
  bool completed = true;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_NORMAL_ORIENTATION_REPORT_H
