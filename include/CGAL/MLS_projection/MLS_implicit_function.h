// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MLS_IMPLICIT_FUNCTION_H
#define CGAL_MLS_PROJECTION_MLS_IMPLICIT_FUNCTION_H

#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Implicit_function_options.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Normal_orientation_report.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Projection_result.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/internal/meshing/Lattice_value_cache.h>
#include <CGAL/MLS_projection/internal/projection/Levin_screened_projection.h>
#include <CGAL/MLS_projection/internal/projection/noise_level.h>
#include <CGAL/MLS_projection/internal/meshing/oriented_normals.h>
#include <CGAL/MLS_projection/project_points.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

/// The largest number of coefficients a cached local fit can hold.
constexpr int max_local_fit_parameters = 16;

/// The closest point of `y` (frame coordinates) on the graph of the full quadratic polynomial
/// `c` of `Polynomial_function_space<3>` (the second phase of Levin's projection): Newton
/// iterations on the squared distance from the vertical foot, with Gauss-Newton steps where its
/// Hessian is not positive definite, kept only while they decrease the distance.
inline Closest_point<3> polynomial_graph_closest_point(const double* c, const Vec<3>& y) {
  const auto f = [&](double u, double v) { return c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v; };
  double u = y[0], v = y[1];
  const auto dist2 = [&](double a, double b) {
    const double dz = f(a, b) - y[2];
    return (a - y[0]) * (a - y[0]) + (b - y[1]) * (b - y[1]) + dz * dz;
  };
  double best = dist2(u, v);
  for(int it = 0; it < 8; ++it) {
    const double fu = c[1] + 2 * c[3] * u + c[4] * v, fv = c[2] + c[4] * u + 2 * c[5] * v;
    const double e = f(u, v) - y[2];
    const double gu = (u - y[0]) + e * fu, gv = (v - y[1]) + e * fv;
    double a = 1 + fu * fu + e * 2 * c[3], b = fu * fv + e * c[4], d = 1 + fv * fv + e * 2 * c[5];
    double det = a * d - b * b;
    if(!(a > 0 && det > 1e-12)) { // Gauss-Newton
      a = 1 + fu * fu;
      b = fu * fv;
      d = 1 + fv * fv;
      det = a * d - b * b;
    }
    const double du = -(d * gu - b * gv) / det, dv = -(a * gv - b * gu) / det;
    const double nu = u + du, nv = v + dv, nd = dist2(nu, nv);
    if(!(nd < best)) break;
    const bool small = du * du + dv * dv <= 1e-24 * (1 + u * u + v * v);
    u = nu;
    v = nv;
    best = nd;
    if(small) break;
  }
  Closest_point<3> cp;
  cp.point = Vec<3>(u, v, f(u, v));
  const double fu = c[1] + 2 * c[3] * u + c[4] * v, fv = c[2] + c[4] * u + 2 * c[5] * v;
  cp.normal = Vec<3>(-fu, -fv, 1.).normalized();
  set_signed_distance(cp, y);
  return cp;
}

/// How the local fits of a projection operator are evaluated: `accepts(kind)` whether it reads
/// the fits of that kind, `unit()` the length unit of their coefficients and frame coordinates
/// (\f$h\f$ for the closest-point operators, which work in units of \f$h\f$, 1 for Levin's),
/// `closest_point()` the closest point on the member with coefficients `c` in frame coordinates,
/// in that unit.
template <class Projection> struct Local_fit_evaluator;

template <class GeomTraits>
struct Local_fit_evaluator<Levin_projection<GeomTraits, Polynomial_function_space<3>>> {
  explicit Local_fit_evaluator(const Levin_projection<GeomTraits, Polynomial_function_space<3>>&) {}
  static double unit(double) { return 1.; }
  static bool accepts(Local_fit_kind k) { return k == Local_fit_kind::LEVIN; }
  Closest_point<3> closest_point(const double* c, const Vec<3>& y) const { return polynomial_graph_closest_point(c, y); }
};

template <class GeomTraits>
struct Local_fit_evaluator<Levin_projection<GeomTraits, Plane_function_space<3>>> {
  explicit Local_fit_evaluator(const Levin_projection<GeomTraits, Plane_function_space<3>>&) {}
  static double unit(double) { return 1.; }
  static bool accepts(Local_fit_kind k) { return k == Local_fit_kind::LEVIN; }
  Closest_point<3> closest_point(const double*, const Vec<3>& y) const {
    return Plane_function_space<3>().closest_point(Plane_function_space<3>::Parameters(), y);
  }
};

// The members of a space prepared for many closest-point queries (`Prepared_member`, e.g. the
// wedge fan's vectors computed once from their angles), void when the space has none.
template <class S, class = void> struct prepared_member { using type = void; };
template <class S> struct prepared_member<S, std::void_t<typename S::Prepared_member>> {
  using type = typename S::Prepared_member;
};

template <class GeomTraits, class Space, Operator_kind kind>
struct Local_fit_evaluator<Closest_point_projection<GeomTraits, Space, kind>> {
  static_assert(Space::number_of_parameters <= max_local_fit_parameters, "too many parameters for a cached local fit");
  using Prepared = typename prepared_member<Space>::type;
  explicit Local_fit_evaluator(const Closest_point_projection<GeomTraits, Space, kind>& p) : space(p.function_space()) {}
  static double unit(double h) { return h; }
  static bool accepts(Local_fit_kind k) { return k == Local_fit_kind::CLOSEST_POINT; }
  Closest_point<3> closest_point(const double* c, const Vec<3>& y) const {
    return space.closest_point(Eigen::Map<const typename Space::Parameters>(c), y);
  }
  template <class S = Space>
  typename S::Prepared_member prepare(const double* c) const {
    return space.prepare_member(Eigen::Map<const typename Space::Parameters>(c));
  }
  template <class S = Space>
  Closest_point<3> closest_point(const typename S::Prepared_member& m, const Vec<3>& y) const {
    return space.closest_point(m, y);
  }
  Space space;
};

// The prepared member type of a local-fit evaluator (`Prepared`), void when it has none.
template <class E, class = void> struct evaluator_prepared { using type = void; };
template <class E> struct evaluator_prepared<E, std::void_t<typename E::Prepared>> { using type = typename E::Prepared; };

// The sharp fits of a mixed projection, in units of the sharp operator's bandwidth; its smooth
// fits are P_L's, which the screening evaluates.
template <class GeomTraits, Operator_kind kind, class Sharp>
struct Local_fit_evaluator<Mixed_projection<GeomTraits, 3, kind, Sharp>>
    : Local_fit_evaluator<typename Mixed_projection<GeomTraits, 3, kind, Sharp>::Sharp_projection> {
  explicit Local_fit_evaluator(const Mixed_projection<GeomTraits, 3, kind, Sharp>& p)
    : Local_fit_evaluator<typename Mixed_projection<GeomTraits, 3, kind, Sharp>::Sharp_projection>(p.sharp_projection()),
      sharp_h(p.sharp_bandwidth()) {}
  double unit(double) const { return sharp_h; }
  double sharp_h;
};

