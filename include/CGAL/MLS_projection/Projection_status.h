// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PROJECTION_STATUS_H
#define CGAL_MLS_PROJECTION_PROJECTION_STATUS_H

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The outcome of one projection.
enum class Projection_status {
  /// The optimiser met its convergence criteria; the result is a local minimum of the energy.
  CONVERGED,
  /// The optimiser stopped at its iteration limit; the result is the best point found, finite.
  NOT_CONVERGED,
  /// A closest-point operator found no valid fit from any of its starts; the result is Levin's
  /// projection \f$\mathcal{P}_L\f$ of the query, with P_L's frame and fit (a success).
  LEVIN_FALLBACK,
  /// Fewer input points than the function space needs lie within the weight's support
  /// around the query's neighbourhood; the result keeps the query point and has a null normal.
  TOO_FEW_NEIGHBORS,
  /// The neighbourhood spans no hyperplane (all points equal, or collinear in 3D);
  /// the result keeps the query point and has a null normal.
  DEGENERATE_NEIGHBORHOOD,
  /// The query point has a NaN or infinite coordinate; the result keeps it, with a null normal.
  INVALID_QUERY
};

/// \ingroup PkgMLSProjectionRef
/// `true` when a projection with this status produced a usable point and normal.
inline bool is_success(Projection_status s) {
  return s == Projection_status::CONVERGED || s == Projection_status::NOT_CONVERGED ||
         s == Projection_status::LEVIN_FALLBACK;
}

/// \ingroup PkgMLSProjectionRef
/// A short English name of the status, for messages.
inline const char* to_string(Projection_status s) {
  switch(s) {
  case Projection_status::CONVERGED: return "converged";
  case Projection_status::NOT_CONVERGED: return "not converged";
  case Projection_status::LEVIN_FALLBACK: return "Levin fallback";
  case Projection_status::TOO_FEW_NEIGHBORS: return "too few neighbors";
  case Projection_status::DEGENERATE_NEIGHBORHOOD: return "degenerate neighborhood";
  case Projection_status::INVALID_QUERY: return "invalid query";
  }
  return "unknown";
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PROJECTION_STATUS_H
