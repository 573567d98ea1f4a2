// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_IMPLICIT_FUNCTION_OPTIONS_H
#define CGAL_MLS_PROJECTION_IMPLICIT_FUNCTION_OPTIONS_H

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
  /// Beyond this distance from the nearest seed (units of \f$h\f$), the value is blended
  /// towards the far value (distance to the nearest seed, signed by its local fit near the
  /// seed)...
  double far_start = 1.;
  /// ... which it reaches at this distance (units of \f$h\f$). The local fits are the
  /// surface within about \f$h\f$ of their data; further out, a wedge fan's sign is less reliable
  /// than the far value's. `mls_surface_reconstruction()` moves both out for an open surface.
  double far_end = 2.;
  /// With an operator that finds creases (the wedge fan, alone or mixed): project every seed with
  /// Levin's operator first and hand only the seeds its quadratic cannot fit (near creases and
  /// corners) to the operator (see `MLS_implicit_function`, "Screening by P_L"). `false`: the
  /// operator projects every seed (10 to 200 ms each).
  bool levin_screening = true;
  /// Project seeds into the gaps of the sampling (holes of a scan up to about \f$4h\f$ across),
  /// so that the local fits make the surface there (see `MLS_implicit_function`, "Gaps").
  /// `mls_surface_reconstruction()` turns it off for an open surface, which ends where its
  /// samples end.
  bool complete_gaps = true;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_IMPLICIT_FUNCTION_OPTIONS_H