/// Wendland's \f$C^2\f$ function \f$(1-t)^4(4t+1)\f$ on \f$[0, 1]\f$, 0 beyond.
inline double wendland_c2(double t) {
  if(!(t < 1.)) return 0.;
  const double s = 1. - t;
  return s * s * s * s * (4. * t + 1.);
}

/// \f$3s^2 - 2s^3\f$ of \f$s\f$ clamped to \f$[0, 1]\f$.
inline double smoothstep(double s) {
  s = std::clamp(s, 0., 1.);
  return s * s * (3. - 2. * s);
}

/// The operator that projects the seeds of `MLS_implicit_function<Projection>`: screened by P_L
/// for the operators that find creases, the operator itself for the others.
template <class Projection, bool = finds_features<Projection>::value>
struct Seed_projection {
  using type = Levin_screened_projection<Projection>;
  static constexpr bool screens = true;
};
template <class Projection>
struct Seed_projection<Projection, false> {
  using type = Projection;
  static constexpr bool screens = false;
};

} // namespace internal

/// \ingroup PkgMLSProjectionRef
/// The MLS surface of a projection operator as an implicit function, a model of CGAL's
/// `ImplicitFunction` concept (`FT operator()(Point_3)`), negative inside, for CGAL's meshers
/// (see `mls_surface_reconstruction()`), in the manner of `Poisson_reconstruction_function`:
/// cheap to copy (its data are shared, immutable but for a thread-safe cache of far values,
/// behind a `std::shared_ptr`), `operator()` is `const`, safe to call from many threads at once,
/// and its values do not depend on the threads.
///
/// <b>Orientation.</b> The sign comes from a consistently oriented normal field on the samples:
/// the input normals when the sample set has some, otherwise normals estimated with
/// `pca_estimate_normals` and oriented along a minimum spanning forest of their neighbour graph
/// that never joins parts on which the free space around the points votes differently, each
/// tree turned outward as a whole (see the manual, section \ref MLSProjectionMeshing, and
/// `normals_report()`).
/// The normal of each local fit is flipped to agree with the oriented normals of the samples
/// nearest to its projected point (the sign of the sum of the dot products with the 6 nearest).
///
/// <b>Seeds.</b> At construction, the input samples thinned on a grid of cell
/// `seed_spacing`\f$\cdot h\f$ (one per occupied cell, the first in input order) are projected
/// once; each successful result keeps its local fit (frame and coefficients) and its oriented
/// normal. The oriented results are available as `projected_seeds()`, e.g. for the detection of
/// sharp features (project once, use twice). A local fit is blended (see below) only where it
/// agrees with the oriented normals of the samples within \f$2h\f$ of its projected point: for
/// each such sample \f$q\f$ with normal \f$n\f$, \f$q + n h/2\f$ must be outside the fit and
/// \f$q - n h/2\f$ inside, and the closest points of these points, and of the points
/// \f$h\f$ and \f$1.5h\f$ above and below the projected point, must lie on parts of the member less
/// steep than \f$75^\circ\f$ in its frame; at most 10% of the tests may fail. This drops the wedge
/// fans whose extension beyond their data turns the wrong side out (a fan fitted in the frame of
/// one face of a crease holds the other face perpendicular to its frame, a part whose side is
/// ill-defined), which put bubbles inside the solid and holes in its surface, and the fans that
/// fit noise (crumpled, in tilted frames). Where the operator's fit of a seed is dropped or its
/// projection failed, P_L's fit of the seed (computed by the screening, below) is blended in its
/// place when it passes the same test and its energy is at most \f$\mu^2 \hat\sigma^2\f$ (\f$\mu\f$ =
/// 3, \f$\hat\sigma^2\f$ as below): a fit of noise, not of a crease, which it
/// would round. On noiseless data \f$\hat\sigma^2\f$ is about 0 and no seed falls back; on noisy
/// data, many.
///
/// <b>Screening by P_L.</b> With an operator that finds creases (`Wedge_fan_function_space`
/// alone or in `Mixed_projection`) and `levin_screening` set (default), every seed is first
/// projected by Levin's operator \f$\mathcal{P}_L\f$ with a quadratic (some 0.3 ms, against 10
/// to 200 ms for the closest-point operators), and its fit is kept where it explains the data:
/// where its energy (weighted mean squared residual) is at most
/// \f$\max\big((0.01 h)^2, 2.5 \hat\sigma^2\big)\f$, with \f$\hat\sigma^2\f$ the variance of the noise
/// estimated from the input (see `Mixed_projection`, whose margin over the noise is 4, not 2.5: a
/// seed's fan also carries its crease to the feature detection). The other seeds (near creases and
/// corners, where a quadratic cannot follow the data) are projected by the operator; with
/// `Mixed_projection`, by its sharp operator only, the fan being kept when it beats P_L's
/// quadratic by the mixed operator's rule (`prefers_sharp()`). `seed_projection()` is that
/// screened operator, also used for the feature detection.
///
/// <b>Gaps.</b> With `complete_gaps` (default), the holes of the sampling get seeds too, as the
/// paper completes a gap by projection (its Figure 8): a blended seed whose neighbours within
/// \f$h\f$, seen in its tangent plane, leave more than \f$150^\circ\f$ free (the rim of a hole)
/// sends a query \f$h\f$ into the middle of that angle; its projection by the seed projection
/// becomes a seed (blended, and among `projected_seeds()`) when its energy is at most the bound of
/// a P_L fit blended in place of the operator's (a fan may converge to a wrong crease where the
/// data are sparse), its fit passes the test above, and it lies at least \f$h/2\f$ from every
/// seed and between \f$h\f$ and \f$2h\f$ from the samples; up to 6 rounds go on from the new
/// seeds. In a hole 2 to 4\f$h\f$ across, the surface is then made by fits that see both of its
/// sides, and a crease across it continues, instead of the far value.
///
/// <b>Evaluation, `LOCAL_FITS` (default).</b> With \f$s_1, \dots, s_{k+1}\f$ the \f$k+1\f$ nearest
/// seeds of \f$x\f$ (\f$k\f$ = 8) and \f$R\f$ the distance to the last,
/// \f[ f_{\mathrm{fit}}(x) = \frac{\sum_{i \le k} \phi(|x - s_i|/R)\, d_i(x)}{\sum_{i \le k} \phi(|x - s_i|/R)}, \f]
/// with \f$\phi\f$ Wendland's \f$C^2\f$ function (compact support: the weight of a seed vanishes
/// when it leaves the \f$k+1\f$ nearest, so \f$f\f$ is continuous) and \f$d_i(x)\f$ the signed
/// distance from \f$x\f$ to the local fit of seed \f$i\f$ (the function space's
/// `closest_point()`; for Levin's quadratic, a Newton iteration on the graph). Where the blended
/// fits are one and the same member (a sampled plane, or a sampled crease with the wedge fan),
/// \f$f\f$ is that member's exact signed distance. Far from the data, with \f$d\f$ the distance to
/// the nearest seed and \f$\lambda\f$ a smooth step from 0 at \f$d\f$ = `far_start`\f$\cdot h\f$ to
/// 1 at `far_end`\f$\cdot h\f$, \f$f = (1 - \lambda) f_{\mathrm{fit}} + \lambda\, f_{\mathrm{far}}\f$,
/// where \f$f_{\mathrm{far}}\f$ is \f$d\f$ signed by the majority of the 3 nearest seeds, each
/// by its local fit at the point \f$h/2\f$ from the seed towards \f$x\f$ (by its normal where
/// the fit is undecided there; not at all where \f$x\f$ is also within \f$15^\circ\f$ of the
/// normal's plane, and outside on a tie): cheap, not an extrapolated quadratic, unlike the seed's normal
/// right beyond a convex crease or corner, whose nearest seed sits on the crease with the normal
/// of one face, and, by the vote, robust to one bad fit (on noisy data, a fan fitted to the noise).
/// Where \f$f_{\mathrm{far}}\f$ at the 8 corners of the cell of \f$x\f$ in a lattice of spacing \f$h\f$
/// is beyond `far_end`\f$\cdot h\f$ plus the cell's diagonal, \f$f\f$ is their trilinear
/// interpolation, each computed once (the meshers evaluate many points deep inside, where the
/// nearest seeds are costly to find).
///
/// <b>Evaluation, `EXACT`.</b> \f$f(x) = \pm|x - P(x)|\f$, \f$P\f$ the projection, the sign that of
/// \f$(x - P(x))\cdot n\f$ with \f$n\f$ the result's normal oriented as above; where the projection
/// fails, the far value. As slow as the projection: the reference the local fits are measured
/// against (manual, section "Meshing").
///
/// \tparam Projection `Levin_projection<K, Polynomial_function_space<3>>`,
///         `Levin_projection<K, Plane_function_space<3>>`, `Closest_point_projection<K, S, kind>`
///         (e.g. `Unified_projection<K, S>`) or `Mixed_projection<K, 3>`, in 3D
template <class Projection>
class MLS_implicit_function {
  static_assert(Projection::dimension == 3, "MLS_implicit_function: a 3D projection operator");
  using Evaluator = internal::Local_fit_evaluator<Projection>;
  // The members of the operator's fits prepared once for the evaluations (see prepare_fits()).
  using Prepared = typename internal::evaluator_prepared<Evaluator>::type;
  static constexpr bool prepares = !std::is_void_v<Prepared>;
  static constexpr bool screens = internal::Seed_projection<Projection>::screens;
  // Gap completion (see complete_gaps()): the free angle that makes a seed a rim seed (the
  // neighbours of a seed inside a random sampling leave less than half a turn free); the step
  // into the gap (units of h, as the next four); the least distance from a gap seed to the other
  // seeds (their spacing); its least distance to the samples: a gap, not one of the empty discs
  // of a random sampling (of which 2% of the surface lies further than h = 2.2 spacings from every
  // sample); its largest distance to the samples (gaps up to 4h across, the support of the
  // projection, whose fits see both sides); the rounds.
  static constexpr double gap_angle = 150.;
  static constexpr double gap_step = 1.;
  static constexpr double gap_apart = 0.5;
  static constexpr double gap_empty = 1.;
  static constexpr double gap_reach = 2.;
  static constexpr int gap_rounds = 6;
  // The seeds blended by the partition of unity at a point (its weights reach 0 at the last).
  static constexpr std::size_t blend_neighbors = 8;
  // Where a seed's fit is dropped, P_L's fit stands in when its energy is at most this factor
  // squared times the noise variance: a fit of the noise (about 0 without noise), not of a crease,
  // which it would round.
  static constexpr double fallback_noise_factor = 3.;
  using V = internal::Vec<3>;
  using M = internal::Mat<3>;

public:
  /// The projection operator, its kernel and the kernel's types, its sample set and result.
  /// @{
  using Projection_type = Projection;
  using Geom_traits = typename Projection::Samples::Geom_traits;
  using FT = typename Geom_traits::FT;
  using Point_3 = typename Geom_traits::Point_3;
  using Point = Point_3;
  using Vector_3 = typename Geom_traits::Vector_3;
  using Sphere_3 = typename Geom_traits::Sphere_3;
  using Samples = typename Projection::Samples;
  using Result = Projection_result<Geom_traits, 3>;
  /// @}
  /// The operator that projects the seeds: for the operators that find creases, an unspecified
  /// operator that projects with Levin's operator first and with `Projection` where P_L's fit is
  /// rejected (see "Screening by P_L"; the screening can be off: see `Implicit_function_options`),
  /// `Projection` for the others. It has the members of the operators that
  /// `detect_sharp_features()` and `interpolate_attributes()` use (`project()`, `samples()`,
  /// `bandwidth()`).
#ifdef DOXYGEN_RUNNING
  using Seed_projection_type = unspecified_type;
#else
  using Seed_projection_type = typename internal::Seed_projection<Projection>::type;
#endif

