// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MIXED_PROJECTION_H
#define CGAL_MLS_PROJECTION_MIXED_PROJECTION_H

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/internal/projection/noise_level.h>

#include <algorithm>
#include <memory>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionOperators
/// The projection that keeps smooth parts smooth and creases sharp (the "mixed" space; beyond
/// the paper, in the spirit of its enriched spaces): Levin's \f$\mathcal{P}_L\f$ with the full
/// quadratic projects every query, and the closest-point operator with a sharp space (the wedge
/// fan) projects only the queries whose quadratic does not explain the data:
///
/// 1. <b>Screening.</b> The fan is tried where \f$\mathcal{P}_L\f$ fails or its energy (weighted
///    mean squared residual) exceeds the noise threshold
///    \f[ \tau = \max\big((\rho h)^2,\; \kappa^2 \hat\sigma^2\big), \f]
///    with \f$\hat\sigma^2\f$ the variance of the noise estimated from the input (`noise_variance()`:
///    the residuals of the 12 nearest neighbours of up to 512 input points about their
///    least-squares quadratic, at a scale where coarse samplings of creased shapes still have
///    points away from every crease),
///    \f$\kappa^2 = 4\f$ (below it, on the benchmark's noisy scans, the fan lands nearer to the
///    surface than the quadratic on about half of the queries, and further off on the worst ones)
///    and \f$\rho = 0.01\f$ (on noiseless data, a residual of a hundredth of \f$h\f$ is what the
///    quadratic leaves on curved smooth parts).
/// 2. <b>Model selection.</b> Where the fan is tried, it is kept only when it explains the data
///    clearly better than the quadratic, \f$E_{\mathrm{sharp}} < \sigma\, E_{\mathrm{smooth}}\f$,
///    \f$\sigma\f$ = `sharp_preference` (default 0.5). The ratio is the complexity penalty: the
///    fan has more parameters (8 against 6 in 3D) and, on noisy smooth data, its extra freedom
///    lowers the energy by a small factor only, whereas at a crease the quadratic cannot follow
///    the data and its energy is larger by orders of magnitude.
/// 3. <b>The sharp operator's bandwidth</b> is \f$h_s = \min(h, \max(s\,h, h_{\min}))\f$
///    (`sharp_bandwidth()`), with
///    \f[ s = s_0 + \lambda\,\hat\sigma / h, \f]
///    \f$s_0 = 0.5\f$, \f$\lambda = 10\f$, and \f$h_{\min}\f$ the bandwidth whose weight support
///    reaches, on average, the \f$3m\f$-th nearest input point, \f$m\f$ = the sharp operator's
///    `minimum_points()` (11 in 3D): the weighted points then count as about \f$m\f$ independent
///    ones. A fan has no bias on its own planes: its error comes from what it cannot follow within
///    its support (a curved face next to a crease, the facets of a tessellated surface), which
///    shrinks with the support, while noise needs the whole support to average out, and the fit
///    needs points. So on clean data the fan is fitted over about 0.6 times the default bandwidth
///    (some 33 points), from \f$\hat\sigma = h/20\f$ over all of it (manual, section "The Mixed
///    Space", "The bandwidth of the fan").
///
/// So the smooth parts cost one \f$\mathcal{P}_L\f$ (a few tens of microseconds) and keep its
/// second-order accuracy, and creases and corners are reproduced by the fan. The result is the
/// result of the fit kept (its `fit_kind` tells which: `Local_fit_kind::LEVIN` for the quadratic,
/// `Local_fit_kind::CLOSEST_POINT` for the sharp space); `iterations` adds both.
///
/// \tparam GeomTraits a CGAL kernel
/// \tparam D the dimension, 2 or 3
/// \tparam kind `Operator_kind::UNIFIED` or `Operator_kind::ENRICHED` (the sharp space is not a graph)
/// \tparam SharpSpace a model of `MLSFunctionSpace`, by default `Wedge_fan_function_space<D>`
template <class GeomTraits, int D, Operator_kind kind = Operator_kind::UNIFIED,
          class SharpSpace = Wedge_fan_function_space<D>>
class Mixed_projection {
  static_assert(kind != Operator_kind::SINGLE_PHASE, "Mixed_projection: the sharp space is not a graph, use P_U or P_E");
  static_assert(SharpSpace::ambient_dimension == D, "Mixed_projection: the sharp space must have dimension D");

public:
  /// The two operators combined, and the types of `Closest_point_projection`.
  /// @{
  using Smooth_projection = Levin_projection<GeomTraits, Polynomial_function_space<D>>;
  using Sharp_projection = Closest_point_projection<GeomTraits, SharpSpace, kind>;
  using FT = typename Sharp_projection::FT;
  using Point = typename Sharp_projection::Point;
  using Vector = typename Sharp_projection::Vector;
  using Samples = typename Sharp_projection::Samples;
  using Result = typename Sharp_projection::Result;
  /// @}
  /// The ambient dimension.
  static constexpr int dimension = D;
  /// The default of `sharp_preference`.
  static constexpr double default_sharp_preference = 0.5;

