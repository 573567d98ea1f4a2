// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What every projection operator shares: the sample set, the bandwidth and weight,
// the initial frame from a weighted PCA, the orientation of normals and the assembly
// of results (including the failure results that never hold a NaN).

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_BASE_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_BASE_H

#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Projection_result.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/Weight_function.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>
#include <CGAL/MLS_projection/internal/projection/Neighborhood.h>
#include <CGAL/MLS_projection/internal/projection/weighted_pca.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

template <class T> struct is_shared_ptr : std::false_type {};
template <class T> struct is_shared_ptr<std::shared_ptr<T>> : std::true_type {};

template <class GeomTraits, int D>
class Operator_base {
public:
  using Geom_traits = GeomTraits;
  using FT = typename GeomTraits::FT;
  using Point = typename Kernel_types<GeomTraits, D>::Point;
  using Vector = typename Kernel_types<GeomTraits, D>::Vector;
  using Samples = Sample_set<GeomTraits, D>;
  using Result = Projection_result<GeomTraits, D>;
  static constexpr int dimension = D;

  Operator_base(std::shared_ptr<const Samples> samples, const Projection_options& options)
    : samples_(std::move(samples)), options_(options),
      k_(options.k > 0 ? std::size_t(options.k) : std::size_t(D == 2 ? 6 : 16)),
      h_(options.bandwidth > 0 ? options.bandwidth : samples_->mean_kth_neighbor_distance(k_)),
      weight_(options.weight, h_ > 0 && std::isfinite(h_) ? h_ : 1.), unit_weight_(options.weight, 1.) {}

  /// The bandwidth \f$h\f$ in use (0 when it could not be derived: all points equal, or fewer than two).
  double bandwidth() const { return has_bandwidth() ? h_ : 0.; }
  /// The number of neighbours of the initial PCA and of the derivation of \f$h\f$.
  std::size_t number_of_neighbors() const { return k_; }
  const Weight_function& weight() const { return weight_; }
  const Projection_options& options() const { return options_; }
  const Samples& samples() const { return *samples_; }
  const std::shared_ptr<const Samples>& shared_samples() const { return samples_; }

  /// The fewest independent points the weights of a fit may count, \f$(\sum w_i)^2 / \sum w_i^2\f$:
  /// 2. Weights that sit on one point (an outlier that the fit passes through, projected onto
  /// itself) describe no surface; the projection then fails with `TOO_FEW_NEIGHBORS`.
  static constexpr double minimum_effective_points() { return 2; }

protected:
  /// Whether weights summing to `sum`, with squares summing to `sum_of_squares`, count as at
  /// least `minimum_effective_points()` points.
  static bool enough_effective_points(double sum, double sum_of_squares) {
    return sum * sum >= minimum_effective_points() * sum_of_squares && sum_of_squares > 0;
  }

  // Energies are in squared length units: h^2 times a few support radii must not overflow.
  bool has_bandwidth() const { return h_ > 0 && h_ < 1e150; }
  /// Radius gathered around a frame origin: the weight's support plus a margin of h/2,
  /// within which the origin may move before the neighbourhood is gathered again.
  double gather_radius() const { return weight_.support_radius() + 0.5 * h_; }

  /// Sets the side of `nbh` for a query at `r` (`internal::side_at()`) with
  /// `Projection_options::one_sided` and input normals, else none.
  void set_side(Neighborhood<D>& nbh, const Vec<D>& r) const {
    const bool sided = options_.one_sided && samples_->has_normals();
    nbh.side = sided ? internal::side_at<D>(*samples_, r) : Vec<D>(Vec<D>::Zero());
    nbh.depth = other_side_depth * h_;
  }

  struct Initial_frame {
    Vec<D> origin, normal;
    Pca<D> pca;
    Projection_status status = Projection_status::CONVERGED;
  };

  /// Weighted PCA of the `k` nearest neighbours of `r` on the side of `nbh` (of the `2k` nearest;
  /// Gaussian weights of bandwidth h, relative to the nearest neighbour so that far queries do
  /// not underflow); the frame origin is `r` projected on the PCA plane.
  Initial_frame initial_frame(const Vec<D>& r, std::size_t minimum_points, const Neighborhood<D>& nbh) const {
    Initial_frame f;
    const std::size_t k = (std::max)(k_, minimum_points);
    std::vector<std::size_t> idx;
    if(samples_->size() >= minimum_points) {
      const bool sided = !nbh.side.isZero();
      samples_->k_nearest(r, sided ? 2 * k : k, idx);
      if(sided) {
        idx.erase(std::remove_if(idx.begin(), idx.end(), [&](std::size_t i) { return !nbh.on_side(*samples_, i, r); }),
                  idx.end());
        if(idx.size() > k) idx.resize(k);
      }
    }
    if(idx.size() < minimum_points) {
      f.status = Projection_status::TOO_FEW_NEIGHBORS;
      return f;
    }
    std::vector<Vec<D>> p(idx.size());
    std::vector<double> w(idx.size());
    double dmin = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < idx.size(); ++i) {
      p[i] = samples_->local_point(idx[i]);
      w[i] = (p[i] - r).squaredNorm();
      dmin = (std::min)(dmin, w[i]);
    }
    const double scale = has_bandwidth() ? 1. / (h_ * h_) : 0.;
    for(double& wi : w) wi = std::exp(-(wi - dmin) * scale);
    f.pca = weighted_pca<D>(p, w);
    if(!has_bandwidth() || !f.pca.valid || f.pca.is_degenerate()) {
      f.status = Projection_status::DEGENERATE_NEIGHBORHOOD;
      return f;
    }
    f.normal = f.pca.minor_axis();
    f.origin = r + (f.pca.centroid - r).dot(f.normal) * f.normal;
    return f;
  }

  /// The sign the normal `n` of a local fit at `q` must have: agreeing with the weighted
  /// input normals when there are some, else pointing away from the centroid of the input.
  double orientation(const Vec<D>& q, const Vec<D>& n, const Neighborhood<D>& nbh) const {
    if(samples_->has_normals()) {
      double s = 0;
      for(std::size_t i = 0; i < nbh.size(); ++i)
        s += weight_((nbh.points[i] - q).squaredNorm()) * samples_->local_normal(nbh.indices[i]).dot(n);
      if(s != 0) return s > 0 ? 1. : -1.;
    }
    return q.dot(n) < 0 ? -1. : 1.;
  }

  Result failure(const Point& query, Projection_status status) const {
    Result res;
    res.point = query;
    res.normal = NULL_VECTOR;
    res.frame.origin = query;
    res.frame.normal = NULL_VECTOR;
    for(auto& t : res.frame.tangents) t = NULL_VECTOR;
    res.status = status;
    return res;
  }

  /// Fills the geometric fields of `res` from local coordinates.
  void set_geometry(Result& res, const Vec<D>& point, const Vec<D>& normal, const Vec<D>& origin,
                    const Vec<D>& frame_normal, const std::array<Vec<D>, D - 1>& tangents) const {
    using KT = Kernel_types<GeomTraits, D>;
    res.point = samples_->to_world(point);
    res.normal = KT::to_vector(normal);
    res.frame.origin = samples_->to_world(origin);
    res.frame.normal = KT::to_vector(frame_normal);
    for(int j = 0; j < D - 1; ++j) res.frame.tangents[j] = KT::to_vector(tangents[j]);
  }

  std::shared_ptr<const Samples> samples_;
  Projection_options options_;
  std::size_t k_;
  double h_;
  Weight_function weight_;
  Weight_function unit_weight_; // the same weight for lengths in units of h
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_BASE_H