  /// The state after construction.
  enum class Status {
    VALID,             ///< ready
    CANCELLED,         ///< the callback returned `false`
    TOO_FEW_SEEDS,     ///< fewer than 2 seeds could be projected (too few or degenerate samples)
    NO_BANDWIDTH       ///< the operator has no bandwidth (fewer than two distinct samples)
  };

  /// Projects the seeds with `projection` (in parallel with `CGAL::Parallel_tag`) and builds
  /// the seed tree. `callback` (may be empty) is called from the calling thread with the
  /// fraction done in [0, 1] (the normal estimation, when needed, is its first 20%); returning
  /// `false` cancels: `status()` is then `CANCELLED`. Check `is_valid()` before use; an invalid
  /// function returns 1 everywhere (outside).
  template <class ConcurrencyTag = Sequential_tag>
  explicit MLS_implicit_function(const Projection& projection,
                                 const Implicit_function_options& options = Implicit_function_options(),
                                 ConcurrencyTag tag = ConcurrencyTag(),
                                 const std::function<bool(double)>& callback = std::function<bool(double)>()) {
    auto data = std::make_shared<Data>(projection, options);
    build(*data, tag, callback);
    data_ = std::move(data);
  }

  /// \f$f(p)\f$: negative inside, positive outside, in length units (see the class documentation).
  FT operator()(const Point_3& p) const {
    const Data& d = *data_;
    if(d.status != Status::VALID) return FT(1);
    if(d.options.mode == Implicit_function_mode::EXACT) return FT(exact_value(p));
    return FT(local_fit_value(p));
  }

