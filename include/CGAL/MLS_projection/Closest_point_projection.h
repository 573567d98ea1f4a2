// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_CLOSEST_POINT_PROJECTION_H
#define CGAL_MLS_PROJECTION_CLOSEST_POINT_PROJECTION_H

#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/internal/projection/Frame.h>
#include <CGAL/MLS_projection/internal/projection/Levenberg_marquardt.h>
#include <CGAL/MLS_projection/internal/projection/Operator_base.h>
#include <CGAL/MLS_projection/internal/projection/plane_split.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
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

// Function spaces may provide `bool member_of_hyperplanes(normals, k, c)`: the member made of k
// hyperplanes through the frame origin, for the starts at creases and apices (else `fit()`).
template <class S, class = void> struct has_member_of_hyperplanes : std::false_type {};
template <class S>
struct has_member_of_hyperplanes<S, std::void_t<decltype(std::declval<const S&>().member_of_hyperplanes(
                                      std::declval<const Vec<S::ambient_dimension>*>(), 2,
                                      std::declval<typename S::Parameters&>()))>> : std::true_type {};

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

// Function spaces may provide the batch `closest_points(c, x, n, out, gradients)`, which also
// gives the derivatives of the signed distances with respect to the parameters: the operators
// then use an analytic Jacobian (else forward differences of the residuals).
template <class S, class = void> struct has_closest_points : std::false_type {};
template <class S>
struct has_closest_points<S, std::void_t<decltype(std::declval<const S&>().closest_points(
                               std::declval<const typename S::Parameters&>(), std::declval<const Vec<S::ambient_dimension>*>(),
                               std::size_t(0), std::declval<Closest_point<S::ambient_dimension>*>(),
                               std::declval<typename S::Parameters*>()))>> : std::true_type {};

// Function spaces may provide `closest_point_derivatives(c, x, cp, d_parameters, d_point)`, which
// also gives the derivatives of the closest point's position by the parameters and by x: the
// operators then differentiate C_{H,f}(r) exactly where it is differentiable (else by central
// differences).
template <class S, class = void> struct has_foot_derivatives : std::false_type {};
template <class S>
struct has_foot_derivatives<S, std::void_t<decltype(std::declval<const S&>().closest_point_derivatives(
                                 std::declval<const typename S::Parameters&>(), std::declval<const Vec<S::ambient_dimension>&>(),
                                 std::declval<Closest_point<S::ambient_dimension>&>(),
                                 std::declval<Eigen::Matrix<double, S::ambient_dimension, S::number_of_parameters>&>(),
                                 std::declval<Mat<S::ambient_dimension>&>()))>> : std::true_type {};

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
/// (or three) hyperplanes meet, with the member made of those hyperplanes when the space provides
/// one (`member_of_hyperplanes()`, optional in `MLSFunctionSpace`). A fit whose \f$C_{H,f}(r)\f$ is
/// further from \f$r\f$ than Levin's frame origin plus \f$2h\f$ is penalised and rejected; when no
/// start gives a valid fit, the result is Levin's projection with the status `LEVIN_FALLBACK`.
///
/// With a `Warm_start`, a projection first continues the final fit of the last one (a nearby
/// query's, the paper's section 6) and keeps it when it converges, is supported by the data and
/// fits it nearly as well (energy at most `warm_energy_factor` times the last one's, or below
/// `warm_energy_floor`: an RMS residual of \f$h/100\f$); otherwise it is
/// tried once more with the last fit's frame origin moved to \f$C_0\f$, the closest point of the
/// query on the last fit, then the starts above run. A continued fit needs neither Levin's frame
/// nor the whole gathered ball: its neighbourhood is the support around \f$C_0\f$, plus \f$h/2\f$,
/// and its bound is \f$\min(|C_0 - r|, d) + 2h\f$, with \f$d\f$ the distance of \f$r\f$ to its
/// nearest input point (a jump in the order of the queries cannot carry the projection to the data
/// near the last query). `project_points()` does this along a Hilbert curve of its queries.
///
/// The optimisation works in units of \f$h\f$: the result's `coefficients` are those of the
/// member with every length divided by \f$h\f$ (its `fit_kind` is `Local_fit_kind::CLOSEST_POINT`).
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

  struct Fit {
    Frame<D> frame;
    Parameters c = Parameters::Zero();
    V C = V::Zero(); // C_{H,f}(r), local coordinates
    Closest_point<D> at_r; // the same with its normal and piece, frame coordinates
    double value = std::numeric_limits<double>::infinity(); // objective (units of h^2, with penalty)
    double energy = 0; // weighted mean squared distance, units of h^2
    int iterations = 0;
    bool converged = false;
    bool valid = false;
    bool supported = false;
  };

  // A start of the joint optimisation: a frame, and the member to start from when known (else
  // the space's `fit()` in that frame).
  struct Start {
    Frame<D> frame;
    std::optional<Parameters> member;
  };

public:
  using typename Base::FT;
  using typename Base::Point;
  using typename Base::Vector;
  using typename Base::Samples;
  using typename Base::Result;
  using Function_space = FunctionSpace; ///< the function space; the other types as in `Levin_projection`

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

  /// The function space.
  const FunctionSpace& function_space() const { return space_; }

  /// The fewest input points a projection needs: the parameters of the frame and of the member.
  static constexpr std::size_t minimum_points() {
    return (std::max)(std::size_t(D + 1), std::size_t(T + R + P));
  }

  /// Projects `query`: \f$C_{H,f}(r)\f$ for the frame and member of lowest energy (see the class).
  Result project(const Point& query) const { return project_impl(query, nullptr); }

  /// The state of a sequence of warm-started projections: the final fit of the last one that
  /// converged. Default-constructed, it holds nothing (the next projection starts cold).
  class Warm_start {
    friend class Closest_point_projection;
    Fit fit_;
    bool valid_ = false;

  public:
    /// Forgets the last fit.
    void reset() { valid_ = false; }
  };

  /// Projects `query`, first continuing the optimisation from the final fit of the last
  /// projection made with `warm` (the paper's section 6), which should be of a nearby query, then
  /// stores this projection's fit in `warm`. The continued fit is kept when it converges, is
  /// supported by the data and its energy is at most `warm_energy_factor` times the last one's
  /// (the same neighbourhood fitted as well) or below `warm_energy_floor`; otherwise, after a
  /// second try from the last fit moved to the query (see the class), the query is projected as
  /// by `project(query)`.
  /// `project_points()` orders its queries along a Hilbert curve for this.
  Result project(const Point& query, Warm_start& warm) const { return project_impl(query, &warm); }

  /// Same as `project()`, so that the operator is a function object.
  Result operator()(const Point& query) const { return project(query); }

  /// The largest ratio of a warm-started fit's energy to the last fit's at which it is kept.
  static constexpr double warm_energy_factor = 1.5;
  /// The energy (units of \f$h^2\f$) below which a warm-started fit is kept whatever the last
  /// fit's: an RMS residual of \f$h/100\f$, the noiseless threshold of `Mixed_projection`'s
  /// screening: the ratio alone rejects nearly exact fits (faceted or curved data next to a
  /// crease) for rises of the energy far below the data's resolution.
  static constexpr double warm_energy_floor = 1e-4;

