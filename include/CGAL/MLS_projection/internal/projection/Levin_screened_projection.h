// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A closest-point operator that finds creases (the wedge fan, alone or in Mixed_projection),
// screened by Levin's operator: every query is projected first with P_L (quadratic, about
// 0.3 ms); where P_L's fit explains the data (its energy at most a threshold), its result is
// kept; elsewhere (near creases and corners, where the quadratic cannot follow the data) the
// closest-point operator projects the query. Used by MLS_implicit_function (the seeds) and by
// mls_surface_reconstruction (the feature detection), where most of the surface is smooth and
// the closest-point operators cost 10 to 500 times P_L per query.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_SCREENED_PROJECTION_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_SCREENED_PROJECTION_H

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/internal/projection/noise_level.h>

#include <memory>
#include <type_traits>

namespace CGAL {
namespace MLS {
namespace internal {

// Whether a projection operator finds creases (its results' `is_on_feature`): the wedge fan,
// alone or in the mixed space.
template <class Projection> struct finds_features : std::false_type {};
template <class K, int N, Operator_kind kind>
struct finds_features<Closest_point_projection<K, Wedge_fan_function_space<3, N>, kind>> : std::true_type {};
template <class K, Operator_kind kind, class Sharp>
struct finds_features<Mixed_projection<K, 3, kind, Sharp>> : std::true_type {};

template <class Projection> struct is_mixed_projection : std::false_type {};
template <class K, int D, Operator_kind kind, class Sharp>
struct is_mixed_projection<Mixed_projection<K, D, kind, Sharp>> : std::true_type {};

// The noise variance of the samples of `projection` (see estimate_noise_variance()): the mixed
// operator's, which estimated it at construction.
template <class Projection>
double noise_variance(const Projection& projection) {
  if constexpr(is_mixed_projection<Projection>::value) return projection.noise_variance();
  else return estimate_noise_variance(projection.samples());
}

/// `Projection` (a model of `finds_features`) screened by P_L with a quadratic: `project(q)` is
/// P_L(q) when that succeeds with `energy <= threshold` (absolute squared length), else the
/// operator's projection; for `Mixed_projection`, only its sharp operator runs then, and its fit
/// is kept when `prefers_sharp(P_L(q), sharp)` (P_L's quadratic stands for the smooth space: its
/// energy, a weighted mean squared residual too, is at least that of the closest-point quadratic),
/// else P_L's. A negative threshold turns the screening off: the operator projects every query.
/// Cheap to copy, `project()` is `const` and thread-safe. Exposes what `project_points()` and
/// `detect_sharp_features()` need (`Sharp_projection` for the latter's helper points).
template <class Projection>
class Levin_screened_projection {
  static_assert(finds_features<Projection>::value, "Levin_screened_projection: an operator that finds features");

public:
  using Operator = Projection;
  using Geom_traits = typename Projection::Samples::Geom_traits;
  using Levin = Levin_projection<Geom_traits, Polynomial_function_space<3>>;
  using FT = typename Projection::FT;
  using Point = typename Projection::Point;
  using Vector = typename Projection::Vector;
  using Samples = typename Projection::Samples;
  using Result = typename Projection::Result;
  static constexpr int dimension = 3;
  // detect_sharp_features reads the sharp function space from `Sharp_projection::Function_space`
  template <class P, class = void> struct sharp_of { using type = P; };
  template <class P> struct sharp_of<P, std::void_t<typename P::Sharp_projection>> { using type = typename P::Sharp_projection; };
  using Sharp_projection = typename sharp_of<Projection>::type;

  Levin_screened_projection(const Projection& projection, double threshold)
    : operator_(projection), levin_(projection.shared_samples(), levin_options(projection)), threshold_(threshold) {}

  /// P_L's projection of `q` (the screening's first step).
  Result levin_project(const Point& q) const { return levin_.project(q); }

  /// The projection, given P_L's result `levin` of the same query.
  Result project(const Point& q, const Result& levin) const {
    if(threshold_ >= 0 && levin.is_success() && levin.energy <= threshold_) return levin;
    if(threshold_ < 0) return operator_.project(q);
    if constexpr(std::is_same<Sharp_projection, Projection>::value) {
      Result r = operator_.project(q);
      return r;
    } else {
      Result sharp = operator_.sharp_projection().project(q);
      const Result* kept = &levin;
      if(operator_.prefers_sharp(levin, sharp)) kept = &sharp;
      Result out = *kept;
      out.iterations = levin.iterations + sharp.iterations;
      return out;
    }
  }

  Result project(const Point& q) const {
    if(threshold_ < 0) return operator_.project(q);
    return project(q, levin_.project(q));
  }
  Result operator()(const Point& q) const { return project(q); }

  /// Whether a P_L result is kept as it is (not handed to the operator).
  bool keeps(const Result& levin) const { return threshold_ >= 0 && levin.is_success() && levin.energy <= threshold_; }

  double threshold() const { return threshold_; }
  double bandwidth() const { return operator_.bandwidth(); }
  const Weight_function& weight() const { return operator_.weight(); }
  const Samples& samples() const { return operator_.samples(); }
  const std::shared_ptr<const Samples>& shared_samples() const { return operator_.shared_samples(); }
  const Projection_options& options() const { return operator_.options(); }
  const Projection& screened_operator() const { return operator_; }
  const Levin& levin() const { return levin_; }
  /// For `detect_sharp_features`: the operator's sharp projection (itself when not mixed).
  const Sharp_projection& sharp_projection() const {
    if constexpr(std::is_same<Sharp_projection, Projection>::value) return operator_;
    else return operator_.sharp_projection();
  }

private:
  static Projection_options levin_options(const Projection& p) {
    Projection_options o = p.options();
    o.bandwidth = p.bandwidth(); // the same h as the operator's, derived once
    return o;
  }

  Projection operator_;
  Levin levin_;
  double threshold_;
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_LEVIN_SCREENED_PROJECTION_H