  /// \f$f(p)\f$ from the local fits, whatever the mode.
  double local_fit_value(const Point_3& p) const {
    const Data& d = *data_;
    if(d.status != Status::VALID) return 1.;
    const V x = d.seeds->to_local(p);
    if(!x.allFinite()) return std::numeric_limits<double>::max();
    thread_local std::vector<std::size_t> idx;
    constexpr std::size_t k = blend_neighbors;
    // the k + 1 nearest seeds, searched within far_end h + 2h only: beyond, x is in the far region
    d.seeds->k_nearest(x, k + 1, idx, (d.options.far_end + 2.) * d.h);
    if(idx.empty() || !((x - d.fits[idx[0]].point).norm() < d.options.far_end * d.h)) return far_region_value(x);
    if(idx.size() < k + 1) d.seeds->k_nearest(x, k + 1, idx); // isolated seeds
    // distances, the nearest seed, and R = the largest distance (the (k+1)-th seed)
    std::array<double, 64> dist;
    const std::size_t m = (std::min<std::size_t>)(idx.size(), dist.size());
    std::size_t nearest = 0;
    double R = 0;
    for(std::size_t j = 0; j < m; ++j) {
      dist[j] = (x - d.fits[idx[j]].point).norm();
      if(dist[j] < dist[nearest]) nearest = j;
      R = (std::max)(R, dist[j]);
    }
    const double dmin = dist[nearest];
    const double lambda =
      internal::smoothstep((dmin - d.options.far_start * d.h) / ((d.options.far_end - d.options.far_start) * d.h));
    const auto far = [&] {
      // the majority of the 3 nearest seeds' signs
      std::array<std::size_t, 64> order;
      for(std::size_t j = 0; j < m; ++j) order[j] = j;
      const std::size_t voters = (std::min<std::size_t>)(3, m);
      std::partial_sort(order.begin(), order.begin() + voters, order.begin() + m,
                        [&](std::size_t a, std::size_t b) { return dist[a] < dist[b]; });
      double vote = 0;
      for(std::size_t j = 0; j < voters; ++j) vote += far_sign(d, d.fits[idx[order[j]]], x);
      return (vote < 0 ? -1. : 1.) * dmin;
    };
    if(lambda >= 1. || m < 2) return far();
    double W = 0, F = 0;
    for(std::size_t j = 0; j < m; ++j) {
      const double w = R > 0 ? internal::wendland_c2(dist[j] / R) : 1.;
      if(!(w > 0)) continue;
      W += w;
      F += w * fit_distance(d, d.fits[idx[j]], x);
    }
    const double blend = W > 0 ? F / W : far();
    const double value = lambda > 0. ? (1. - lambda) * blend + lambda * far() : blend;
    return std::isfinite(value) ? value : far();
  }

  /// \f$f(p)\f$ from a projection of `p`, whatever the mode (see `Implicit_function_mode::EXACT`).
  double exact_value(const Point_3& p) const {
    const Data& d = *data_;
    if(d.status != Status::VALID) return 1.;
    const Result r = d.projection.project(p);
    const V x = d.seeds->to_local(p);
    if(!x.allFinite()) return std::numeric_limits<double>::max();
    if(!r.is_success()) return far_value(x);
    const V P = d.seeds->to_local(r.point);
    V n = internal::Kernel_types<Geom_traits, 3>::to_eigen(r.normal);
    if(orientation_vote(d, d.projection.samples().to_local(r.point), n) < 0) n = -n;
    const V e = x - P;
    const double value = (e.dot(n) < 0 ? -1. : 1.) * e.norm();
    return std::isfinite(value) ? value : far_value(x);
  }

  /// A sphere enclosing the data with a margin of `far_end`\f$\cdot h\f$: on and beyond its
  /// boundary, \f$f\f$ is the far value (positive for a closed, outward oriented surface).
  Sphere_3 bounding_sphere() const { return data_->sphere; }

  /// A point where \f$f < 0\f$, as deep inside as found: among points \f$s - t\,n\f$ below the
  /// seeds (\f$t\f$ from \f$h/2\f$ doubling up to the bounding radius, at most 64 seeds), the one of
  /// lowest \f$f\f$. The centre of the bounding sphere when the function is not valid.
  Point_3 get_inner_point() const { return data_->inner_point; }

  /// The results of the seed projections, in world coordinates, their normals oriented as the
  /// function's (outward): where P_L's fit is blended in place of the operator's (see "Seeds"),
  /// P_L's result. Failed projections are left out; the unblended seeds are in.
  const std::vector<Result>& projected_seeds() const { return data_->projected; }

  /// The projection operator.
  const Projection& projection() const { return data_->projection; }
  /// The operator that projected the seeds (see "Screening by P_L"); only on a function whose
  /// seeds were projected (`status()` neither `NO_BANDWIDTH` nor `TOO_FEW_SEEDS` before them).
  const Seed_projection_type& seed_projection() const { return *data_->seed_projection; }
  /// Whether `seed_projection()` may be called.
  bool has_seed_projection() const { return bool(data_->seed_projection); }
  /// The number of seeds projected by the closest-point operator (all seeds without screening).
  std::size_t number_of_operator_seeds() const { return data_->operator_seeds; }
  /// The energy threshold of the screening (absolute squared length); negative without screening.
  double screening_threshold() const { return data_->threshold; }
  /// The options given at construction.
  const Implicit_function_options& options() const { return data_->options; }
  /// The bandwidth \f$h\f$ of the operator.
  double bandwidth() const { return data_->h; }
  /// The state after construction.
  Status status() const { return data_->status; }
  /// `status() == Status::VALID`.
  bool is_valid() const { return data_->status == Status::VALID; }
  /// The number of seeds whose local fits are blended.
  std::size_t number_of_seeds() const { return data_->fits.size(); }
  /// The number of seeds projected successfully whose local fit is not blended, because it
  /// disagrees with the oriented normals of the samples around it (see "Seeds"), and whose
  /// P_L fit does not agree either (or was not computed); their projections are among
  /// `projected_seeds()`.
  std::size_t number_of_unblended_seeds() const { return data_->unblended; }
  /// The number of seeds whose projection failed (not in `projected_seeds()`) and whose P_L fit
  /// is not blended either.
  std::size_t number_of_failed_seeds() const { return data_->failed; }
  /// The number of seeds blended with P_L's fit in place of the operator's, which failed or
  /// disagreed with the sample normals (see "Seeds"); counted in `number_of_seeds()`.
  std::size_t number_of_levin_fallbacks() const { return data_->levin_fallbacks; }
  /// The number of seeds projected into the gaps of the sampling (see "Gaps"); counted in
  /// `number_of_seeds()`.
  std::size_t number_of_gap_seeds() const { return data_->gap_seeds; }
  /// What the estimation of oriented normals did (all zero when the samples carry normals).
  const Normal_orientation_report& normals_report() const { return data_->normals_report; }

private:
  struct Fit {
    V point = V::Zero();  // the projected seed (seed-local coordinates)
    V normal = V::Zero(); // its oriented unit normal
    V origin = V::Zero(); // the fit's frame origin (seed-local)
    M axes = M::Identity(); // columns: tangents, frame normal
    double unit = 1;        // the length unit of the coefficients
    double sign = 1;        // +1 when the space's "up" side is outside
    int count = 0;          // the number of coefficients (0: the frame's plane)
    Local_fit_kind kind = Local_fit_kind::NONE;
    std::array<double, internal::max_local_fit_parameters> c{};
    std::uint32_t prepared = no_prepared; // its member in Data::prepared, if any
  };
  static constexpr std::uint32_t no_prepared = std::numeric_limits<std::uint32_t>::max();

