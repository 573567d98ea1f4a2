// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_CLOSEST_POINT_PROJECTION_H
#define CGAL_MLS_PROJECTION_CLOSEST_POINT_PROJECTION_H

#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/internal/Frame.h>
#include <CGAL/MLS_projection/internal/Least_squares_minimizer.h>
#include <CGAL/MLS_projection/internal/Operator_base.h>
#include <CGAL/MLS_projection/internal/plane_split.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionOperators
/// The closest-point operators of the paper.
enum class Operator_kind {
  /// \f$\mathcal{P}_S\f$ (equation 4): frame and function optimised together; the query is
  /// projected along the frame normal, \f$\mathcal{P}_S(r) = g(h(r), f(h(r)))\f$ (section 3.2).
  /// Needs a function space that is a graph over the frame (`vertical_projection()`).
  SINGLE_PHASE,
  /// \f$\mathcal{P}_E\f$ (equation 5): Levin's frame (phase 1 of \f$\mathcal{P}_L\f$), then the
  /// function minimising the closest-point energy; \f$\mathcal{P}_E(r) = C_f(r)\f$.
  ENRICHED,
  /// \f$\mathcal{P}_U\f$ (equation 6): frame and function optimised together;
  /// \f$\mathcal{P}_U(r) = C_{H,f}(r)\f$.
  UNIFIED
};

namespace internal {

// Function spaces may declare `static constexpr bool has_sharp_features = true` (the wedge fan):
// the operator then adds starts at creases and apices proposed by splitting the neighbourhood.
template <class S, class = void> struct has_sharp_features : std::false_type {};
template <class S> struct has_sharp_features<S, std::void_t<decltype(S::has_sharp_features)>>
  : std::integral_constant<bool, S::has_sharp_features> {};

// Function spaces closed under rotations of the frame (the wedge fan, whose vectors are free)
// declare `static constexpr bool is_rotation_invariant = true`: the frame is then not tilted.
template <class S, class = void> struct is_rotation_invariant : std::false_type {};
template <class S> struct is_rotation_invariant<S, std::void_t<decltype(S::is_rotation_invariant)>>
  : std::integral_constant<bool, S::is_rotation_invariant> {};

// Graph function spaces provide `vertical_projection(c, x)`, the point of f above or below x.
template <class S, class = void> struct has_vertical_projection : std::false_type {};
template <class S>
struct has_vertical_projection<S, std::void_t<decltype(std::declval<const S&>().vertical_projection(
                                    std::declval<const typename S::Parameters&>(), std::declval<const Vec<S::ambient_dimension>&>()))>>
  : std::true_type {};

// Function spaces may provide `double regularization(c, h)`: a dimensionless residual added to
// the energy, zero for the members the space considers plausible at bandwidth h (e.g. a bound
// on the curvature of the quadratic space).
template <class S, class = void> struct has_regularization : std::false_type {};
template <class S>
struct has_regularization<S, std::void_t<decltype(std::declval<const S&>().regularization(
                               std::declval<const typename S::Parameters&>(), 1.))>> : std::true_type {};

} // namespace internal

