// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H
#define CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H

#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/internal/projection/Newton_minimizer.h>
#include <CGAL/MLS_projection/internal/projection/levin_energy.h>
#include <CGAL/MLS_projection/internal/projection/Operator_base.h>
#include <CGAL/MLS_projection/internal/projection/weighted_pca.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace MLS {

enum class Operator_kind;
template <class GeomTraits, class FunctionSpace, Operator_kind kind>
class Closest_point_projection;

/// \ingroup PkgMLSProjectionOperators
/// Levin's two-phase MLS projection \f$\mathcal{P}_L\f$ (section 3.1 of the paper).
///
/// <b>Phase 1</b> finds the reference frame \f$H_{r,q}\f$: the hyperplane through \f$q\f$ with
/// normal \f$n = (q - r)/|q - r|\f$ minimising the weighted mean squared distance of the input
/// points to it, with weights \f$\omega(|p_i - q|)\f$ (equation 1). The frame is parameterised by
/// its unit normal \f$n\f$ (exponential map around the current normal) and the signed distance
/// \f$t\f$ with \f$q = r + t\,n\f$, which stays well defined when \f$r\f$ is on the surface.
/// The start is the weighted PCA plane of the points around \f$r\f$ (those of its `k` nearest
/// neighbours when \f$r\f$ is further than the weight's support from the data); the minimiser is
/// Newton's method on the closed-form gradient and Hessian of the energy, damped as
/// Levenberg-Marquardt (user manual, "Optimiser").
///
/// <b>Phase 2</b> fits a member \f$f\f$ of the function space over \f$H\f$ by weighted linear least
/// squares with the weights of phase 1 (equation 2), and returns
/// \f$\mathcal{P}_L(r) = q + f(0)\,n\f$, the projection of \f$r\f$ on \f$f\f$ along \f$n\f$.
///
/// The result's normal is the normal of \f$f\f$ at the projected point, oriented to agree with the
/// input normals when the sample set has some, and else to point away from the centroid of the
/// input. `energy` is the weighted mean squared residual of equation 2.
///
/// Cheap to copy (the samples are shared); `project()` is `const` and thread-safe.
///
/// \tparam GeomTraits a CGAL kernel
/// \tparam FunctionSpace a model of `MLSGraphFunctionSpace`; its ambient dimension (2 or 3)
///         sets the dimension of the operator
template <class GeomTraits, class FunctionSpace = Polynomial_function_space<3>>
class Levin_projection : public internal::Operator_base<GeomTraits, FunctionSpace::ambient_dimension> {
  static constexpr int D = FunctionSpace::ambient_dimension;
  using Base = internal::Operator_base<GeomTraits, D>;
  using Vec = internal::Vec<D>;

public:
  using typename Base::FT;
  using typename Base::Point;
  using typename Base::Vector;
  using typename Base::Samples;
  using typename Base::Result;
  using Function_space = FunctionSpace; ///< the function space of phase 2

  /// Builds the sample set of `points` (named parameters `point_map`, `normal_map`, see `Sample_set`).
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<!internal::is_shared_ptr<PointRange>::value>>
  explicit Levin_projection(const PointRange& points, const Projection_options& options = Projection_options(),
                            const NamedParameters& np = parameters::default_values(),
                            const FunctionSpace& space = FunctionSpace())
    : Levin_projection(std::make_shared<const Samples>(points, np), options, space) {}

  /// Shares an existing sample set (and its kd-tree) with other operators.
  explicit Levin_projection(std::shared_ptr<const Samples> samples,
                            const Projection_options& options = Projection_options(),
                            const FunctionSpace& space = FunctionSpace())
    : Base(std::move(samples), options), space_(space) {}

  /// The function space of phase 2.
  const FunctionSpace& function_space() const { return space_; }

private:
  // Phase 1 is also the start of the closest-point operators.
  template <class, class, Operator_kind>
  friend class Closest_point_projection;