  struct Data {
    Data(const Projection& p, const Implicit_function_options& o)
      : projection(p), evaluator(p), options(o), h(p.bandwidth()), far_corners(h > 0 && std::isfinite(h) ? h : 1.) {}
    Projection projection;
    Evaluator evaluator;
    Implicit_function_options options;
    double h;
    mutable internal::Lattice_value_cache far_corners; // see far_region_value()
    std::vector<V> sample_normals; // oriented, indexed like the samples (local coordinates)
    std::shared_ptr<const Samples> seeds; // the projected seeds and their kd-tree
    std::vector<Fit> fits;                // indexed like `seeds`
    std::vector<std::conditional_t<prepares, Prepared, char>> prepared; // the fits' prepared members
    std::vector<Result> projected;
    std::size_t failed = 0;
    std::size_t unblended = 0;
    std::size_t levin_fallbacks = 0;
    std::size_t gap_seeds = 0;
    std::optional<Seed_projection_type> seed_projection;
    std::size_t operator_seeds = 0;
    double threshold = -1;
    double fallback_threshold = -1; // the largest energy of a P_L fit blended in place of the operator's
    Normal_orientation_report normals_report;
    Sphere_3 sphere;
    Point_3 inner_point;
    Status status = Status::VALID;
  };

  // A fit of the screening's P_L quadratic among the fits of a screened operator.
  static bool is_screening_fit(Local_fit_kind kind) { return screens && kind == Local_fit_kind::LEVIN; }

  static Closest_point<3> fit_closest_point(const Data& d, const Fit& f, const V& y) {
    if(is_screening_fit(f.kind)) return internal::polynomial_graph_closest_point(f.c.data(), y);
    if constexpr(prepares)
      if(f.prepared != no_prepared) return d.evaluator.closest_point(d.prepared[f.prepared], y);
    return d.evaluator.closest_point(f.c.data(), y);
  }

  // Whether the member of `f` can be prepared: a fit of the operator's space that can.
  static bool is_preparable(const Fit& f) {
    return prepares && f.count > 0 && !is_screening_fit(f.kind) && Evaluator::accepts(f.kind);
  }

  // Prepares the members of the seeds' fits once (the meshers evaluate each fit thousands of
  // times; a wedge fan's vectors come from their angles by trigonometry), when the space can.
  static void prepare_fits(Data& d) {
    if constexpr(prepares) {
      for(Fit& f : d.fits) {
        if(!is_preparable(f)) continue;
        f.prepared = std::uint32_t(d.prepared.size());
        d.prepared.push_back(d.evaluator.prepare(f.c.data()));
      }
    }
  }

  // The closest points on the fit `f` (frame coordinates, in its unit), its member prepared once
  // here when not yet: for the many points of one fit that agrees_with_normals() tests.
  class Fit_closest_points {
  public:
    Fit_closest_points(const Data& d, const Fit& f) : d_(d), f_(f) {
      if constexpr(prepares)
        if(f.prepared == no_prepared && is_preparable(f)) member_ = d.evaluator.prepare(f.c.data());
    }
    Closest_point<3> operator()(const V& y) const {
      if constexpr(prepares)
        if(member_) return d_.evaluator.closest_point(*member_, y);
      return fit_closest_point(d_, f_, y);
    }

  private:
    const Data& d_;
    const Fit& f_;
    std::optional<std::conditional_t<prepares, Prepared, char>> member_;
  };

  static double fit_distance(const Data& d, const Fit& f, const V& x) {
    if(f.count == 0) return f.sign * f.axes.col(2).dot(x - f.origin); // a plane (e.g. Levin's fall-back)
    const V y = f.axes.transpose() * (x - f.origin) / f.unit;
    return f.sign * f.unit * fit_closest_point(d, f, y).signed_distance;
  }

  // The sign of f at `x` as the nearest seed's fit `f` tells it: that of the fit's signed
  // distance at the point h/2 from the seed towards `x` (where the fit still explains its data:
  // at a crease, the fan tells a convex crease's outside from its inside; the seed's normal alone
  // would put the space beyond the other face inside), or of the normal where that is undecided;
  // 0 (no vote) where `x` is also within 15 degrees of the normal's plane: beyond a knife edge,
  // seeds on the edge see `x` sideways, and a guess put space far out of the part inside.
  static double far_sign(const Data& d, const Fit& f, const V& x) {
    const V e = x - f.point;
    const double n = e.norm();
    if(n > 0) {
      const double v = fit_distance(d, f, V(f.point + (0.5 * d.h / n) * e));
      if(std::isfinite(v) && std::abs(v) > 0.05 * d.h) return v < 0 ? -1. : 1.;
    }
    const double c = e.dot(f.normal);
    return std::abs(c) < 0.25 * n ? 0. : c < 0 ? -1. : 1.;
  }

  // The far value: the distance to the nearest seed, signed by the majority of the 3 nearest
  // (outside on a tie).
  double far_value(const V& x) const {
    const Data& d = *data_;
    thread_local std::vector<std::size_t> idx;
    d.seeds->k_nearest(x, 3, idx);
    if(idx.empty()) return 1.;
    double vote = 0, dmin = std::numeric_limits<double>::infinity();
    for(std::size_t i : idx) {
      vote += far_sign(d, d.fits[i], x);
      dmin = (std::min)(dmin, (x - d.fits[i].point).norm());
    }
    return (vote < 0 ? -1. : 1.) * dmin;
  }