/// \ingroup PkgMLSProjectionOperators
/// The closest-point MLS projections \f$\mathcal{P}_S\f$, \f$\mathcal{P}_E\f$ and
/// \f$\mathcal{P}_U\f$ (sections 3.2-3.4 of the paper), usually named through the aliases
/// `Single_phase_projection`, `Enriched_projection` and `Unified_projection`.
///
/// Residuals are the signed closest-point distances of the input points to the local function
/// \f$f\f$ over the frame \f$H\f$, weighted by \f$\omega(|C_{H,f}(r) - p_i|)\f$, the distance to the
/// closest point of the query on \f$f\f$. The optimisation (Levenberg-Marquardt, as for
/// `Levin_projection`) runs from several starts and keeps the lowest energy:
/// Levin's frame with the function space's initial member; the frame whose normal is each other
/// principal axis of the neighbourhood (the paper's start rotated by \f$\pi/2\f$); and, for spaces
/// with sharp features, frames at the crease or apex where a split of the neighbourhood into two
/// (or three) hyperplanes meet. A fit whose \f$C_{H,f}(r)\f$ is further from \f$r\f$ than Levin's
/// frame origin plus \f$2h\f$ is penalised and rejected; when no start gives a valid fit, the
/// result is Levin's projection with the status `NOT_CONVERGED`.
///
/// The result's `is_on_feature` and `feature_direction` tell whether \f$C_{H,f}(r)\f$ lies on a
/// crease or apex of \f$f\f$.
///
/// \tparam GeomTraits a CGAL kernel
/// \tparam FunctionSpace a model of `MLSFunctionSpace`
/// \tparam kind which operator
template <class GeomTraits, class FunctionSpace, Operator_kind kind>
class Closest_point_projection : public internal::Operator_base<GeomTraits, FunctionSpace::ambient_dimension> {
protected:
  static constexpr int D = FunctionSpace::ambient_dimension;
  static constexpr int P = FunctionSpace::number_of_parameters;
  static constexpr bool optimise_frame = kind != Operator_kind::ENRICHED;
  // The frame's parameters (section 4.1). P_S: as in Levin's projection, the normal n (D-1
  // angles; the tangent axes are transported with it) and the signed distance t of the origin
  // q = r + t n, so that P_S(r) = g(h(r), f(h(r))) is the point of f on the normal line through r.
  // P_U: the origin moves freely (D) and the frame turns independently of it (the paper's extra
  // terms M), so that every member of the space in every position is reachable and the members
  // are reproduced exactly; spaces closed under rotations (the wedge fan) only move the origin.
  static constexpr bool rotation_invariant = internal::is_rotation_invariant<FunctionSpace>::value;
  static constexpr bool origin_on_normal_line = kind == Operator_kind::SINGLE_PHASE && !rotation_invariant;
  static constexpr int R = (optimise_frame && !rotation_invariant) ? D - 1 : 0;
  static constexpr int T = optimise_frame ? (origin_on_normal_line ? 1 : D) : 0;
  using Base = internal::Operator_base<GeomTraits, D>;
  using V = internal::Vec<D>;
  template <int K> using Vec = internal::Vec<K>;
  template <int K> using Frame = internal::Frame<K>;
  template <int K> using Neighborhood = internal::Neighborhood<K>;
  template <int K> using Pca = internal::Pca<K>;
  template <int K> using Hyperplane = internal::Hyperplane<K>;
  using Minimizer_settings = internal::Minimizer_settings;
  static_assert(kind != Operator_kind::SINGLE_PHASE || internal::has_vertical_projection<FunctionSpace>::value,
                "Single_phase_projection needs a function space that is a graph (vertical_projection())");
  using Parameters = typename FunctionSpace::Parameters;
  using Levin = Levin_projection<GeomTraits, Plane_function_space<D>>;

public:
  using typename Base::FT;
  using typename Base::Point;
  using typename Base::Vector;
  using typename Base::Samples;
  using typename Base::Result;
  using Function_space = FunctionSpace;

  /// Builds the sample set of `points` (named parameters `point_map`, `normal_map`, see `Sample_set`).
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<!internal::is_shared_ptr<PointRange>::value>>
  explicit Closest_point_projection(const PointRange& points, const Projection_options& options = Projection_options(),
                                    const NamedParameters& np = parameters::default_values(),
                                    const FunctionSpace& space = FunctionSpace())
    : Closest_point_projection(std::make_shared<const Samples>(points, np), options, space) {}

  /// Shares an existing sample set (and its kd-tree) with other operators.
  explicit Closest_point_projection(std::shared_ptr<const Samples> samples,
                                    const Projection_options& options = Projection_options(),
                                    const FunctionSpace& space = FunctionSpace())
    : Base(samples, options), space_(space), levin_(samples, with_bandwidth(options, this->bandwidth())) {}

