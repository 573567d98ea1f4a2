// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PROJECTION_OPTIONS_H
#define CGAL_MLS_PROJECTION_PROJECTION_OPTIONS_H

#include <CGAL/MLS_projection/Weight_function.h>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The knobs shared by every projection operator. The defaults suit noiseless to
/// moderately noisy scans; every field is documented in the user manual.
struct Projection_options {
  /// The bandwidth \f$h\f$ of the weight function. 0 (default): derived from the data
  /// as the mean distance from an input point to its `k`-th nearest neighbour. A bandwidth
  /// above \f$10^{150}\f$ (whose square times the support would overflow) is not usable: every
  /// projection then fails with `DEGENERATE_NEIGHBORHOOD`.
  double bandwidth = 0;
  /// The number of neighbours used to derive \f$h\f$ and for the initial weighted PCA.
  /// 0 (default): 6 for curves in 2D, 16 for surfaces in 3D.
  int k = 0;
  /// The kind of weight function.
  Weight_kind weight = Weight_kind::POLYNOMIAL;
  /// The largest number of energy evaluations of one optimiser run.
  int max_evaluations = 400;
  /// Whether `project_points()` continues each projection from the fit of a nearby query, with
  /// the operators that can (`Closest_point_projection`, `Mixed_projection`).
  bool warm_starts = true;
  /// Whether each projection weighs only the input points on its query's side of a thin part:
  /// with input normals, the points whose normal makes more than \f$120^\circ\f$ with the sum of
  /// the normals of the 6 input points nearest to the query, and which lie more than \f$h/4\f$
  /// behind the fit's origin along it, are left out (the other side of a plate or blade a few
  /// spacings thick, which would pull the fit to its middle). No effect without input normals.
  /// Off by default: it also leaves out the other face of a convex crease sharper than
  /// \f$60^\circ\f$. `mls_surface_reconstruction()` turns it on.
  bool one_sided = false;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PROJECTION_OPTIONS_H