  // The far value where no seed is within far_end h of `x`: when the far values at the 8 corners
  // of the cell of `x` in a lattice of spacing h are all beyond far_end h + the cell's diagonal
  // (so is then the whole cell), their trilinear interpolation (continuous: the meshers' root
  // finding needs no cell faces for surfaces); else `far_value(x)`. The corner values are
  // computed once: Mesh_3 labels its cells at their circumcentres, near the medial axis deep
  // inside, where many seeds are almost as near as the nearest and a query of the nearest seeds
  // costs some ten times one near the surface.
  double far_region_value(const V& x) const {
    const Data& d = *data_;
    const double e = d.far_corners.spacing();
    const double reach = d.options.far_end * d.h + std::sqrt(3.) * e;
    const V g = x / e;
    std::array<double, 3> base;
    for(int j = 0; j < 3; ++j) {
      base[j] = std::floor(g[j]);
      if(!(std::abs(base[j]) + 1 < internal::Lattice_value_cache::max_index)) return far_value(x);
    }
    const V t(g[0] - base[0], g[1] - base[1], g[2] - base[2]);
    double value = 0;
    for(int c = 0; c < 8; ++c) {
      const std::array<double, 3> node{base[0] + (c & 1), base[1] + ((c >> 1) & 1), base[2] + ((c >> 2) & 1)};
      const double v = d.far_corners.value(node, [&](const V& p) {
        const double f = far_value(p);
        return std::abs(f) >= reach ? f : 0.; // 0: the node is not far enough
      });
      if(v == 0) return far_value(x);
      value += v * ((c & 1) ? t[0] : 1 - t[0]) * (((c >> 1) & 1) ? t[1] : 1 - t[1]) * (((c >> 2) & 1) ? t[2] : 1 - t[2]);
    }
    return value;
  }

  // The oriented fit of a seed's result `r`, with its projected point `P` and oriented normal `rn`
  // (sample-local); false when the result or its fit is unusable.
  static bool make_fit(const Data& d, const Result& r, Fit& f, V& P, V& rn) {
    using KT = internal::Kernel_types<Geom_traits, 3>;
    const Samples& samples = d.projection.samples();
    f.count = int(r.coefficients.size());
    f.kind = r.fit_kind;
    // no coefficients: a plane (the closest-point operators fall back on Levin's plane)
    if(!r.is_success() || !(f.count == 0 || is_screening_fit(f.kind) || Evaluator::accepts(f.kind)) ||
       f.count > internal::max_local_fit_parameters)
      return false;
    P = samples.to_local(r.point);
    f.axes.col(0) = KT::to_eigen(r.frame.tangents[0]);
    f.axes.col(1) = KT::to_eigen(r.frame.tangents[1]);
    f.axes.col(2) = KT::to_eigen(r.frame.normal);
    f.origin = samples.to_local(r.frame.origin);
    f.unit = f.kind == Local_fit_kind::LEVIN ? 1. : d.evaluator.unit(d.h);
    std::copy(r.coefficients.begin(), r.coefficients.end(), f.c.begin());
    // the "up" normal of the fit at the projected point, and its orientation
    Closest_point<3> cp;
    if(f.count == 0) {
      cp.normal = V(0, 0, 1);
      cp.signed_distance = f.axes.col(2).dot(P - f.origin) / f.unit;
    } else {
      cp = fit_closest_point(d, f, V(f.axes.transpose() * (P - f.origin) / f.unit));
    }
    const V up = f.axes * cp.normal;
    rn = KT::to_eigen(r.normal);
    double vote = orientation_vote(d, P, up);
    if(vote == 0) vote = up.dot(rn) < 0 ? -1. : 1.; // no sample normal decides: the operator's
    f.sign = vote;
    if(rn.dot(up) * vote < 0) rn = -rn;
    f.point = P; // converted to seed-local coordinates by the caller
    f.normal = rn;
    // the fit must pass through its own projection
    return P.allFinite() && f.origin.allFinite() && f.axes.allFinite() && up.allFinite() && rn.allFinite() &&
           std::abs(cp.signed_distance) * f.unit <= 0.1 * d.h;
  }

  // Whether the oriented fit `f` (sample-local coordinates) agrees with the oriented normals of
  // the samples within 2h of its projected point `P`: each sample q with normal n must have
  // q + n h/2 outside of the fit and q - n h/2 inside, and the closest points of these test
  // points, and of P + t n and P - t n for t = h, 1.5h (the blend's reach), must lie on parts of
  // the member less steep than 75 degrees in its frame (the side of a part perpendicular to the
  // frame, e.g. a thin vertical cone of a wedge fan, is ill-defined). A fit that fails more than
  // 10% of the tests would carry the wrong sign into the blend. With `one_sided` projections,
  // only the samples on the side of `P` are tested (those the fit saw).
  static bool agrees_with_normals(const Data& d, const Fit& f, const V& P, const V& nP) {
    if(d.sample_normals.empty() || f.count == 0) return true;
    std::size_t wrong = 0, tests = 0;
    const Fit_closest_points closest(d, f);
    const auto test = [&](const V& x, int expected) {
      ++tests;
      const Closest_point<3> cp = closest(V(f.axes.transpose() * (x - f.origin) / f.unit));
      if(!(cp.normal[2] >= 0.25) || (expected != 0 && !(f.sign * cp.signed_distance * expected > 0))) ++wrong;
    };
    thread_local std::vector<std::size_t> idx;
    const V side = d.projection.options().one_sided && d.projection.samples().has_normals()
                     ? internal::side_at<3>(d.projection.samples(), P)
                     : V(V::Zero());
    idx.clear();
    d.projection.samples().in_ball(P, 2 * d.h, idx);
    for(std::size_t i : idx) {
      const V& n = d.sample_normals[i];
      const V& q = d.projection.samples().local_point(i);
      if(!(n.squaredNorm() > 0.25) ||
         (n.dot(side) < internal::other_side_cosine && (q - P).dot(side) < -internal::other_side_depth * d.h))
        continue;
      test(V(q + 0.5 * d.h * n), 1);
      test(V(q - 0.5 * d.h * n), -1);
    }
    for(double t : {1., 1.5}) {
      test(V(P + t * d.h * nP), 0);
      test(V(P - t * d.h * nP), 0);
    }
    return 10 * wrong <= tests;
  }

  // The sign of the sum of the dot products of `n` with the oriented normals of the 6 samples
  // nearest to `q` (sample-local coordinates); 0 when undecided.
  static double orientation_vote(const Data& d, const V& q, const V& n) {
    if(d.sample_normals.empty()) return 0.;
    thread_local std::vector<std::size_t> idx;
    d.projection.samples().k_nearest(q, 6, idx);
    double s = 0;
    for(std::size_t i : idx) s += d.sample_normals[i].dot(n);
    return s > 0 ? 1. : (s < 0 ? -1. : 0.);
  }

