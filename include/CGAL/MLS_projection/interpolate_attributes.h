// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERPOLATE_ATTRIBUTES_H
#define CGAL_MLS_PROJECTION_INTERPOLATE_ATTRIBUTES_H

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/internal/projection/Levin_screened_projection.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>
#include <CGAL/MLS_projection/internal/projection/Neighborhood.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

// Calls `f(space, unit, is_graph, weight)` with the function space whose member `fit` holds (told
// by its `fit_kind`), the length unit of its frame coordinates (1, or h for the
// closest-point operators), whether `f` must use the space's `height()` (a graph fitted by
// Levin's operator) or its `closest_point()`, and the weight function of the operator that made
// the fit; returns false (without calling `f`) when the fit is of no known space.
template <class Projection> struct Fit_space_visitor;

template <class K, class S>
struct Fit_space_visitor<Levin_projection<K, S>> {
  template <class Result, class F>
  static bool visit(const Levin_projection<K, S>& p, const Result& fit, F&& f) {
    if(fit.fit_kind != Local_fit_kind::LEVIN || fit.coefficients.size() != std::size_t(S::number_of_parameters)) return false;
    f(S(), 1., std::true_type(), p.weight());
    return true;
  }
};

template <class K, class S, Operator_kind kind>
struct Fit_space_visitor<Closest_point_projection<K, S, kind>> {
  template <class Result, class F>
  static bool visit(const Closest_point_projection<K, S, kind>& p, const Result& fit, F&& f) {
    if(fit.fit_kind != Local_fit_kind::CLOSEST_POINT || fit.coefficients.size() != std::size_t(S::number_of_parameters) ||
       !(p.bandwidth() > 0))
      return false;
    f(p.function_space(), p.bandwidth(), std::false_type(), p.weight());
    return true;
  }
};

template <class K, int D, Operator_kind kind, class S>
struct Fit_space_visitor<Mixed_projection<K, D, kind, S>> {
  template <class Result, class F>
  static bool visit(const Mixed_projection<K, D, kind, S>& p, const Result& fit, F&& f) {
    return Fit_space_visitor<typename Mixed_projection<K, D, kind, S>::Smooth_projection>::visit(p.smooth_projection(), fit, f) ||
           Fit_space_visitor<typename Mixed_projection<K, D, kind, S>::Sharp_projection>::visit(p.sharp_projection(), fit, f);
  }
};

template <class P>
struct Fit_space_visitor<Levin_screened_projection<P>> {
  template <class Result, class F>
  static bool visit(const Levin_screened_projection<P>& p, const Result& fit, F&& f) {
    return Fit_space_visitor<typename Levin_screened_projection<P>::Levin>::visit(p.levin(), fit, f) ||
           Fit_space_visitor<P>::visit(p.screened_operator(), fit, f);
  }
};

// Whether a neighbour's closest point on a fan lies on the face of normal `face`.
template <int D>
bool on_face(const Closest_point<D>& cp, const Vec<D>& face) {
  return !cp.is_on_feature && cp.normal.dot(face) > 1. - 1e-6;
}