  // The frame of phase 1, in local (centred) coordinates.
  struct Frame {
    Vec origin, normal; // the origin q and the unit normal n
    int iterations = 0;
    bool converged = false; // false when the optimiser exhausted its budget
    Projection_status status = Projection_status::CONVERGED; // why phase 1 failed, if it did
  };

  // Phase 1 for the query `r` in local coordinates; `nbh` receives the final neighbourhood
  // (the points within the weight's support plus a margin of the frame origin, on the side
  // `nbh.side`).
  Frame find_frame(const Vec& r, internal::Neighborhood<D>& nbh) const {
    Frame frame;
    const double h = this->h_, support = this->weight_.support_radius();
    Start start;
    frame.status = start_frame(r, nbh, start);
    if(frame.status != Projection_status::CONVERGED) return frame;
    // The state of the minimisation: the frame normal and the origin's offset along it from r,
    // in units of h. The Newton steps are in the tangent coordinates of the normal's exponential
    // map at the current normal, and the offset.
    struct State {
      Vec n;
      double s;
    };
    State x{start.normal, start.offset};
    thread_local std::vector<Vec> y; // the neighbourhood relative to r, in units of h
    const auto evaluate = [&](const State& st, double& E, Step& g, Step_matrix& H) {
      return internal::levin_energy<D>(y, st.n, st.s, unit_weight_, E, g, H);
    };
    const auto retract = [](const State& st, const Step& delta) {
      const auto basis = internal::tangent_basis<D>(st.n);
      return State{internal::exp_map<D>(st.n, basis, delta), st.s + delta[D - 1]};
    };
    internal::Newton_settings settings;
    settings.max_evaluations = this->options_.max_evaluations;
    for(int round = 0; round < 5; ++round) {
      if(nbh.size() < minimum_points()) {
        frame.status = Projection_status::TOO_FEW_NEIGHBORS;
        return frame;
      }
      y.resize(nbh.size());
      for(std::size_t i = 0; i < nbh.size(); ++i) y[i] = (nbh.points[i] - r) / h;
      const internal::Newton_report report = internal::minimize_newton<D>(x, evaluate, retract, settings);
      frame.iterations += report.iterations;
      frame.converged = report.converged;
      if(!report.valid) { // no point of positive weight around the frame: the start left the data
        frame.status = Projection_status::TOO_FEW_NEIGHBORS;
        return frame;
      }
      const Vec q = r + (x.s * h) * x.n;
      if(nbh.covers(q, support)) break;
      // the origin moved out of the gathered ball: gather around it and continue from there
      nbh.gather(this->samples(), q, this->gather_radius());
    }
    frame.origin = r + (x.s * h) * x.n;
    frame.normal = x.n;
    if(!frame.origin.allFinite() || !frame.normal.allFinite()) frame.status = Projection_status::DEGENERATE_NEIGHBORHOOD;
    return frame;
  }

public:
  /// Projects `query` on the MLS curve (2D) or surface (3D).
  Result project(const Point& query) const {
    const Vec r = this->samples().to_local(query);
    if(!r.allFinite()) return this->failure(query, Projection_status::INVALID_QUERY);
    thread_local internal::Neighborhood<D> nbh;
    this->set_side(nbh, r);
    Frame frame = find_frame(r, nbh);
    if(frame.status != Projection_status::CONVERGED) return this->failure(query, frame.status);

    // Phase 2: the weighted linear fit of the function space in the frame, oriented first so
    // that the coefficients are expressed in the frame the result reports.
    Vec q = frame.origin;
    Vec n = frame.normal * this->orientation(q, frame.normal, nbh);
    const auto tangents = internal::tangent_basis<D>(n);
    thread_local std::vector<Vec> local;
    thread_local std::vector<double> w;
    local.clear();
    w.clear();
    for(const Vec& p : nbh.points) {
      const Vec d = p - q;
      const double wi = this->weight_(d.squaredNorm());
      if(wi <= 0) continue;
      Vec l;
      for(int j = 0; j < D - 1; ++j) l[j] = d.dot(tangents[j]);
      l[D - 1] = d.dot(n);
      local.push_back(l);
      w.push_back(wi);
    }
    if(local.size() < minimum_points()) return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);
    const auto c = space_.fit(local.data(), w.data(), local.size());
    using Domain_point = typename FunctionSpace::Domain_point;
    const double f0 = space_.height(c, Domain_point::Zero());
    const Domain_point g = space_.gradient(c, Domain_point::Zero());
    Vec normal = n;
    for(int j = 0; j < D - 1; ++j) normal -= g[j] * tangents[j];
    normal.normalize();
    const Vec point = q + f0 * n;