  const FunctionSpace& function_space() const { return space_; }

  static constexpr std::size_t minimum_points() {
    return (std::max)(std::size_t(D + 1), std::size_t(T + R + P));
  }

  Result project(const Point& query) const {
    const V r = this->samples().to_local(query);
    if(!r.allFinite()) return this->failure(query, Projection_status::INVALID_QUERY);
    if(this->samples().size() < minimum_points())
      return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);

    // Levin's frame: the start of every operator (and its fall-back).
    Neighborhood<D> nbh;
    const auto levin = levin_.find_frame(r, nbh);
    if(levin.status != Projection_status::CONVERGED) return this->failure(query, levin.status);
    const V qL = levin.origin, nL = levin.normal;
    const double h = this->h_;
    // P_U(r) may not move further from r than Levin's frame origin plus this margin.
    const double bound = (qL - r).norm() + 2 * h;
    nbh.gather(this->samples(), qL, this->weight_.support_radius() + 2 * h);
    if(nbh.size() < minimum_points()) return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);

    std::vector<Frame<D>> starts;
    starts.push_back(Frame<D>::from_normal(qL, nL));
    if constexpr(optimise_frame) add_starts(r, qL, nbh, starts);

    std::vector<Fit> fits;
    int iterations = 0;
    for(const Frame<D>& start : starts) {
      Fit fit = minimize(r, start, initial_member(start, nbh), nbh, bound);
      iterations += fit.iterations;
      fits.push_back(fit);
    }
    Fit best = select(fits, nbh);
    // The weights are centred on C(r): make sure the gathered ball covers their support there.
    for(int round = 0; round < 3 && best.valid && !nbh.covers(best.C, this->weight_.support_radius()); ++round) {
      nbh.gather(this->samples(), best.C, this->weight_.support_radius() + 2 * h);
      if(nbh.size() < minimum_points()) break;
      Fit fit = minimize(r, best.frame, best.c, nbh, bound);
      iterations += fit.iterations;
      best = fit;
    }
    if(!best.valid) return fallback(query, iterations);
    return make_result(r, best, nbh, iterations);
  }

  Result operator()(const Point& query) const { return project(query); }