// The weights of the input points of `nbh`, gathered around `x` (local coordinates): the weight
// function of the operator that made the fit (in Mixed_projection, the smooth or the sharp
// operator's), centred on `x`, kept only for the points the fit explains (distance
// to it at most three times its RMS residual plus h/100, and, when the samples have normals, a
// normal within 30 degrees of the fit's at the closest point) and, on a fit with sharp features, whose
// closest points lie on the face of the closest point of `x` (at a crease or apex: the face of
// the weighted closest point nearest to it). All weights are kept when none would be.
template <class Projection>
void attribute_weights(const Projection& projection, const typename Projection::Result& fit, const Vec<Projection::dimension>& x,
                       Neighborhood<Projection::dimension>& nbh, std::vector<double>& w) {
  constexpr int D = Projection::dimension;
  const auto& samples = projection.samples();
  const Weight_function* fit_weight = &projection.weight();
  Fit_space_visitor<Projection>::visit(projection, fit, [&](const auto&, double, auto, const Weight_function& wf) { fit_weight = &wf; });
  const Weight_function& weight = *fit_weight;
  const double h = weight.bandwidth();
  if(projection.options().one_sided && samples.has_normals()) {
    nbh.side = side_at<D>(samples, x);
    nbh.depth = other_side_depth * h;
  }
  nbh.gather(samples, x, weight.support_radius());
  w.resize(nbh.size());
  for(std::size_t i = 0; i < nbh.size(); ++i) w[i] = weight((nbh.points[i] - x).squaredNorm());

  using KT = Kernel_types<typename Projection::Samples::Geom_traits, D>;
  Mat<D> axes;
  for(int j = 0; j < D - 1; ++j) axes.col(j) = KT::to_eigen(fit.frame.tangents[j]);
  axes.col(D - 1) = KT::to_eigen(fit.frame.normal);
  const Vec<D> origin = samples.to_local(fit.frame.origin);
  const double tolerance = 3. * std::sqrt((std::max)(0., fit.energy)) + 0.01 * h;
  thread_local std::vector<char> kept;
  kept.assign(nbh.size(), 0);
  // whether the normal of point i (when the samples have some) is within 30 degrees of the fit's
  // normal `n` (frame coordinates) at its closest point, up to orientation
  const auto agrees = [&](std::size_t i, const Vec<D>& n) {
    return !samples.has_normals() || std::abs(samples.local_normal(nbh.indices[i]).dot(axes * n)) >= 0.866 * n.norm();
  };
  Fit_space_visitor<Projection>::visit(projection, fit, [&](const auto& space, double unit, auto is_graph, const Weight_function&) {
    using Space = std::decay_t<decltype(space)>;
    const typename Space::Parameters c = Eigen::Map<const typename Space::Parameters>(fit.coefficients.data());
    const auto to_frame = [&](const Vec<D>& p) { return Vec<D>(axes.transpose() * (p - origin) / unit); };
    if constexpr(decltype(is_graph)::value) {
      for(std::size_t i = 0; i < nbh.size(); ++i) {
        const Vec<D> y = to_frame(nbh.points[i]);
        const auto u = y.template head<D - 1>();
        Vec<D> n;
        n << -space.gradient(c, u), 1.;
        kept[i] = w[i] > 0 && std::abs(y[D - 1] - space.height(c, u)) * unit <= tolerance && agrees(i, n);
      }
    } else {
      thread_local std::vector<Closest_point<D>> cps;
      cps.resize(nbh.size());
      for(std::size_t i = 0; i < nbh.size(); ++i) {
        if(!(w[i] > 0)) continue;
        cps[i] = space.closest_point(c, to_frame(nbh.points[i]));
        kept[i] = std::abs(cps[i].signed_distance) * unit <= tolerance && agrees(i, cps[i].normal);
      }
      if constexpr(has_sharp_features<Space>::value) {
        const Closest_point<D> at_x = space.closest_point(c, to_frame(x));
        Vec<D> face = at_x.normal;
        double nearest = std::numeric_limits<double>::infinity();
        for(std::size_t i = 0; at_x.is_on_feature && i < nbh.size(); ++i) {
          const double d = (cps[i].point - at_x.point).squaredNorm();
          if(kept[i] && !cps[i].is_on_feature && d < nearest) {
            nearest = d;
            face = cps[i].normal;
          }
        }
        for(std::size_t i = 0; i < nbh.size(); ++i) kept[i] = kept[i] && on_face(cps[i], face);
      }
    }
  });
  bool any = false;
  for(std::size_t i = 0; i < nbh.size(); ++i) any = any || kept[i];
  if(!any) return; // no point passes: all of them
  for(std::size_t i = 0; i < nbh.size(); ++i)
    if(!kept[i]) w[i] = 0;
}

} // namespace internal

