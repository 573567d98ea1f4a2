// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H
#define CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H

#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/internal/Least_squares_minimizer.h>
#include <CGAL/MLS_projection/internal/Operator_base.h>

#include <cmath>
#include <memory>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionOperators
/// Levin's two-phase MLS projection \f$\mathcal{P}_L\f$ (section 3.1 of the paper).
///
/// <b>Phase 1</b> finds the reference frame \f$H_{r,q}\f$: the hyperplane through \f$q\f$ with
/// normal \f$n = (q - r)/|q - r|\f$ minimising the weighted mean squared distance of the input
/// points to it, with weights \f$\omega(|p_i - q|)\f$ (equation 1). The frame is parameterised by
/// its unit normal \f$n\f$ (exponential map around the start normal) and the signed distance
/// \f$t\f$ with \f$q = r + t\,n\f$, which stays well defined when \f$r\f$ is on the surface.
/// The start is the weighted PCA plane of the `k` nearest neighbours of \f$r\f$; the minimiser is
/// Levenberg-Marquardt (see `Least_squares_minimizer`).
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

  /// The frame of phase 1, in local (centred) coordinates, as used by the operators built on it.
  struct Frame {
    /// The origin \f$q\f$ and the unit normal \f$n\f$ of the frame.
    /// @{
    Vec origin, normal;
    /// @}
    int iterations = 0;      ///< iterations of the optimiser
    bool converged = false;  ///< `false` when the optimiser exhausted its budget
    Projection_status status = Projection_status::CONVERGED; ///< why phase 1 failed, if it did
  };

  /// Phase 1 for the query `r` in local coordinates; `nbh` receives the final neighbourhood.
  Frame find_frame(const Vec& r, internal::Neighborhood<D>& nbh) const {
    Frame frame;
    const auto init = this->initial_frame(r, minimum_points());
    if(init.status != Projection_status::CONVERGED) {
      frame.status = init.status;
      return frame;
    }
    const double h = this->h_;
    const double support = this->weight_.support_radius();
    Vec n0 = init.normal;
    double s0 = (init.origin - r).dot(n0) / h;
    nbh.gather(this->samples(), init.origin, this->gather_radius());

    std::vector<double> w, z;
    internal::Minimizer_settings settings;
    settings.tolerance = this->options_.tolerance;
    settings.max_evaluations = this->options_.max_evaluations;
    Vec q = init.origin, n = n0;
    for(int round = 0; round < 5; ++round) {
      if(nbh.size() < minimum_points()) {
        frame.status = Projection_status::TOO_FEW_NEIGHBORS;
        return frame;
      }
      const auto basis = internal::tangent_basis<D>(n0);
      const auto frame_of = [&](const Eigen::VectorXd& x, Vec& qx, Vec& nx) {
        nx = internal::exp_map<D>(n0, basis, x);
        qx = r + (x[D - 1] * h) * nx;
      };
      w.resize(nbh.size());
      z.resize(nbh.size());
      const auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& res) {
        Vec qx, nx;
        frame_of(x, qx, nx);
        double W = 0;
        for(std::size_t i = 0; i < nbh.size(); ++i) {
          const Vec d = nbh.points[i] - qx;
          w[i] = this->weight_(d.squaredNorm());
          z[i] = d.dot(nx) / h;
          W += w[i];
        }
        if(!(W > 0)) {
          res.setConstant(1e3); // the frame left the points: a plateau the minimiser backs off from
          return;
        }
        for(std::size_t i = 0; i < nbh.size(); ++i) res[i] = std::sqrt(w[i] / W) * z[i];
      };
      Eigen::VectorXd x0 = Eigen::VectorXd::Zero(D);
      x0[D - 1] = s0;
      const auto report = internal::minimize_sum_of_squares(residuals, int(nbh.size()), x0, settings);
      frame.iterations += report.iterations;
      frame.converged = report.converged;
      frame_of(report.x, q, n);
      if(nbh.covers(q, support)) break;
      // The origin moved out of the gathered ball: gather around it and continue from there.
      n0 = n;
      s0 = report.x[D - 1];
      nbh.gather(this->samples(), q, this->gather_radius());
    }
    frame.origin = q;
    frame.normal = n;
    if(!q.allFinite() || !n.allFinite()) frame.status = Projection_status::DEGENERATE_NEIGHBORHOOD;
    return frame;
  }

  /// Projects `query` on the MLS curve (2D) or surface (3D).
  Result project(const Point& query) const {
    const Vec r = this->samples().to_local(query);
    if(!r.allFinite()) return this->failure(query, Projection_status::INVALID_QUERY);
    internal::Neighborhood<D> nbh;
    Frame frame = find_frame(r, nbh);
    if(frame.status != Projection_status::CONVERGED) return this->failure(query, frame.status);

    // Phase 2: the weighted linear fit of the function space in the frame, oriented first so
    // that the coefficients are expressed in the frame the result reports.
    Vec q = frame.origin;
    Vec n = frame.normal * this->orientation(q, frame.normal, nbh);
    const auto tangents = internal::tangent_basis<D>(n);
    std::vector<Vec> local;
    std::vector<double> w;
    local.reserve(nbh.size());
    w.reserve(nbh.size());
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

    double W = 0, E = 0;
    for(std::size_t i = 0; i < local.size(); ++i) {
      const double e = local[i][D - 1] - space_.height(c, Domain_point(local[i].template head<D - 1>()));
      W += w[i];
      E += w[i] * e * e;
    }
    if(!point.allFinite() || !normal.allFinite())
      return this->failure(query, Projection_status::DEGENERATE_NEIGHBORHOOD);

    Result res;
    this->set_geometry(res, point, normal, q, n, tangents);
    res.coefficients.assign(c.data(), c.data() + c.size());
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
  FunctionSpace space_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_LEVIN_PROJECTION_H