  template <class ConcurrencyTag>
  static void build(Data& d, ConcurrencyTag, const std::function<bool(double)>& callback) {
    using KT = internal::Kernel_types<Geom_traits, 3>;
    const Samples& samples = d.projection.samples();
    const std::size_t n = samples.size();
    d.sphere = Sphere_3(ORIGIN, 1);
    d.inner_point = ORIGIN;
    if(!(d.h > 0) || !std::isfinite(d.h)) {
      d.status = n < 2 ? Status::TOO_FEW_SEEDS : Status::NO_BANDWIDTH;
      return;
    }
    // 1. oriented normals of the samples
    double start = 0;
    d.sample_normals.resize(n);
    if(samples.has_normals()) {
      for(std::size_t i = 0; i < n; ++i) d.sample_normals[i] = samples.local_normal(i);
    } else {
      std::vector<Point_3> world(n);
      std::vector<Vector_3> normals;
      for(std::size_t i = 0; i < n; ++i) world[i] = samples.to_world(samples.local_point(i));
      const auto sub = [&](double f) { return !callback || callback(0.2 * f); };
      d.normals_report = internal::estimate_oriented_normals<ConcurrencyTag, Geom_traits>(
        world, normals, internal::normal_neighbors, sub);
      if(!d.normals_report.completed) {
        d.status = Status::CANCELLED;
        return;
      }
      for(std::size_t i = 0; i < n && i < normals.size(); ++i) d.sample_normals[i] = KT::to_eigen(normals[i]);
      start = 0.2;
    }

    // 2. seeds: one sample per occupied grid cell, the first in input order
    std::vector<std::size_t> seed_index;
    const double cell = d.options.seed_spacing * d.h;
    if(cell > 0) {
      std::unordered_map<std::uint64_t, std::size_t> occupied;
      occupied.reserve(n);
      for(std::size_t i = 0; i < n; ++i) {
        const V& p = samples.local_point(i);
        std::uint64_t key = 0;
        for(int j = 0; j < 3; ++j) {
          const double c = std::floor(p[j] / cell);
          const std::int64_t ic = std::int64_t(std::clamp(c, -1e6, 1e6)) + (std::int64_t(1) << 20);
          key = (key << 21) | (std::uint64_t(ic) & ((std::uint64_t(1) << 21) - 1));
        }
        if(occupied.emplace(key, i).second) seed_index.push_back(i);
      }
    } else {
      seed_index.resize(n);
      for(std::size_t i = 0; i < n; ++i) seed_index[i] = i;
    }

    // 3. project the seeds, in chunks so that the callback is called often
    std::vector<Point_3> queries(seed_index.size());
    for(std::size_t j = 0; j < seed_index.size(); ++j) queries[j] = samples.to_world(samples.local_point(seed_index[j]));
    std::vector<Result> results, levin_results;
    if(!project_seeds(d, ConcurrencyTag(), queries, results, levin_results, callback, start)) {
      d.status = Status::CANCELLED;
      return;
    }

    // 4. the local fits, oriented
    std::vector<Point_3> seed_points;
    std::vector<Fit> fits;
    // The fit each seed blends: the operator's, else P_L's in its place (if it agrees), else none.
    // Tested in parallel, kept in seed order.
    enum Kept : std::uint8_t { NONE, OPERATOR, LEVIN };
    std::vector<Fit> seed_fits(results.size());
    std::vector<std::uint8_t> usable(results.size()), kept(results.size(), NONE);
    internal::for_each_index<ConcurrencyTag>(0, results.size(), 16, [&](std::size_t j) {
      Result& r = results[j];
      Fit& f = seed_fits[j];
      V P, rn;
      usable[j] = make_fit(d, r, f, P, rn);
      if(usable[j]) r.normal = KT::to_vector(rn);
      if(usable[j] && agrees_with_normals(d, f, P, rn)) {
        kept[j] = OPERATOR;
        return;
      }
      V Pg, ng;
      if(j < levin_results.size() && levin_results[j].is_success() && levin_results[j].energy <= d.fallback_threshold &&
         make_fit(d, levin_results[j], f, Pg, ng) && agrees_with_normals(d, f, Pg, ng)) {
        kept[j] = LEVIN;
        levin_results[j].normal = KT::to_vector(ng);
      }
    });
    std::size_t m = 0; // the kept fits, moved to the front in place
    for(std::size_t j = 0; j < results.size(); ++j) {
      // the result whose fit is blended: the feature detection then finds no crease that f rounds
      if(kept[j] == LEVIN) d.projected.push_back(levin_results[j]);
      else if(usable[j]) d.projected.push_back(results[j]);
      if(kept[j] == NONE) {
        ++(usable[j] ? d.unblended : d.failed);
        continue;
      }
      if(kept[j] == LEVIN) ++d.levin_fallbacks;
      seed_points.push_back(kept[j] == LEVIN ? levin_results[j].point : results[j].point);
      if(m != j) seed_fits[m] = seed_fits[j];
      ++m;
    }
    seed_fits.resize(m);
    fits = std::move(seed_fits);
    if(d.options.complete_gaps) complete_gaps(d, ConcurrencyTag(), seed_points, fits);
    if(fits.size() < 2) {
      d.status = Status::TOO_FEW_SEEDS;
      return;
    }
    d.seeds = std::make_shared<const Samples>(seed_points);
    // sample-local -> seed-local coordinates
    const V shift = samples.centre() - d.seeds->centre();
    for(Fit& f : fits) {
      f.point += shift;
      f.origin += shift;
    }
    // Sample_set drops nothing here (the points are finite), so the indices agree
    CGAL_assertion(d.seeds->size() == fits.size());
    d.fits = std::move(fits);
    prepare_fits(d);

    // 5. bounding sphere and inner point
    V lo = V::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for(std::size_t i = 0; i < n; ++i) {
      lo = lo.cwiseMin(samples.local_point(i));
      hi = hi.cwiseMax(samples.local_point(i));
    }
    const V c = 0.5 * (lo + hi);
    const double radius = 0.5 * (hi - lo).norm() + d.options.far_end * d.h;
    d.sphere = Sphere_3(samples.to_world(c), radius * radius);
    d.inner_point = samples.to_world(c);
    MLS_implicit_function self(d);
    double best = self.local_fit_value(d.inner_point);
    const std::size_t stride = (std::max<std::size_t>)(1, d.fits.size() / 64);
    for(std::size_t i = 0; i < d.fits.size(); i += stride) {
      const Fit& f = d.fits[i];
      for(double t = 0.5 * d.h; t <= 2 * radius; t *= 2) {
        const Point_3 q = d.seeds->to_world(V(f.point - t * f.normal));
        const double v = self.local_fit_value(q);
        if(v < best) {
          best = v;
          d.inner_point = q;
        }
      }
    }
    if(callback && !callback(1.)) d.status = Status::CANCELLED;
  }