/// \ingroup PkgMLSProjectionFunctions
/// Writes to `out` the attributes (see `Sample_set::number_of_attributes()`) at the point `x` of
/// the local fit `fit`, a result of `projection` (or of an operator sharing its sample set and
/// function spaces, such as the seed projection of `MLS_implicit_function`).
///
/// Each channel is the weighted mean of the input points' values, with the weight function of the
/// operator that made the fit (in `Mixed_projection`, the smooth or the sharp operator's) centred
/// on `x` (on the side of `x` when `Projection_options::one_sided` and the
/// samples have normals; non-finite values are skipped), over the input points that the fit
/// explains: those within \f$3\sqrt{E} + h/100\f$ of it, \f$E\f$ = `fit.energy`, and, when the
/// samples have normals, whose normal is within 30 degrees of the fit's at their closest point (an
/// outlier, or a point of another face that a smooth fit bends towards, gives nothing). Where the fit belongs to
/// a space with sharp features (the wedge fan, alone or in `Mixed_projection`), only the input
/// points whose closest points on the fit lie on the same face as the closest point of `x`
/// contribute, so that a change of colour along a crease stays on the crease; at a crease or
/// apex, that face is the one of the weighted closest point nearest to it. When no input point
/// passes these tests, all of them count. Where no input point lies within the weight's
/// support (a far `x`), or `fit` is not a success, the values are those of the input point nearest
/// to `x`.
///
/// \tparam Projection a projection operator of this package
/// \param projection the operator whose samples hold the attributes
/// \param fit a result of `projection` (its frame, coefficients and energy)
/// \param x the point at which the attributes are wanted, on or near the fit
/// \param out an output iterator accepting `double`, written `number_of_attributes()` times
/// \return `fit.is_success()`
template <class Projection, class OutputIterator>
bool interpolate_attributes(const Projection& projection, const typename Projection::Result& fit,
                            const typename Projection::Point& x, OutputIterator out) {
  constexpr int D = Projection::dimension;
  const auto& samples = projection.samples();
  const std::size_t channels = samples.number_of_attributes();
  if(channels == 0) return fit.is_success();
  const internal::Vec<D> y = samples.to_local(x);
  thread_local internal::Neighborhood<D> nbh;
  thread_local std::vector<double> w;
  nbh = internal::Neighborhood<D>();
  w.clear();
  if(fit.is_success() && y.allFinite()) internal::attribute_weights(projection, fit, y, nbh, w);
  std::vector<double> sum(channels, 0.), total(channels, 0.);
  for(std::size_t i = 0; i < w.size(); ++i) {
    if(!(w[i] > 0)) continue;
    const double* a = samples.attributes(nbh.indices[i]);
    for(std::size_t k = 0; k < channels; ++k)
      if(std::isfinite(a[k])) {
        sum[k] += w[i] * a[k];
        total[k] += w[i];
      }
  }
  thread_local std::vector<std::size_t> nearest;
  nearest.clear();
  for(std::size_t k = 0; k < channels; ++k) {
    if(total[k] > 0) {
      *out++ = sum[k] / total[k];
      continue;
    }
    if(nearest.empty()) samples.k_nearest(y.allFinite() ? y : internal::Vec<D>(internal::Vec<D>::Zero()), 1, nearest);
    const double v = nearest.empty() ? 0. : samples.attributes(nearest[0])[k];
    *out++ = std::isfinite(v) ? v : 0.;
  }
  return fit.is_success();
}

/// The same at the projected point `fit.point`.
template <class Projection, class OutputIterator>
bool interpolate_attributes(const Projection& projection, const typename Projection::Result& fit, OutputIterator out) {
  return interpolate_attributes(projection, fit, fit.point, out);
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERPOLATE_ATTRIBUTES_H