protected:
  Result project_impl(const Point& query, Warm_start* warm) const {
    const V r = this->samples().to_local(query);
    if(!r.allFinite()) return this->failure(query, Projection_status::INVALID_QUERY);
    if(this->samples().size() < minimum_points())
      return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);

    const double h = this->h_;
    const double support = unit_weight_.support_radius(); // in units of h
    // From here on, lengths are in units of h (the optimiser's parameters are then all of
    // order 1, whatever the scale of the input).
    const V rs = r / h;
    Neighborhood<D> nbh, unit, race_ball;
    this->set_side(nbh, r);
    const Neighborhood<D>* fitted = &unit; // the points the fit was made on: `unit` or `race_ball`
    double bound = 0; // P_U(r) may not move further from r than this (units of h)
    int iterations = 0;
    Fit best;
    if(warm && warm->valid_) {
      // The last fit continued: C(r) hardly moves from the closest point C0 of r on it, so the
      // ball gathered around C0 needs only a small margin (fewer residuals: a cheaper
      // factorisation at each iteration; a C(r) that leaves it is gathered again below), and
      // Levin's frame is not needed (measured on the noisy cube: 1.82 -> 1.43 ms per query, see
      // the manual).
      const Fit& last = warm->fit_;
      const V C0 = last.frame.to_local(space_.closest_point(last.c, last.frame.to_frame(rs)).point);
      if(C0.allFinite()) {
        nbh.gather(this->samples(), h * C0, h * (support + warm_margin));
        if(nbh.size() >= minimum_points()) {
          unit = in_units_of_h(nbh);
          // C(r) may not move further from r than C0 or r's nearest input point, plus 2h (as
          // Levin's origin in the cold bound): a jump in the order of the queries can put C0 on
          // the last fit's extension, far from the data near r, where the continued fit fits
          // other data (on the benchmark's noisy torus, with a trial Jacobian that differed only
          // by rounding, a projection landed 9.7 h from its query; see the manual).
          const double nearest = this->samples().kth_neighbor_distance(r, 1) / h;
          bound = (std::min)((C0 - rs).norm(), nearest) + 2;
          best = continued(rs, last, unit, bound, iterations);
          if(!best.valid) {
            // On noisy data, a continued fit is mostly rejected because the fit's kinks, which
            // follow the noise, stayed behind the query: the fit's apex is moved to C0 (the
            // surface near C0 hardly changes when the fit is nearly flat) and continued again
            // before the race runs (see the manual, "Warm starts").
            Fit moved = last;
            moved.frame.origin = C0;
            best = continued(rs, moved, unit, bound, iterations);
          }
        }
      }
    }
    if(!best.valid) {
      // Levin's frame: the start of every operator (and its fall-back).
      const auto levin = levin_.find_frame(r, nbh);
      if(levin.status != Projection_status::CONVERGED) return this->failure(query, levin.status);
      nbh.gather(this->samples(), levin.origin, h * (support + gather_margin));
      if(nbh.size() < minimum_points()) return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);
      unit = in_units_of_h(nbh);
      const V qL = levin.origin / h, nL = levin.normal;
      // P_U(r) may not move further from r than Levin's frame origin plus this margin.
      bound = (qL - rs).norm() + 2;
      // The proposals of add_starts() see the whole ball; the race's fits only the support
      // around Levin's origin plus `race_margin` (fewer residuals; a C(r) that leaves it is
      // fitted again below on the whole ball, or on a ball gathered around it).
      const std::vector<Start> starts = starts_at(rs, qL, nL, unit);
      race_ball = unit.within(qL, support + race_margin);
      if(race_ball.size() >= minimum_points()) fitted = &race_ball;
      best = race(rs, starts, *fitted, bound, iterations, warm != nullptr);
    }
    // The weights are centred on C(r): make sure the fitted points cover their support there.
    for(int round = 0; round < 3 && best.valid && !fitted->covers(best.C, support); ++round) {
      if(!unit.covers(best.C, support)) {
        nbh.gather(this->samples(), h * best.C, h * (support + gather_margin));
        if(nbh.size() < minimum_points()) break;
        unit = in_units_of_h(nbh);
      }
      fitted = &unit;
      Fit fit = minimize(rs, best.frame, best.c, unit, bound);
      iterations += fit.iterations;
      best = fit;
    }
    if(!best.valid) {
      if(warm) warm->reset();
      return fallback(query, iterations);
    }
    const std::vector<double> w = weights_at(best, unit);
    if(!has_effective_points(w)) {
      if(warm) warm->reset();
      return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);
    }
    Result res = make_result(rs, best, unit, w, nbh, iterations);
    if(warm) {
      warm->fit_ = best;
      warm->valid_ = res.status == Projection_status::CONVERGED;
    }
    return res;
  }

  // The fit continued from `last`, the final fit of the last warm-started projection, when
  // kept (else an invalid fit). The continued fit starts at the minimum of a nearby query: the
  // stop windows of the optimiser are shortened to `warm_window` evaluations (measured on the
  // benchmark's torus, every point: 10 -> 4 evaluations, 21.6 -> 13.1 iterations per query;
  // 4 -> 2, 12.9 -> 9.1; the same accuracy, see the manual, "Warm starts").
  Fit continued(const V& rs, const Fit& last, const Neighborhood<D>& unit, double bound, int& iterations) const {
    Fit fit = minimize(rs, last.frame, last.c, unit, bound, 0, warm_window, warm_window);
    iterations += fit.iterations;
    if(!fit.valid || !fit.converged || !(fit.energy <= (std::max)(warm_energy_factor * last.energy, warm_energy_floor)))
      return Fit();
    fit.supported = is_supported(fit, unit);
    return fit.supported ? fit : Fit();
  }

  // The starts of the race: Levin's frame (origin qL, normal nL), then those of add_starts(),
  // proposed from `unit`, the whole gathered ball.
  std::vector<Start> starts_at(const V& rs, const V& qL, const V& nL, const Neighborhood<D>& unit) const {
    std::vector<Start> starts;
    starts.push_back({frame_from_data(qL, nL, unit), std::nullopt});
    if constexpr(optimise_frame) add_starts(rs, qL, unit, starts);
    return starts;
  }

  // The race of the starts on the points `unit` (see project()); `in_chain`: in a chain of warm starts.
  Fit race(const V& rs, const std::vector<Start>& starts, const Neighborhood<D>& unit, double bound, int& iterations,
           bool in_chain = false) const {
    // A race: every start gets a short budget, then only the selected fit runs to convergence
    // (most starts lead to minima of much higher energy, which are told apart early). An exact
    // fit (zero energy) supported by the data ends the race: no other start can beat it.
    std::vector<Fit> fits;
    const bool alone = starts.size() == 1;
    for(const Start& start : starts) {
      const Parameters c = start.member ? *start.member : initial_member(start.frame, unit);
      Fit fit = alone ? converge(rs, start.frame, c, unit, bound, in_chain)
                      : minimize(rs, start.frame, c, unit, bound, race_evaluations);
      iterations += fit.iterations;
      fit.supported = fit.valid && is_supported(fit, unit);
      fits.push_back(fit);
      if(fit.supported && fit.converged && fit.value <= exact_value) break;
    }
    Fit best = select(fits);
    if(best.valid && !best.converged) {
      const Fit leader = best;
      Fit fit = converge(rs, best.frame, best.c, unit, bound, in_chain);
      iterations += fit.iterations;
      if(fit.valid) best = fit;
      // The race can pick a start that ends at a small but non-zero energy while another start
      // reaches the exact fit (noiseless cube of the benchmark: a corner fan stopped at 4.8e-7 h^2,
      // 6.3e-7 h off the face, where Levin's frame, second in the race, reached 3e-29 h^2). When
      // the converged leader nearly fits the data, the starts whose race values were within
      // `rival_factor` of the leader's run to convergence too, and the selection is made again.
      // On noisy data (energies above `near_exact_energy`) this never happens: no time is spent.
      if(best.valid && best.value > exact_value && best.energy < near_exact_energy) {
        best.supported = is_supported(best, unit);
        std::vector<Fit> finals{best};
        for(const Fit& f : fits) {
          if(!f.valid || f.converged || f.value > rival_factor * leader.value ||
             (f.frame.origin == leader.frame.origin && f.c == leader.c))
            continue;
          Fit rival = minimize(rs, f.frame, f.c, unit, bound);
          iterations += rival.iterations;
          if(!rival.valid) continue;
          rival.supported = is_supported(rival, unit);
          finals.push_back(rival);
        }
        best = select(finals);
      }
    }
    return best;
  }

  // A run to convergence. In a chain of warm starts, the improving evaluations that stop it when
  // C(r) no longer moves (see minimize()) are watched over the continued fits' short window; a
  // fit that then ends nearly exact but not exact runs on with the full windows, which only
  // noiseless data reaches (with the short window alone, the benchmark's noiseless cube ended
  // 1.2e-11 off, against 2.9e-12; see the manual, "Warm starts").
  Fit converge(const V& rs, const Frame<D>& frame, const Parameters& c, const Neighborhood<D>& unit, double bound,
               bool in_chain) const {
    if(!in_chain) return minimize(rs, frame, c, unit, bound);
    Fit fit = minimize(rs, frame, c, unit, bound, 0, 0, warm_window);
    if(fit.valid && fit.value > exact_value && fit.energy < near_exact_energy) {
      Fit more = minimize(rs, fit.frame, fit.c, unit, bound);
      if(more.valid) {
        more.iterations += fit.iterations;
        return more;
      }
      fit.iterations += more.iterations;
    }
    return fit;
  }

  // The closest points `out[0..n-1]` of the frame coordinates `y[0..n-1]` on the member `c`, in one
  // batch when the space has `closest_points()` (with the gradients, when `grads` is not null).
  void closest_points(const Parameters& c, const V* y, std::size_t n, Closest_point<D>* out, Parameters* grads) const {
    if constexpr(internal::has_closest_points<FunctionSpace>::value) {
      space_.closest_points(c, y, n, out, grads);
    } else {
      for(std::size_t i = 0; i < n; ++i) out[i] = space_.closest_point(c, y[i]);
    }
  }

  // Calls `visit(w_i, cp_i)` for each point i of `nbh` of positive weight w_i around the fit's
  // C(r), with its closest point cp_i on the fit (frame coordinates), until `visit` returns true;
  // returns whether it did. The closest points are computed in batches: a fan is prepared (its
  // vectors from their angles) once per batch, not once per point.
  template <class Visit>
  bool visit_weighted_points(const Fit& f, const Neighborhood<D>& nbh, Visit visit) const {
    constexpr std::size_t batch = 32;
    std::array<double, batch> weight;
    std::array<V, batch> y;
    std::array<Closest_point<D>, batch> cps;
    std::size_t k = 0;
    for(std::size_t i = 0; i <= nbh.size(); ++i) {
      if(i < nbh.size()) {
        const double wi = unit_weight_((nbh.points[i] - f.C).squaredNorm());
        if(!(wi > 0)) continue;
        weight[k] = wi;
        y[k++] = f.frame.to_frame(nbh.points[i]);
        if(k < batch) continue;
      }
      closest_points(f.c, y.data(), k, cps.data(), nullptr);
      for(std::size_t j = 0; j < k; ++j)
        if(visit(weight[j], cps[j])) return true;
      k = 0;
    }
    return false;
  }

  // The fit of lowest energy among the fits whose C(r) is supported by data, i.e. lies within
  // h/2 of the closest point of some weighted input point; among fits whose energies are
  // indistinguishable (within 5%, or both numerically zero: below `exact_value`), the earliest
  // start wins: Levin's frame, then the turned frames, then the feature proposals. (A tolerance
  // of 1e-10 h^2 let fits stalled at 1e-11 h^2 beat the exact fit: 7.7e-6 h off a 60-degree edge.)
  // Equation 6 has spurious minima of equal energy: e.g. a fan with one face on the data and
  // another face, unsupported, near r has zero residuals too (and a C(r) nearer to r); the
  // support test rejects those far from the data, the order of the starts those near it.
  // When no fit is supported (a query beyond the end of the data), all fits compete.
  // Whether C(r) lies within h/2 of the closest point of some weighted input point, or, when
  // h is close to the sample spacing, within the spacing of those closest points around it (on a
  // grid of spacing s, C(r) can be s/sqrt(2) from every sample), or, in a gap of a random
  // sampling, amid closest points on every side.
  // For spaces with sharp features (piecewise-linear members), the piece of C(r) must moreover
  // carry weighted input points: see on_a_piece_with_data().
  bool is_supported(const Fit& f, const Neighborhood<D>& nbh) const {
    if constexpr(internal::has_sharp_features<FunctionSpace>::value)
      if(!on_a_piece_with_data(f, nbh)) return false;
    std::vector<V> c;
    c.reserve(nbh.size());
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t k = 0;
    const bool near = visit_weighted_points(f, nbh, [&](double, const Closest_point<D>& cp) {
      c.push_back(f.frame.to_local(cp.point));
      const double d = (c.back() - f.C).squaredNorm();
      if(d <= 0.25) return true;
      if(d < nearest) {
        nearest = d;
        k = c.size() - 1;
      }
      return false;
    });
    if(near) return true;
    double spacing = std::numeric_limits<double>::infinity();
    for(std::size_t j = 0; j < c.size(); ++j)
      if(j != k) spacing = (std::min)(spacing, (c[j] - c[k]).squaredNorm());
    if(std::isfinite(spacing) && nearest <= spacing) return true;
    // C(r) in a gap of the sampling: supported when feet within 1.5 h surround it, one in each
    // orthant of the tangent directions (a C(r) beyond the end of the data has none on one side)
    constexpr int orthants = 1 << (D - 1);
    bool seen[orthants] = {};
    for(const V& cj : c) {
      const V t = f.frame.axes.transpose() * (cj - f.C);
      if(t.template head<D - 1>().squaredNorm() > 2.25) continue;
      int o = 0;
      for(int a = 0; a < D - 1; ++a) o |= (t[a] > 0 ? 1 : 0) << a;
      seen[o] = true;
    }
    return std::all_of(seen, seen + orthants, [](bool b) { return b; });
  }

  // Whether the piece of C(r) (the query's own closest point, `f.at_r`) carries data, for
  // piecewise-linear members. Near a narrow edge, exact fans (zero energy) exist whose C(r) lies on
  // a piece that no input point is on: a cone bridging the two faces, or a sliver cone beside one
  // face, nearer to r than the data. Such a C(r) can be within h/2 of the data; measured on a dense
  // grid of queries across the test's 45 and 60 degree edges, they were selected 0.092 h and
  // 2.3e-4 h off the edge. The rules (see the manual, "Selection"):
  // - on a regular piece, the closest point of some weighted input point lies on it too (same
  //   normal, within 1e-6 rad), and in 3D those closest points span it: not all on one line
  //   (within 1e-6 h; a cone whose only data is a grid row on its boundary ray fits it exactly);
  // - on a crease, the faces on both sides carry such closest points (a data-free sliver cone
  //   along an unsampled edge, C(r) on its boundary ray, fits exactly too);
  // - an apex is not judged.
  bool on_a_piece_with_data(const Fit& f, const Neighborhood<D>& nbh) const {
    constexpr double same = 1 - 5e-13; // the cosine of 1e-6 rad
    const Closest_point<D>& at = f.at_r;
    if(at.is_on_feature) {
      if(!(at.direction.squaredNorm() > 0)) return true;
      // the distinct normals of the faces along the crease that carry data, until two of them
      // are the crease's faces (their normalised sum is the crease's normal)
      std::vector<V> faces;
      return visit_weighted_points(f, nbh, [&](double, const Closest_point<D>& cp) {
        if(cp.is_on_feature || std::abs(cp.normal.dot(at.direction)) > 1e-6) return false;
        for(const V& n : faces)
          if(n.dot(cp.normal) > same) return false;
        for(const V& n : faces)
          if((n + cp.normal).normalized().dot(at.normal) > same) return true;
        faces.push_back(cp.normal);
        return false;
      });
    }
    std::vector<V> on_piece;
    const bool found = visit_weighted_points(f, nbh, [&](double, const Closest_point<D>& cp) {
      if(cp.is_on_feature || !(cp.normal.dot(at.normal) > same)) return false;
      if constexpr(D == 3) on_piece.push_back(cp.point);
      return D == 2;
    });
    if constexpr(D == 2) return found;
    else return !are_collinear(on_piece, 1e-6);
  }

  // Whether the points lie within `tolerance` of one line (or are none).
  static bool are_collinear(const std::vector<V>& p, double tolerance) {
    if(p.empty()) return true;
    std::size_t far = 0;
    double d2 = 0;
    for(std::size_t k = 1; k < p.size(); ++k) {
      const double dk = (p[k] - p[0]).squaredNorm();
      if(dk > d2) {
        d2 = dk;
        far = k;
      }
    }
    if(!(d2 > tolerance * tolerance)) return true;
    const V u = (p[far] - p[0]) / std::sqrt(d2);
    return std::none_of(p.begin(), p.end(), [&](const V& q) {
      const V e = q - p[0];
      return (e - e.dot(u) * u).squaredNorm() > tolerance * tolerance;
    });
  }

  Fit select(const std::vector<Fit>& fits) const {
    bool any_supported = false;
    for(const Fit& f : fits) any_supported |= f.supported;
    double lowest = std::numeric_limits<double>::infinity();
    for(const Fit& f : fits)
      if(f.valid && (f.supported || !any_supported)) lowest = (std::min)(lowest, f.energy);
    for(const Fit& f : fits) {
      if(!f.valid || (any_supported && !f.supported)) continue;
      if(f.energy <= 1.05 * lowest + exact_value) return f;
    }
    return Fit();
  }

  Parameters initial_member(const Frame<D>& frame, const Neighborhood<D>& nbh) const {
    std::vector<V> y;
    std::vector<double> w;
    y.reserve(nbh.size());
    w.reserve(nbh.size());
    for(const V& p : nbh.points) {
      const double wi = unit_weight_((p - frame.origin).squaredNorm());
      if(wi <= 0) continue;
      y.push_back(frame.to_frame(p));
      w.push_back(wi);
    }
    return space_.fit(y.data(), w.data(), y.size());
  }

  // The frame at `origin` with the unit normal `n` whose first tangent axis follows the data: in
  // 3D, the major axis of the second moments, about `origin` and weighted around it, of the points
  // of `nbh` projected on the tangent plane, signed by their third moment along it. The starts of
  // a fan (sectors from the first axis) and hence the fits then move with the input under a rigid
  // motion, which `tangent_basis()`, built from the coordinate axes, did not allow (with the
  // origin's offsets of minimize(), see the manual, "Invariance"). An isotropic or symmetric
  // neighbourhood leaves the axis or its sign to rounding.
  Frame<D> frame_from_data(const V& origin, const V& n, const Neighborhood<D>& nbh) const {
    Frame<D> frame = Frame<D>::from_normal(origin, n);
    if constexpr(D == 3) {
      const V t1 = frame.axes.col(0), t2 = frame.axes.col(1);
      Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
      std::vector<std::pair<double, Eigen::Vector2d>> weighted;
      weighted.reserve(nbh.size());
      for(const V& p : nbh.points) {
        const V d = p - origin;
        const double w = unit_weight_(d.squaredNorm());
        if(!(w > 0)) continue;
        const Eigen::Vector2d u(t1.dot(d), t2.dot(d));
        second.noalias() += w * u * u.transpose();
        weighted.emplace_back(w, u);
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(second);
      if(solver.info() != Eigen::Success || !solver.eigenvectors().allFinite()) return frame;
      Eigen::Vector2d major = solver.eigenvectors().col(1);
      double third = 0;
      for(const auto& [w, u] : weighted) {
        const double x = u.dot(major);
        third += w * x * x * x;
      }
      if(third < 0) major = -major;
      const V e1 = (major[0] * t1 + major[1] * t2).normalized();
      if(!e1.allFinite()) return frame;
      frame.axes.col(0) = e1;
      frame.axes.col(1) = n.cross(e1);
    }
    return frame;
  }

  // Starts of the joint optimisation besides Levin's frame (paper, section 4.1): the frame
  // turned by pi/2 (in 3D, each other principal axis of the neighbourhood as the normal), and,
  // for spaces with sharp features, frames at the crease or apex proposed by a plane split.
  void add_starts(const V& r, const V& qL, const Neighborhood<D>& nbh, std::vector<Start>& starts) const {
    std::vector<double> w(nbh.size());
    for(std::size_t i = 0; i < nbh.size(); ++i) w[i] = unit_weight_((nbh.points[i] - qL).squaredNorm());
    const Pca<D> pca = internal::weighted_pca<D>(nbh.points, w);
    if(!pca.valid) return;
    // A flat neighbourhood (the smallest eigenvalue below a tenth of the next) gives a turned
    // frame nothing to fit: those starts are skipped (measured in the benchmark's README).
    if(!rotation_invariant && !(pca.eigenvalues[0] < flat_ratio * pca.eigenvalues[1]))
      for(int axis = 1; axis < D; ++axis)
        starts.push_back({frame_from_data(qL, pca.eigenvectors.col(axis), nbh), std::nullopt});
    if constexpr(internal::has_sharp_features<FunctionSpace>::value) {
      // Proposals see the whole gathered ball (radius: support + 2h) with equal weights, so
      // that a crease at the edge of the support, with few points of weight, is still found.
      std::fill(w.begin(), w.end(), 1.);
      const Pca<D> pca = internal::weighted_pca<D>(nbh.points, w);
      if(!pca.valid) return;
      const auto two = internal::split_in_two<D>(nbh.points, w, pca);
      // only when two hyperplanes explain the points much better than one (four times: at ten,
      // the benchmark's noisy torus had no feature start, and twice as fast P_U wedge, but a
      // query of the noiseless cube 2 h from an edge and 4.5 h from a corner (ratio 0.15) was
      // not reproduced: 6e-3 h off)
      if(two.valid && two.energy < 0.25 * pca.eigenvalues[0]) add_feature_start<2>(r, two.planes, nbh, starts);
      if constexpr(D == 3) {
        const auto three = internal::split_in_three(nbh.points, w, pca);
        if(three.valid && three.energy < 0.25 * (std::min)(two.energy, pca.eigenvalues[0]))
          add_feature_start<3>(r, three.planes, nbh, starts);
      }
    }
  }

  template <int K>
  void add_feature_start(const V& r, const std::array<Hyperplane<D>, K>& planes, const Neighborhood<D>& nbh,
                         std::vector<Start>& starts) const {
    V x;
    if(!internal::intersection_nearest<D, K>(planes, r, x)) return;
    // Orient each hyperplane so that the other pieces lie behind it: the normals are then all
    // outward (convex feature) or all inward (concave), and their sum is the feature's bisector,
    // over which the pieces form a graph.
    std::array<V, K> normals;
    V n = V::Zero();
    for(int k = 0; k < K; ++k) {
      double behind = 0;
      for(int j = 0; j < K; ++j)
        if(j != k) behind += planes[k].distance(planes[j].centroid);
      normals[k] = (behind > 0 ? -1. : 1.) * planes[k].normal;
      n += normals[k];
    }
    if(!(n.norm() > 1e-6)) return;
    Frame<D> frame;
    if constexpr(D == 3 && K == 2) {
      // first tangent axis along the crease, where a fan's first vector starts
      frame = Frame<D>::from_normal(x, n.normalized());
      const V e1 = planes[0].normal.cross(planes[1].normal).normalized();
      frame.axes.col(0) = e1;
      frame.axes.col(1) = frame.normal().cross(e1);
    } else {
      frame = frame_from_data(x, n.normalized(), nbh);
    }
    // The member made of the planes themselves, when the space has it: on noiseless data of a
    // crease or corner, the start is then exact at once. (From `fit()`, a corner start could
    // lose the race or converge in another basin: test_unified_projection's grid around a cube's
    // corner had 35 of 629 cold projections up to 0.24 h off; see the manual, "Starts at features".)
    std::optional<Parameters> member;
    if constexpr(internal::has_member_of_hyperplanes<FunctionSpace>::value) {
      for(V& nk : normals) nk = frame.axes.transpose() * nk;
      Parameters c;
      if(space_.member_of_hyperplanes(normals.data(), K, c)) member = c;
    }
    starts.push_back({frame, member});
  }

  // The neighbourhood with every length divided by h.
  Neighborhood<D> in_units_of_h(const Neighborhood<D>& nbh) const {
    Neighborhood<D> unit = nbh;
    const double inv_h = 1. / this->h_;
    for(V& p : unit.points) p *= inv_h;
    unit.centre *= inv_h;
    unit.radius *= inv_h;
    return unit;
  }

  // Minimises equation 6 (4, 5) from `start` and `c0`, in units of h. The parameters are the
  // tilt angles (R), the frame offsets (T) and the function's parameters (P).
  // `max_evaluations` (0: the options' budget) limits the evaluations of the residuals.
  Fit minimize(const V& r, const Frame<D>& start, const Parameters& c0, const Neighborhood<D>& nbh, double bound,
               int max_evaluations = 0, int stall_window = 0, int watch_window = 0) const {
    constexpr int F = T + R; // parameters of the frame
    constexpr int n = F + P;
    constexpr bool translation_only = optimise_frame && R == 0; // the frame only moves
    constexpr bool analytic_foot = internal::has_foot_derivatives<FunctionSpace>::value;
    using X = Eigen::Matrix<double, n, 1>;
    using Normal_matrix = Eigen::Matrix<double, n, n>;
    using Row = Eigen::Matrix<double, 1, n>;
    // the start's plane, its origin moved to the foot of r
    const double s0 = (start.origin - r).dot(start.normal());
    const auto unpack = [&](const X& x, Frame<D>& f, Parameters& c) {
      // the origin's offsets are along the start's axes (not the coordinate axes, so that the
      // optimiser's scaling and step bound, per parameter, turn with the data)
      if constexpr(optimise_frame && R > 0 && T == D) {
        f = start.moved(V(start.axes * x.template segment<D>(R)), x.template segment<R>(0));
      } else if constexpr(optimise_frame && R > 0) {
        f = start.moved(V::Zero(), x.template segment<R>(0));
        f.origin = r + (s0 + x[R]) * f.normal();
      } else if constexpr(optimise_frame) {
        f = start;
        f.origin += start.axes * x.template head<D>();
      } else {
        f = start;
      }
      for(int j = 0; j < P; ++j) c[j] = x[F + j];
    };
    internal::Minimizer_report<n> report;
    report.x = X::Zero();
    report.converged = true;
    if constexpr(n > 0) {
      // The weighted points of the last evaluation: their indices in `nbh`, weights, frame
      // coordinates, closest points and the gradients of their signed distances in the member's
      // parameters.
      thread_local std::vector<int> active;
      thread_local std::vector<double> w;
      thread_local std::vector<V> y;
      thread_local std::vector<Closest_point<D>> cps;
      thread_local std::vector<Parameters> grads;
      Eigen::VectorXd C_at_last_evaluation = Eigen::VectorXd::Zero(D); // watched by the optimiser
      // The sum of squares of the residuals sqrt(w_i / W) d_i (zero outside the support), of the
      // displacement penalty and of the space's regularisation, and the Gauss-Newton system of
      // their derivatives, accumulated point by point: with the residuals written f_i = a_i d_i,
      // a_i = sqrt(w_i / W), their gradients are u_i - c_i dW, u_i = (d_i dw_i / (2 sqrt(w_i)) +
      // sqrt(w_i) dd_i) / sqrt(W), c_i = d_i sqrt(w_i) / (2 W^1.5), dW = sum_i dw_i, so J^T J and
      // J^T f are sums over the points of products of u_i, c_i and f_i, and of dW.
      const auto evaluate = [&](const X& x, double& value, Normal_matrix& JtJ, X& Jtf) {
        Frame<D> f;
        Parameters c;
        unpack(x, f, c);
        Eigen::Matrix<double, D, P> dS_dc; // the closest point's derivatives (frame coordinates)
        internal::Mat<D> dS_dx;
        // where the space's derivatives are one-sided, the difference quotients' rule below
        const V xr = f.to_frame(r);
        bool exact = false;
        Closest_point<D> S;
        if constexpr(analytic_foot) exact = space_.closest_point_derivatives(c, xr, S, dS_dc, dS_dx);
        else S = space_.closest_point(c, xr);
        const V C = f.to_local(S.point);
        C_at_last_evaluation = C;
        double W = 0;
        active.clear();
        w.clear();
        y.clear();
        for(std::size_t i = 0; i < nbh.size(); ++i) {
          const double wi = unit_weight_((nbh.points[i] - C).squaredNorm());
          if(!(wi > 0)) continue;
          W += wi;
          active.push_back(int(i));
          w.push_back(wi);
          y.push_back(f.to_frame(nbh.points[i]));
        }
        if(!(W > 0) || !C.allFinite()) return false;
        const std::size_t m = y.size();
        cps.resize(m);
        grads.resize(m);
        closest_points(c, y.data(), m, cps.data(), grads.data());
        double sum = 0;
        for(std::size_t k = 0; k < m; ++k) sum += w[k] * cps[k].signed_distance * cps[k].signed_distance;
        const double excess = (C - r).norm() - bound;
        const double penalty = excess > 0 ? 10. * excess : 0.;
        double regularization = 0;
        if constexpr(internal::has_regularization<FunctionSpace>::value) regularization = space_.regularization(c, 1.);
        value = sum / W + penalty * penalty + regularization * regularization;
        if(!std::isfinite(value)) return false;

        // The derivatives of C(r) and of the frame (no input point involved: cheap).
        Eigen::Matrix<double, D, n> dC;
        std::array<internal::Mat<D>, F + 1> dA;
        std::array<V, F + 1> Adq; // A^T dq
        std::array<double, n> step;
        for(int j = 0; j < n; ++j) step[j] = 1e-7 * (1. + std::abs(x[j]));
        // C(r) jumps where the closest piece of a fan changes: when the one-sided differences
        // disagree, the smaller one is kept (the derivative on the side of the query's piece)
        const auto difference = [&](int j, const V& plus, const V& minus) {
          const V forward = (plus - C) / step[j], backward = (C - minus) / step[j];
          if((forward - backward).norm() <= 1e-2 * (forward.norm() + backward.norm()) + 1e-6)
            dC.col(j) = 0.5 * (forward + backward);
          else
            dC.col(j) = forward.norm() < backward.norm() ? forward : backward;
        };
        if(exact && translation_only) {
          // C = q + A S(A^T (r - q)) with the origin q moving along the axes A
          for(int j = 0; j < F; ++j) {
            Adq[j] = V::Unit(j);
            dC.col(j) = f.axes * (V::Unit(j) - dS_dx.col(j));
          }
        } else if constexpr(F > 0) {
          // r's closest points on the member in the moved frames, in one batch (the member is the same)
          std::array<Frame<D>, 2 * F> moved;
          std::array<V, 2 * F> moved_r;
          std::array<Closest_point<D>, 2 * F> moved_cp;
          for(int j = 0; j < F; ++j)
            for(int side = 0; side < 2; ++side) {
              X xs = x;
              xs[j] += side == 0 ? step[j] : -step[j];
              Parameters unused;
              unpack(xs, moved[2 * j + side], unused);
              moved_r[2 * j + side] = moved[2 * j + side].to_frame(r);
            }
          closest_points(c, moved_r.data(), 2 * F, moved_cp.data(), nullptr);
          for(int j = 0; j < F; ++j) {
            difference(j, moved[2 * j].to_local(moved_cp[2 * j].point), moved[2 * j + 1].to_local(moved_cp[2 * j + 1].point));
            dA[j] = (moved[2 * j].axes - moved[2 * j + 1].axes) / (2. * step[j]);
            Adq[j] = f.axes.transpose() * ((moved[2 * j].origin - moved[2 * j + 1].origin) / (2. * step[j]));
          }
        }
        if(exact) {
          dC.template rightCols<P>() = f.axes * dS_dc;
        } else {
          for(int j = F; j < n; ++j) {
            const double eps = step[j];
            Parameters cp = c, cm = c;
            cp[j - F] += eps;
            cm[j - F] -= eps;
            difference(j, f.to_local(space_.closest_point(cp, xr).point),
                       f.to_local(space_.closest_point(cm, xr).point));
            if constexpr(!internal::has_closest_points<FunctionSpace>::value) {
              // the member's parameters: central differences of each weighted point's distance
              for(std::size_t k = 0; k < m; ++k)
                grads[k][j - F] = (space_.closest_point(cp, y[k]).signed_distance - space_.closest_point(cm, y[k]).signed_distance) / (2. * eps);
            }
          }
        }
        // the rows u_i (times sqrt(W)) of the weighted points in a matrix, for one product U^T U
        thread_local Eigen::Matrix<double, Eigen::Dynamic, n> U;
        thread_local Eigen::VectorXd cu, fu;
        U.resize(Eigen::Index(m), n);
        cu.resize(Eigen::Index(m));
        fu.resize(Eigen::Index(m));
        Row dW = Row::Zero();
        for(std::size_t k = 0; k < m; ++k) {
          const int i = active[k];
          const Closest_point<D>& cp = cps[k];
          const double d = cp.signed_distance, sw = std::sqrt(w[k]);
          // d w_i = w'(|p_i - C|^2) (-2 (p_i - C) . dC)
          const V e = nbh.points[i] - C;
          const Row dw = (-2. * unit_weight_.derivative(e.squaredNorm(), w[k])) * (e.transpose() * dC);
          // the gradient of the signed distance with respect to the point, in frame coordinates
          V g = cp.normal;
          if(std::abs(d) > 0) g = (y[k] - cp.point) / d;
          Row dd;
          for(int j = 0; j < F; ++j) {
            // the frame coordinates y = A^T (p - q) move by dA^T (p - q) - A^T dq (dA = 0 when the
            // frame only moves)
            if constexpr(translation_only) dd[j] = -g.dot(Adq[j]);
            else dd[j] = g.dot(dA[j].transpose() * (nbh.points[i] - f.origin) - Adq[j]);
          }
          for(int j = 0; j < P; ++j) dd[F + j] = grads[k][j];
          U.row(Eigen::Index(k)) = (sw > 1e-150 ? d / (2. * sw) : 0.) * dw + sw * dd;
          cu[Eigen::Index(k)] = 0.5 * d * sw;
          fu[Eigen::Index(k)] = sw * d;
          dW += dw;
        }
        Normal_matrix Suu;
        Suu.noalias() = U.transpose() * U;
        const X Scu = U.transpose() * cu, Sfu = U.transpose() * fu;
        const double Scc = cu.squaredNorm(), Sfc = cu.dot(fu);
        const X dWt = dW.transpose();
        JtJ = Suu / W - (dWt * Scu.transpose() + Scu * dW) / (W * W) + (Scc / (W * W * W)) * dWt * dW;
        Jtf = Sfu / W - (Sfc / (W * W)) * dWt;
        if(excess > 0) {
          const X row = (10. * ((C - r).normalized().transpose() * dC)).transpose();
          JtJ.noalias() += row * row.transpose();
          Jtf += penalty * row;
        }
        if constexpr(internal::has_regularization<FunctionSpace>::value) {
          X row = X::Zero();
          for(int j = 0; j < P; ++j) {
            const double eps = 1e-6 * (1. + std::abs(c[j]));
            Parameters cp = c, cm = c;
            cp[j] += eps;
            cm[j] -= eps;
            row[F + j] = (space_.regularization(cp, 1.) - space_.regularization(cm, 1.)) / (2. * eps);
          }
          JtJ.noalias() += row * row.transpose();
          Jtf += regularization * row;
        }
        return JtJ.allFinite() && Jtf.allFinite();
      };

      X x0 = X::Zero();
      for(int j = 0; j < P; ++j) x0[F + j] = c0[j];
      Minimizer_settings settings;
      // An exact fit stops at once. On noisy data, the energy has long, nearly flat valleys
      // (moving the origin tangentially while tilting the frame and bending the function changes
      // the surface near C(r) very little), along which the steps would crawl for hundreds of
      // iterations, gaining a few 1e-5 of the energy: stop when 10 evaluations gain less than 1e-6,
      // or when 10 improving ones move C(r) by less than 1e-5 h, or 1% of the RMS residual when
      // that is larger, and gain less than 1% (user manual, "Stopping on noisy data").
      settings.absolute_value = exact_value;
      settings.stall_tolerance = 1e-6;
      settings.watched = &C_at_last_evaluation;
      settings.watch_tolerance = 1e-5;
      settings.watch_relative = 1e-2;
      // A parameter that hardly moves the residuals (a fan vector turning within its face, whose
      // two cones stay coplanar) would get a tiny damping, and then huge trial steps: the floor
      // bounds them (see the manual, "Scaling of the parameters").
      settings.scaling_floor = scaling_floor;
      settings.max_evaluations =
        max_evaluations > 0 ? max_evaluations : this->options_.max_evaluations * (n + 1) / (D + 1);
      if(stall_window > 0) settings.stall_evaluations = stall_window;
      if(watch_window > 0) settings.watch_evaluations = watch_window;
      report = internal::levenberg_marquardt<n>(evaluate, x0, settings);

}
    Fit fit;
    unpack(report.x, fit.frame, fit.c);
    fit.iterations = report.iterations;
    fit.converged = report.converged;
    fit.at_r = space_.closest_point(fit.c, fit.frame.to_frame(r));
    fit.C = fit.frame.to_local(fit.at_r.point);
    // the energy of equation 6 without the displacement penalty
    double sum_w = 0, E = 0;
    visit_weighted_points(fit, nbh, [&](double wi, const Closest_point<D>& cp) {
      sum_w += wi;
      E += wi * cp.signed_distance * cp.signed_distance;
      return false;
    });
    fit.energy = sum_w > 0 ? E / sum_w : std::numeric_limits<double>::infinity();
    // the objective: the energy plus the displacement penalty (and the regularisation)
    fit.value = n > 0 ? report.value : fit.energy;
    fit.valid = std::isfinite(fit.value) && std::isfinite(fit.energy) && fit.C.allFinite() &&
                (fit.C - r).norm() <= bound * (1 + 1e-9) && fit.value < 1e5;
    return fit;
  }

  // The weights of the points `unit` (units of h), centred on the fit's C(r).
  std::vector<double> weights_at(const Fit& fit, const Neighborhood<D>& unit) const {
    std::vector<double> w(unit.size());
    for(std::size_t i = 0; i < unit.size(); ++i) w[i] = unit_weight_((unit.points[i] - fit.C).squaredNorm());
    return w;
  }

  // Whether the weights `w` count as enough points (see `minimum_effective_points()`).
  bool has_effective_points(const std::vector<double>& w) const {
    double sum = 0, sum_of_squares = 0;
    for(const double wi : w) {
      sum += wi;
      sum_of_squares += wi * wi;
    }
    return this->enough_effective_points(sum, sum_of_squares);
  }

  // `r`, `fit` and `unit` in units of h, `w` the weights of `unit` at C(r); `nbh` is `unit` in
  // local coordinates.
  Result make_result(const V& r, const Fit& fit, const Neighborhood<D>& unit, const std::vector<double>& w,
                     const Neighborhood<D>& nbh, int iterations) const {
    const double h = this->h_;
    const Closest_point<D>& cp = fit.at_r;
    V point = fit.C;
    V normal = fit.frame.vector_to_local(cp.normal);
    if constexpr(kind == Operator_kind::SINGLE_PHASE) {
      // P_S(r) = g(h(r), f(h(r))): the projection along the frame normal (section 3.2).
      const V y = fit.frame.to_frame(r);
      const auto vertical = space_.vertical_projection(fit.c, y);
      point = fit.frame.to_local(vertical.point);
      normal = fit.frame.vector_to_local(vertical.normal);
    }
    point *= h;
    normal.normalize();
    normal *= this->orientation(point, normal, nbh);
    if(!point.allFinite() || !normal.allFinite()) return fallback(this->samples().to_world(r * h), iterations);
    Result res;
    std::array<V, D - 1> tangents;
    for(int j = 0; j < D - 1; ++j) tangents[j] = fit.frame.axes.col(j);
    this->set_geometry(res, point, normal, V(h * fit.frame.origin), fit.frame.normal(), tangents);
    res.coefficients.assign(fit.c.data(), fit.c.data() + P);
    res.fit_kind = Local_fit_kind::CLOSEST_POINT;
    res.energy = fit.energy * h * h;
    res.iterations = iterations;
    res.number_of_neighbors = nbh.size();
    if constexpr(kind != Operator_kind::SINGLE_PHASE) {
      // A C(r) on a feature of the member is one of the data only if no single hyperplane
      // explains the weighted points as well as the fit: a fan can also have an apex or a crease
      // on a flat region (coplanar faces but one, which no point supports).
      const auto pca = internal::weighted_pca<D>(unit.points, w);
      const bool is_feature = pca.valid && pca.eigenvalues[0] > 4. * fit.energy + 1e-14;
      res.is_on_feature = cp.is_on_feature && is_feature;
      if(res.is_on_feature)
        res.feature_direction = internal::Kernel_types<GeomTraits, D>::to_vector(fit.frame.vector_to_local(cp.direction));
    }
    res.status = fit.converged ? Projection_status::CONVERGED : Projection_status::NOT_CONVERGED;
    return res;
  }

  // The gathered ball: the weight's support around Levin's frame origin plus this margin (units
  // of h), within which C(r) may move before the ball is gathered again around it. A margin of
  // 1 h was 10% faster, but the feature proposals, which see the whole ball, then missed a
  // cube's corner: test_unified_projection's invariance test found a fit 2e-8 off.
  static constexpr double gather_margin = 2;
  // The margin of the race's ball around Levin's frame origin (units of h; see project_impl()).
  // At 0.5, the noisy cube of test_sharp_features lost its crease vertex (0.097 h off, against
  // a tolerance of 0.071 h).
  static constexpr double race_margin = 1;
  // The margin of the ball gathered for a continued fit (units of h; see project_impl()).
  static constexpr double warm_margin = 0.5;
  // The eigenvalue ratio under which a neighbourhood is flat (see add_starts()).
  static constexpr double flat_ratio = 0.1;
  // The budget of evaluations of each start before the selection. The starts of a space closed
  // under rotations (the wedge fan) are the planes of the data, exact or nearly so, and are told
  // apart within 10; the tilted starts of the other spaces (the quadratic) need 30 (with 10, P_U
  // quadratic ended 0.17 h off a 60-degree 2D apex, against 0.10 h: test pinch_is_gone...).
  static constexpr int race_evaluations = rotation_invariant ? 10 : 30;
  // The optimiser's stop windows (evaluations) when continuing a nearby query's fit.
  static constexpr int warm_window = 2;
  // A sum of squares (units of h^2) below which a fit is exact: every residual below 1e-13 h.
  static constexpr double exact_value = 1e-26;
  // An energy (units of h^2; an RMS distance of 1e-3 h) below which a converged fit nearly fits
  // the data, and the factor of the leader's race value within which its rivals then run to
  // convergence (see project()). Measured on the benchmark's 100 queries: P_U wedge 6% more
  // iterations on the noiseless cube, none on the torus and the noisy cube.
  static constexpr double near_exact_energy = 1e-6;
  static constexpr double rival_factor = 10;
  // The floor of the optimiser's parameter scales, relative to the largest (see minimize()).
  static constexpr double scaling_floor = 1e-2;

  static Projection_options with_bandwidth(Projection_options options, double h) {
    if(h > 0) options.bandwidth = h; // derived once, by the base
    return options;
  }

  // Levin's answer, marked as a fallback, when the joint optimisation fails.
  Result fallback(const Point& query, int iterations) const {
    Result res = levin_.project(query);
    res.iterations += iterations;
    if(res.is_success()) res.status = Projection_status::LEVIN_FALLBACK;
    return res;
  }

  using Base::unit_weight_; // the optimisation works in units of h
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