    double W = 0, W2 = 0, E = 0;
    for(std::size_t i = 0; i < local.size(); ++i) {
      const double e = local[i][D - 1] - space_.height(c, Domain_point(local[i].template head<D - 1>()));
      W += w[i];
      W2 += w[i] * w[i];
      E += w[i] * e * e;
    }
    if(!point.allFinite() || !normal.allFinite())
      return this->failure(query, Projection_status::DEGENERATE_NEIGHBORHOOD);
    if(!this->enough_effective_points(W, W2)) return this->failure(query, Projection_status::TOO_FEW_NEIGHBORS);

    Result res;
    this->set_geometry(res, point, normal, q, n, tangents);
    res.coefficients.assign(c.data(), c.data() + c.size());
    res.fit_kind = Local_fit_kind::LEVIN;
    res.energy = W > 0 ? E / W : 0.;
    res.iterations = frame.iterations;
    res.number_of_neighbors = local.size();
    res.status = frame.converged ? Projection_status::CONVERGED : Projection_status::NOT_CONVERGED;
    return res;
  }

  /// Same as `project()`, so that the operator is a function object.
  Result operator()(const Point& query) const { return project(query); }

  /// The fewest input points a projection needs: those the function space needs, and at least D.
  static constexpr std::size_t minimum_points() {
    return (std::max)(std::size_t(D), FunctionSpace::minimum_number_of_points());
  }

private:
  using Step = Eigen::Matrix<double, D, 1>;         // (tangent angles of the normal, offset / h)
  using Step_matrix = Eigen::Matrix<double, D, D>;

  struct Start {
    Vec normal;
    double offset = 0; // of the origin along the normal from r, in units of h
  };

  // The start of phase 1 and its neighbourhood: the weighted PCA plane of the points around r
  // (weights of the projection centred at r) when r is within the weight's support of the
  // data, else that of its k nearest neighbours (`initial_frame()`); `nbh` is gathered around
  // the start's origin.
  Projection_status start_frame(const Vec& r, internal::Neighborhood<D>& nbh, Start& start) const {
    const double h = this->h_;
    if(this->samples().size() < minimum_points()) return Projection_status::TOO_FEW_NEIGHBORS;
    if(!this->has_bandwidth()) return Projection_status::DEGENERATE_NEIGHBORHOOD;
    nbh.gather(this->samples(), r, this->gather_radius());
    thread_local std::vector<double> w;
    w.resize(nbh.size());
    std::size_t weighted = 0;
    for(std::size_t i = 0; i < nbh.size(); ++i) {
      w[i] = this->weight_((nbh.points[i] - r).squaredNorm());
      if(w[i] > 0) ++weighted;
    }
    if(weighted >= minimum_points()) {
      const internal::Pca<D> pca = internal::weighted_pca<D>(nbh.points, w);
      if(!pca.valid || pca.is_degenerate()) return Projection_status::DEGENERATE_NEIGHBORHOOD;
      start.normal = pca.minor_axis();
      start.offset = (pca.centroid - r).dot(start.normal) / h;
      return Projection_status::CONVERGED;
    }
    const auto init = this->initial_frame(r, minimum_points(), nbh);
    if(init.status != Projection_status::CONVERGED) return init.status;
    start.normal = init.normal;
    start.offset = (init.origin - r).dot(init.normal) / h;
    nbh.gather(this->samples(), init.origin, this->gather_radius());
    return Projection_status::CONVERGED;
  }

  using Base::unit_weight_;
  FunctionSpace space_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H