  // Gap completion: seeds projected into the gaps of the sampling (the holes of a scan), so that
  // local fits, not the far value, make the surface there and a crease crossing a gap goes on
  // across it (the paper's Figure 8). A seed whose neighbours within h, seen in its tangent plane,
  // leave an angle of more than `gap_angle` free (the rim of a gap) sends a query `gap_step` h
  // into the middle of that angle. Its projection becomes a seed, as a seed of the samples would,
  // if its fit explains its data within the noise and agrees with the normals, and it lies at
  // least `gap_apart` h from every seed, between `gap_empty` h and `gap_reach` h from the
  // samples; rounds go on from the new seeds.
  template <class ConcurrencyTag>
  static void complete_gaps(Data& d, ConcurrencyTag, std::vector<Point_3>& seed_points, std::vector<Fit>& fits) {
    using KT = internal::Kernel_types<Geom_traits, 3>;
    const Samples& samples = d.projection.samples();
    const double h = d.h, apart2 = gap_apart * gap_apart * h * h;
    // a gap seed's fit must explain its data within the noise (a fan may converge to a wrong
    // crease where the data are sparse): the bound of a P_L fit blended in place of a seed's
    const double max_energy = d.fallback_threshold >= 0 ? d.fallback_threshold : std::numeric_limits<double>::infinity();
    std::vector<V> points; // the seeds' projected points (sample-local)
    for(const Fit& f : fits) points.push_back(f.point);
    std::vector<std::pair<double, std::size_t>> near;
    std::vector<double> angles;
    const auto far_from = [&](const internal::Point_tree<3>& tree, const V& x, std::size_t from) {
      tree.k_nearest(x, 1, near);
      if(!near.empty() && near[0].first < apart2) return false;
      for(std::size_t j = from; j < points.size(); ++j) // this round's, not in the tree
        if((points[j] - x).squaredNorm() < apart2) return false;
      return true;
    };
    for(std::size_t begin = 0, round = 0; round < gap_rounds && begin < points.size(); ++round) {
      const internal::Point_tree<3> tree(points);
      const std::size_t end = points.size();
      std::vector<Point_3> queries;
      for(std::size_t i = begin; i < end; ++i) {
        const V& P = points[i];
        const V& n = fits[i].normal;
        const V t0 = (std::abs(n[0]) < 0.9 ? V(1, 0, 0) : V(0, 1, 0)).cross(n).normalized(), t1 = n.cross(t0);
        angles.clear();
        tree.for_each_in_ball(P, h, [&](std::size_t j, const V& q) {
          if(j != i) angles.push_back(std::atan2((q - P).dot(t1), (q - P).dot(t0)));
        });
        if(angles.size() < 3) continue;
        std::sort(angles.begin(), angles.end());
        double gap = angles.front() + 2 * CGAL_PI - angles.back(), middle = angles.back() + 0.5 * gap;
        for(std::size_t k = 1; k < angles.size(); ++k)
          if(angles[k] - angles[k - 1] > gap) {
            gap = angles[k] - angles[k - 1];
            middle = angles[k - 1] + 0.5 * gap;
          }
        const V q = P + gap_step * h * (std::cos(middle) * t0 + std::sin(middle) * t1);
        if(gap > gap_angle * CGAL_PI / 180. && far_from(tree, q, end) &&
           samples.kth_neighbor_distance(q, 1) >= gap_empty * h) {
          points.push_back(q); // held back from the tree until the next round, to thin the queries
          queries.push_back(samples.to_world(q));
        }
      }
      points.resize(end);
      if(queries.empty()) break;
      std::vector<Result> results;
      project_points<ConcurrencyTag>(*d.seed_projection, queries, std::back_inserter(results));
      for(Result& r : results) {
        Fit f;
        V P, rn;
        if(!(r.energy <= max_energy) || !make_fit(d, r, f, P, rn) || !far_from(tree, P, end)) continue;
        const double to_samples = samples.kth_neighbor_distance(P, 1);
        if(to_samples < gap_empty * h || to_samples > gap_reach * h || !agrees_with_normals(d, f, P, rn)) continue;
        r.normal = KT::to_vector(rn);
        d.projected.push_back(r);
        seed_points.push_back(r.point);
        fits.push_back(f);
        points.push_back(P);
        ++d.gap_seeds;
      }
      begin = end;
    }
  }

  // Projects `queries` with the seed projection (built here: its screening threshold comes from
  // the seeds), in chunks so that the callback (fractions from `start` to 0.95) is called often:
  // 128 queries, or 8 blocks of warm starts for an operator that has them (project_points() runs
  // a block per task: a chunk of one block would run on one thread). False when cancelled.
  template <class ConcurrencyTag>
  static bool project_seeds(Data& d, ConcurrencyTag, const std::vector<Point_3>& queries, std::vector<Result>& results,
                            std::vector<Result>& levin_results, const std::function<bool(double)>& callback,
                            double start) {
    const auto project_all = [&](const auto& projection, const std::vector<Point_3>& q, std::vector<Result>& out,
                                 double from, double to) {
      using P = std::decay_t<decltype(projection)>;
      bool warm = false;
      if constexpr(internal::has_warm_start<P>::value) warm = projection.options().warm_starts;
      const std::size_t chunk = warm ? 8 * warm_start_block : 128;
      out.reserve(out.size() + q.size());
      for(std::size_t b = 0; b < q.size(); b += chunk) {
        const std::size_t e = (std::min)(q.size(), b + chunk);
        std::vector<Point_3> part(q.begin() + b, q.begin() + e);
        project_points<ConcurrencyTag>(projection, part, std::back_inserter(out));
        if(callback && !callback(start + (1. - start) * (from + (to - from) * double(e) / double(q.size()))))
          return false;
      }
      return true;
    };
    if constexpr(!screens) {
      d.seed_projection.emplace(d.projection);
      d.operator_seeds = queries.size();
      return project_all(d.projection, queries, results, 0., 0.95);
    } else {
      if(!d.options.levin_screening) {
        d.seed_projection.emplace(d.projection, -1.);
        d.operator_seeds = queries.size();
        return project_all(*d.seed_projection, queries, results, 0., 0.95);
      }
      // P_L on every seed, the operator on the seeds whose energy exceeds the noise threshold
      const Seed_projection_type probe(d.projection, 0.);
      if(!project_all(probe.levin(), queries, results, 0., 0.05)) return false;
      const double noise = internal::noise_variance(d.projection);
      d.threshold = internal::screening_threshold(d.h, noise, internal::seed_noise_margin);
      d.fallback_threshold = (std::max)(d.threshold, fallback_noise_factor * fallback_noise_factor * noise);
      d.seed_projection.emplace(d.projection, d.threshold);
      std::vector<std::size_t> others;
      std::vector<Point_3> other_queries;
      for(std::size_t j = 0; j < results.size(); ++j)
        if(!d.seed_projection->keeps(results[j])) {
          others.push_back(j);
          other_queries.push_back(queries[j]);
        }
      d.operator_seeds = others.size();
      std::vector<Result> projected;
      if(!project_all(*d.seed_projection, other_queries, projected, 0.05, 0.95)) return false;
      levin_results = results; // P_L's fits: the fall-back of the operator's fits not to blend
      for(std::size_t k = 0; k < others.size() && k < projected.size(); ++k) results[others[k]] = std::move(projected[k]);
      return true;
    }
  }

  // A non-owning view used during construction (data_ does not exist yet).
  explicit MLS_implicit_function(Data& d) : data_(std::shared_ptr<Data>(std::shared_ptr<Data>(), &d)) {}

  std::shared_ptr<const Data> data_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MLS_IMPLICIT_FUNCTION_H