protected:
  struct Fit {
    Frame<D> frame;
    Parameters c = Parameters::Zero();
    V C = V::Zero(); // C_{H,f}(r), local coordinates
    double value = std::numeric_limits<double>::infinity(); // objective (units of h^2, with penalty)
    double energy = 0; // weighted mean squared distance, squared length units
    int iterations = 0;
    bool converged = false;
    bool valid = false;
    bool supported = false;
  };

  // The fit of lowest energy among the fits whose C(r) is supported by data, i.e. lies within
  // h/2 of the closest point of some weighted input point; among fits whose energies are
  // indistinguishable (within 5%, or both numerically zero), the earliest start wins: Levin's
  // frame, then the turned frames, then the feature proposals.
  // Equation 6 has spurious minima of equal energy: e.g. a fan with one face on the data and
  // another face, unsupported, near r has zero residuals too (and a C(r) nearer to r); the
  // support test rejects those far from the data, the order of the starts those near it.
  // When no fit is supported (a query beyond the end of the data), all fits compete.
  Fit select(std::vector<Fit>& fits, const Neighborhood<D>& nbh) const {
    bool any_supported = false;
    for(Fit& f : fits) {
      if(!f.valid) continue;
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < nbh.size(); ++i) {
        if(this->weight_((nbh.points[i] - f.C).squaredNorm()) <= 0) continue;
        const V c = f.frame.to_local(space_.closest_point(f.c, f.frame.to_frame(nbh.points[i])).point);
        nearest = (std::min)(nearest, (c - f.C).squaredNorm());
      }
      f.supported = nearest <= 0.25 * this->h_ * this->h_;
      any_supported |= f.supported;
    }
    double lowest = std::numeric_limits<double>::infinity();
    for(const Fit& f : fits)
      if(f.valid && (f.supported || !any_supported)) lowest = (std::min)(lowest, f.energy);
    for(const Fit& f : fits) {
      if(!f.valid || (any_supported && !f.supported)) continue;
      if(f.energy <= 1.05 * lowest + 1e-10 * this->h_ * this->h_) return f;
    }
    return Fit();
  }

  Parameters initial_member(const Frame<D>& frame, const Neighborhood<D>& nbh) const {
    std::vector<V> y;
    std::vector<double> w;
    y.reserve(nbh.size());
    w.reserve(nbh.size());
    for(const V& p : nbh.points) {
      const double wi = this->weight_((p - frame.origin).squaredNorm());
      if(wi <= 0) continue;
      y.push_back(frame.to_frame(p));
      w.push_back(wi);
    }
    return space_.fit(y.data(), w.data(), y.size());
  }

  // Starts of the joint optimisation besides Levin's frame (paper, section 4.1): the frame
  // turned by pi/2 (in 3D, each other principal axis of the neighbourhood as the normal), and,
  // for spaces with sharp features, frames at the crease or apex proposed by a plane split.
  void add_starts(const V& r, const V& qL, const Neighborhood<D>& nbh, std::vector<Frame<D>>& starts) const {
    std::vector<double> w(nbh.size());
    for(std::size_t i = 0; i < nbh.size(); ++i) w[i] = this->weight_((nbh.points[i] - qL).squaredNorm());
    const Pca<D> pca = internal::weighted_pca<D>(nbh.points, w);
    if(!pca.valid) return;
    for(int axis = 1; axis < D; ++axis) starts.push_back(Frame<D>::from_normal(qL, pca.eigenvectors.col(axis)));
    if constexpr(internal::has_sharp_features<FunctionSpace>::value) {
      // Proposals see the whole gathered ball (radius: support + 2h) with equal weights, so
      // that a crease at the edge of the support, with few points of weight, is still found.
      std::fill(w.begin(), w.end(), 1.);
      const Pca<D> pca = internal::weighted_pca<D>(nbh.points, w);
      if(!pca.valid) return;
      const auto two = internal::split_in_two<D>(nbh.points, w, pca);
      // only when two hyperplanes explain the points much better than one
      if(two.valid && two.energy < 0.25 * pca.eigenvalues[0]) add_feature_start<2>(r, two.planes, starts);
      if constexpr(D == 3) {
        const auto three = internal::split_in_three(nbh.points, w, pca);
        if(three.valid && three.energy < 0.25 * (std::min)(two.energy, pca.eigenvalues[0]))
          add_feature_start<3>(r, three.planes, starts);
      }
    }
  }

  template <int K>
  void add_feature_start(const V& r, const std::array<Hyperplane<D>, K>& planes, std::vector<Frame<D>>& starts) const {
    V x;
    if(!internal::intersection_nearest<D, K>(planes, r, x)) return;
    // Orient each hyperplane so that the other pieces lie behind it: the normals are then all
    // outward (convex feature) or all inward (concave), and their sum is the feature's bisector,
    // over which the pieces form a graph.
    V n = V::Zero();
    for(int k = 0; k < K; ++k) {
      double behind = 0;
      for(int j = 0; j < K; ++j)
        if(j != k) behind += planes[k].distance(planes[j].centroid);
      n += (behind > 0 ? -1. : 1.) * planes[k].normal;
    }
    if(!(n.norm() > 1e-6)) return;
    Frame<D> frame = Frame<D>::from_normal(x, n.normalized());
    if constexpr(D == 3 && K == 2) {
      // first tangent axis along the crease, where a fan's first vector starts
      const V e1 = planes[0].normal.cross(planes[1].normal).normalized();
      frame.axes.col(0) = e1;
      frame.axes.col(1) = frame.normal().cross(e1);
    }
    starts.push_back(frame);
  }

  // Packs frame offsets (units of h), tilt angles and function parameters.
  Fit minimize(const V& r, const Frame<D>& start, const Parameters& c0, const Neighborhood<D>& nbh, double bound) const {
    const double h = this->h_;
    const int n = T + R + P;
    const int m = int(nbh.size()) + 2;
    std::vector<double> w(nbh.size());
    // the start's plane, its origin moved to the foot of r
    const double s0 = (start.origin - r).dot(start.normal()) / h;
    const auto unpack = [&](const Eigen::VectorXd& x, Frame<D>& f, Parameters& c) {
      if constexpr(optimise_frame && R > 0 && T == D) {
        f = start.moved(h * V(x.template segment<D>(R)), x.template segment<R>(0));
      } else if constexpr(optimise_frame && R > 0) {
        f = start.moved(V::Zero(), x.template segment<R>(0));
        f.origin = r + ((s0 + x[R]) * h) * f.normal();
      } else if constexpr(optimise_frame) {
        f = start;
        f.origin += h * V(x.template head<D>());
      } else {
        f = start;
      }
      for(int j = 0; j < P; ++j) c[j] = x[T + R + j];
    };
    const auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& res) {
      Frame<D> f;
      Parameters c;
      unpack(x, f, c);
      const V C = f.to_local(space_.closest_point(c, f.to_frame(r)).point);
      double W = 0;
      for(std::size_t i = 0; i < nbh.size(); ++i) {
        w[i] = this->weight_((nbh.points[i] - C).squaredNorm());
        W += w[i];
      }
      if(!(W > 0) || !C.allFinite()) {
        res.setConstant(1e3); // a plateau the trust region backs off from
        return;
      }
      for(std::size_t i = 0; i < nbh.size(); ++i)
        res[i] = w[i] > 0 ? std::sqrt(w[i] / W) * space_.closest_point(c, f.to_frame(nbh.points[i])).signed_distance / h : 0.;
      const double excess = (C - r).norm() - bound;
      res[m - 2] = excess > 0 ? 10. * excess / h : 0.;
      if constexpr(internal::has_regularization<FunctionSpace>::value) res[m - 1] = space_.regularization(c, h);
      else res[m - 1] = 0.;
      if(!res.allFinite()) res.setConstant(1e3);
    };
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(n);
    for(int j = 0; j < P; ++j) x0[T + R + j] = c0[j];
    Minimizer_settings settings;
    settings.tolerance = this->options_.tolerance;
    settings.max_evaluations = this->options_.max_evaluations * (n + 1) / (D + 1);
    const auto report = internal::minimize_sum_of_squares(residuals, m, x0, settings);

    Fit fit;
    unpack(report.x, fit.frame, fit.c);
    fit.iterations = report.iterations;
    fit.converged = report.converged;
    fit.C = fit.frame.to_local(space_.closest_point(fit.c, fit.frame.to_frame(r)).point);
    fit.value = report.value;
    // the energy of equation 6 without the displacement penalty
    double W = 0, E = 0;
    for(std::size_t i = 0; i < nbh.size(); ++i) {
      const double wi = this->weight_((nbh.points[i] - fit.C).squaredNorm());
      if(wi <= 0) continue;
      const double d = space_.closest_point(fit.c, fit.frame.to_frame(nbh.points[i])).signed_distance;
      W += wi;
      E += wi * d * d;
    }
    fit.energy = W > 0 ? E / W : std::numeric_limits<double>::infinity();
    fit.valid = std::isfinite(fit.value) && std::isfinite(fit.energy) && fit.C.allFinite() &&
                (fit.C - r).norm() <= bound * (1 + 1e-9) && fit.value < 1e5;
    return fit;
  }

  Result make_result(const V& r, const Fit& fit, const Neighborhood<D>& nbh, int iterations) const {
    const auto cp = space_.closest_point(fit.c, fit.frame.to_frame(r));
    V point = fit.C;
    V normal = fit.frame.vector_to_local(cp.normal);
    if constexpr(kind == Operator_kind::SINGLE_PHASE) {
      // P_S(r) = g(h(r), f(h(r))): the projection along the frame normal (section 3.2).
      const V y = fit.frame.to_frame(r);
      const auto vertical = space_.vertical_projection(fit.c, y);
      point = fit.frame.to_local(vertical.point);
      normal = fit.frame.vector_to_local(vertical.normal);
    }
    normal.normalize();
    normal *= this->orientation(point, normal, nbh);
    if(!point.allFinite() || !normal.allFinite()) return fallback(this->samples().to_world(r), iterations);
    Result res;
    std::array<V, D - 1> tangents;
    for(int j = 0; j < D - 1; ++j) tangents[j] = fit.frame.axes.col(j);
    this->set_geometry(res, point, normal, fit.frame.origin, fit.frame.normal(), tangents);
    res.coefficients.assign(fit.c.data(), fit.c.data() + P);
    res.energy = fit.energy;
    res.iterations = iterations;
    res.number_of_neighbors = nbh.size();
    if constexpr(kind != Operator_kind::SINGLE_PHASE) {
      // A singular C(r) is a feature of the data only if no single hyperplane explains the
      // weighted points as well as the fit: a fan can also have an apex or a crease on a flat
      // region (coplanar faces but one, which no point supports).
      std::vector<double> w(nbh.size());
      for(std::size_t i = 0; i < nbh.size(); ++i) w[i] = this->weight_((nbh.points[i] - fit.C).squaredNorm());
      const auto pca = internal::weighted_pca<D>(nbh.points, w);
      const bool is_feature = pca.valid && pca.eigenvalues[0] > 4. * fit.energy + 1e-14 * this->h_ * this->h_;
      res.is_on_feature = cp.is_singular && is_feature;
      if(res.is_on_feature)
        res.feature_direction = internal::Kernel_types<GeomTraits, D>::to_vector(fit.frame.vector_to_local(cp.direction));
    }
    res.status = fit.converged ? Projection_status::CONVERGED : Projection_status::NOT_CONVERGED;
    return res;
  }

  static Projection_options with_bandwidth(Projection_options options, double h) {
    if(h > 0) options.bandwidth = h; // derived once, by the base
    return options;
  }

  // Levin's answer, marked as not converged, when the joint optimisation fails.
  Result fallback(const Point& query, int iterations) const {
    Result res = levin_.project(query);
    res.iterations += iterations;
    if(res.is_success()) res.status = Projection_status::NOT_CONVERGED;
    return res;
  }

  FunctionSpace space_;
  Levin levin_;
};

/// \ingroup PkgMLSProjectionOperators
/// The single-phase projection \f$\mathcal{P}_S\f$ (equation 4).
template <class GeomTraits, class FunctionSpace>
using Single_phase_projection = Closest_point_projection<GeomTraits, FunctionSpace, Operator_kind::SINGLE_PHASE>;

/// \ingroup PkgMLSProjectionOperators
/// The enriched projection \f$\mathcal{P}_E\f$ (equation 5).
template <class GeomTraits, class FunctionSpace>
using Enriched_projection = Closest_point_projection<GeomTraits, FunctionSpace, Operator_kind::ENRICHED>;

/// \ingroup PkgMLSProjectionOperators
/// The unified projection \f$\mathcal{P}_U\f$ (equation 6).
template <class GeomTraits, class FunctionSpace>
using Unified_projection = Closest_point_projection<GeomTraits, FunctionSpace, Operator_kind::UNIFIED>;

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_CLOSEST_POINT_PROJECTION_H
