// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_MIXED_PROJECTION_H
#define CGAL_MLS_PROJECTION_MIXED_PROJECTION_H

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Quadratic_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>

#include <algorithm>
#include <memory>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionOperators
/// A closest-point projection over the union of a smooth and a sharp function space (the
/// "mixed" space; beyond the paper, in the spirit of its enriched spaces): each query is
/// projected with both, and the sharp fit is kept only when it explains the data clearly
/// better than the smooth one,
/// \f[ E_{\mathrm{sharp}} < \rho \, E_{\mathrm{smooth}}, \f]
/// where \f$E\f$ is the energy of the final fit (weighted mean squared closest-point distance) and
/// \f$\rho\f$ is the `sharp_preference` (default 0.5). The ratio is the complexity penalty: the
/// wedge fan has more parameters than the quadratic (8 against 3 in 3D) and, on noisy smooth
/// data, its extra freedom lowers the energy by a small factor only (it fits a fold into the
/// noise), whereas at a crease the quadratic cannot follow the data and its energy is larger by
/// orders of magnitude. So curved regions keep the quadratic's second-order accuracy and creases
/// are reproduced by the fan. A fit that did not converge (its energy is that of the best
/// point found, or of Levin's fall-back) competes all the same: an exact fan that exhausted its
/// budget near zero energy must still win over a converged quadratic that cannot fit a crease.
///
/// The result is the result of the kept fit (its `coefficients` are those of its space: their
/// number tells which); `iterations` adds both.
///
/// \tparam GeomTraits a CGAL kernel
/// \tparam D the dimension, 2 or 3
/// \tparam kind `Operator_kind::UNIFIED` or `Operator_kind::ENRICHED` (the sharp space is not a graph)
/// \tparam SmoothSpace a model of `MLSFunctionSpace`, by default `Quadratic_function_space<D>`
/// \tparam SharpSpace a model of `MLSFunctionSpace`, by default `Wedge_fan_function_space<D>`
template <class GeomTraits, int D, Operator_kind kind = Operator_kind::UNIFIED,
          class SmoothSpace = Quadratic_function_space<D>, class SharpSpace = Wedge_fan_function_space<D>>
class Mixed_projection {
  static_assert(kind != Operator_kind::SINGLE_PHASE, "Mixed_projection: the sharp space is not a graph, use P_U or P_E");
  static_assert(SmoothSpace::ambient_dimension == D && SharpSpace::ambient_dimension == D,
                "Mixed_projection: both function spaces must have dimension D");

public:
  /// The two operators combined, and the types of `Closest_point_projection`.
  /// @{
  using Smooth_projection = Closest_point_projection<GeomTraits, SmoothSpace, kind>;
  using Sharp_projection = Closest_point_projection<GeomTraits, SharpSpace, kind>;
  using FT = typename Smooth_projection::FT;
  using Point = typename Smooth_projection::Point;
  using Vector = typename Smooth_projection::Vector;
  using Samples = typename Smooth_projection::Samples;
  using Result = typename Smooth_projection::Result;
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

  /// Shares an existing sample set (and its kd-tree) with other operators.
  explicit Mixed_projection(std::shared_ptr<const Samples> samples, const Projection_options& options = Projection_options(),
                            double sharp_preference = default_sharp_preference)
    : smooth_(samples, options), sharp_(samples, with_bandwidth(options, smooth_.bandwidth())),
      sharp_preference_(sharp_preference) {
    CGAL_precondition(sharp_preference > 0 && sharp_preference <= 1);
  }

  /// The fewest input points a projection needs (the larger of the two operators').
  static constexpr std::size_t minimum_points() {
    return (std::max)(Smooth_projection::minimum_points(), Sharp_projection::minimum_points());
  }

  /// Projects `query` with both operators and keeps the sharp result when `prefers_sharp()`.
  Result project(const Point& query) const { return choose(smooth_.project(query), sharp_.project(query)); }

  /// The state of a sequence of warm-started projections: that of each operator.
  struct Warm_start {
    typename Smooth_projection::Warm_start smooth; ///< the smooth operator's
    typename Sharp_projection::Warm_start sharp;   ///< the sharp operator's
    /// Forgets the last fits.
    void reset() {
      smooth.reset();
      sharp.reset();
    }
  };

  /// The same with both operators warm-started (see `Closest_point_projection::project()`).
  Result project(const Point& query, Warm_start& warm) const {
    return choose(smooth_.project(query, warm.smooth), sharp_.project(query, warm.sharp));
  }

  /// Same as `project()`.
  Result operator()(const Point& query) const { return project(query); }

  /// Whether the sharp fit `sharp` is kept against the smooth fit `smooth` of the same query.
  bool prefers_sharp(const Result& smooth, const Result& sharp) const {
    if(!sharp.is_success()) return false;
    if(!smooth.is_success()) return true;
    return sharp.energy < sharp_preference_ * smooth.energy;
  }

  /// The bandwidth \f$h\f$, the preference factor of the sharp space, the options, the shared
  /// sample set, and the two operators.
  /// @{
  double bandwidth() const { return smooth_.bandwidth(); }
  double sharp_preference() const { return sharp_preference_; }
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
    return kept;
  }

  static Projection_options with_bandwidth(Projection_options options, double h) {
    if(h > 0) options.bandwidth = h; // derived once, by the smooth operator
    return options;
  }

  Smooth_projection smooth_;
  Sharp_projection sharp_;
  double sharp_preference_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_MIXED_PROJECTION_H