  /// Builds the sample set of `points` (named parameters `point_map`, `normal_map`, see `Sample_set`).
  /// \pre `0 < sharp_preference <= 1`
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<!internal::is_shared_ptr<PointRange>::value>>
  explicit Mixed_projection(const PointRange& points, const Projection_options& options = Projection_options(),
                            const NamedParameters& np = parameters::default_values(),
                            double sharp_preference = default_sharp_preference)
    : Mixed_projection(std::make_shared<const Samples>(points, np), options, sharp_preference) {}

  /// Shares an existing sample set (and its kd-tree) with other operators. Estimates the noise
  /// level of the samples (up to 512 neighbourhoods of 12 points).
  explicit Mixed_projection(std::shared_ptr<const Samples> samples, const Projection_options& options = Projection_options(),
                            double sharp_preference = default_sharp_preference)
    : smooth_(samples, options), sharp_preference_(sharp_preference),
      noise_variance_(internal::estimate_noise_variance(*samples)),
      threshold_(internal::screening_threshold(bandwidth(), noise_variance_, internal::projection_noise_margin)),
      sharp_(samples, with_bandwidth(options, sharp_bandwidth(*samples, bandwidth(), smooth_.weight(), noise_variance_))) {
    CGAL_precondition(sharp_preference > 0 && sharp_preference <= 1);
  }

  /// The fewest input points a projection needs (the larger of the two operators').
  static constexpr std::size_t minimum_points() {
    return (std::max)(Smooth_projection::minimum_points(), Sharp_projection::minimum_points());
  }

  /// Projects `query` by \f$\mathcal{P}_L\f$, and by the sharp operator where `needs_sharp()`.
  Result project(const Point& query) const {
    Result smooth = smooth_.project(query);
    return needs_sharp(smooth) ? choose(std::move(smooth), sharp_.project(query)) : smooth;
  }

  /// The state of a sequence of warm-started projections: that of the sharp operator.
  struct Warm_start {
    typename Sharp_projection::Warm_start sharp; ///< the sharp operator's
    /// Forgets the last fit.
    void reset() { sharp.reset(); }
  };

  /// The same with the sharp operator warm-started (see `Closest_point_projection::project()`).
  Result project(const Point& query, Warm_start& warm) const {
    Result smooth = smooth_.project(query);
    return needs_sharp(smooth) ? choose(std::move(smooth), sharp_.project(query, warm.sharp)) : smooth;
  }

  /// Same as `project()`.
  Result operator()(const Point& query) const { return project(query); }

  /// Whether the sharp operator is tried after the smooth result `smooth` (the screening).
  bool needs_sharp(const Result& smooth) const { return !smooth.is_success() || !(smooth.energy <= threshold_); }

  /// Whether the sharp fit `sharp` is kept against the smooth fit `smooth` of the same query.
  bool prefers_sharp(const Result& smooth, const Result& sharp) const {
    if(!sharp.is_success()) return false;
    if(!smooth.is_success()) return true;
    return sharp.energy < sharp_preference_ * smooth.energy;
  }

  /// The bandwidth \f$h\f$ (the smooth operator's and the options'), the sharp operator's
  /// \f$h_s\f$, the weight function (the smooth operator's), the preference factor of the sharp
  /// space, the estimated noise variance \f$\hat\sigma^2\f$ of the samples, the noise threshold
  /// \f$\tau\f$ of the screening (a squared length), the options, the shared sample set, and the
  /// two operators.
  /// @{
  double bandwidth() const { return smooth_.bandwidth(); }
  double sharp_bandwidth() const { return sharp_.bandwidth(); }
  const Weight_function& weight() const { return smooth_.weight(); }
  double sharp_preference() const { return sharp_preference_; }
  double noise_variance() const { return noise_variance_; }
  double screening_threshold() const { return threshold_; }
  const Projection_options& options() const { return smooth_.options(); }
  const Samples& samples() const { return smooth_.samples(); }
  const std::shared_ptr<const Samples>& shared_samples() const { return smooth_.shared_samples(); }
  const Smooth_projection& smooth_projection() const { return smooth_; }
  const Sharp_projection& sharp_projection() const { return sharp_; }
  /// @}

private:
  // The result of the fit kept, with the iterations of both.
  Result choose(Result smooth, Result sharp) const {
    Result& kept = prefers_sharp(smooth, sharp) ? sharp : smooth;
    kept.iterations = smooth.iterations + sharp.iterations;
    return std::move(kept);
  }

  static Projection_options with_bandwidth(Projection_options options, double h) {
    if(h > 0) options.bandwidth = h; // derived once, by the smooth operator
    return options;
  }

  // h_s of the class documentation, given h and the smooth operator's weight (0 without h).
  static double sharp_bandwidth(const Samples& samples, double h, const Weight_function& weight, double noise_variance) {
    constexpr double s0 = 0.5, lambda = 10;
    const double s = s0 + lambda * std::sqrt(noise_variance) / h;
    if(!(h > 0) || !(s < 1)) return h;
    // the mean distance to the 3m-th neighbour, over the weight's support radius in units of h
    const double h_min = samples.mean_kth_neighbor_distance(3 * Sharp_projection::minimum_points(), 2000) /
                         (weight.support_radius() / h);
    return (std::min)(h, (std::max)(s * h, h_min));
  }

  Smooth_projection smooth_;
  double sharp_preference_;
  double noise_variance_;
  double threshold_;
  Sharp_projection sharp_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MIXED_PROJECTION_H
