// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_SAMPLE_SET_H
#define CGAL_MLS_PROJECTION_SAMPLE_SET_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>
#include <CGAL/MLS_projection/internal/projection/Point_tree.h>
#include <CGAL/MLS_projection/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The input of every projection operator: the input points (and optional unit normals)
/// copied once, translated so that their centroid is the origin, and a kd-tree over them
/// for k-nearest and ball queries, and optionally per-point attributes (any number of scalar
/// channels: colours, intensities) that `interpolate_attributes()` carries onto projections and
/// meshes.
///
/// Centring makes scans with large coordinate offsets (e.g. UTM coordinates, offsets of
/// \f$10^6\f$) as accurate as centred ones: all computations are done in double precision
/// relative to the centroid, which is added back only to the final results.
///
/// The tree is built in the constructor, so all member functions are `const` and safe to call
/// from many threads at once. Points with a NaN or infinite coordinate are dropped and counted
/// by `number_of_ignored_points()`. Not copyable: operators share it through a `std::shared_ptr`.
///
/// \tparam GeomTraits a CGAL kernel
/// \tparam D the ambient dimension, 2 or 3
template <class GeomTraits, int D>
class Sample_set {
  static_assert(D == 2 || D == 3, "CGAL::MLS::Sample_set: the dimension must be 2 or 3");

public:
  using Geom_traits = GeomTraits;                                        ///< the kernel
  using FT = typename GeomTraits::FT;                                     ///< the kernel's number type
  using Point = typename internal::Kernel_types<GeomTraits, D>::Point;   ///< `Point_2` or `Point_3`
  using Vector = typename internal::Kernel_types<GeomTraits, D>::Vector; ///< `Vector_2` or `Vector_3`
  using Local_point = Eigen::Matrix<double, D, 1>; ///< a point in local (centred) coordinates

private:
  using KT = internal::Kernel_types<GeomTraits, D>;

public:
  /// Copies the points of `points` (and the normals and attributes, when the named parameters
  /// `normal_map` and `attribute_map` are given) and builds the kd-tree.
  ///
  /// \param points a range of input points
  /// \param np optional named parameters: `point_map` (default: identity),
  ///        `normal_map` (default: none; input normals are used to orient the results),
  ///        `attribute_map` (default: none; see `CGAL::MLS::parameters::attribute_map()`)
  /// \pre the attribute values of all points have the same number of channels (otherwise no
  ///      attribute is kept: `number_of_attributes()` is 0)
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  explicit Sample_set(const PointRange& points, const NamedParameters& np = parameters::default_values()) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using Value = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
    using Default_point_map = CGAL::Identity_property_map<Value>;
    auto point_map = choose_parameter(get_parameter(np, internal_np::point_map), Default_point_map());
    constexpr bool has_normals = !parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value;
    constexpr bool has_attributes =
      !parameters::is_default_parameter<NamedParameters, internal_np::mls_attribute_map_t>::value;
    bool consistent = true;

    // Centroid in long double so that large offsets do not lose the small differences.
    std::vector<Local_point> world;
    std::vector<Local_point> normals;
    world.reserve(std::distance(points.begin(), points.end()));
    for(const auto& v : points) {
      const Local_point p = KT::to_eigen(Point(get(point_map, v)));
      if(!p.allFinite()) {
        ++ignored_;
        continue;
      }
      world.push_back(p);
      if constexpr(has_normals) {
        auto normal_map = get_parameter(np, internal_np::normal_map);
        Local_point n = KT::to_eigen(Vector(get(normal_map, v)));
        const double len = n.norm();
        normals.push_back(n.allFinite() && len > 0 ? Local_point(n / len) : Local_point(Local_point::Zero()));
      }
      if constexpr(has_attributes) {
        const auto& values = get(get_parameter(np, internal_np::mls_attribute_map), v);
        const std::size_t c = std::size_t(std::distance(std::begin(values), std::end(values)));
        if(world.size() == 1) channels_ = c;
        consistent = consistent && c == channels_;
        if(consistent)
          for(const auto& x : values) attributes_.push_back(static_cast<double>(x));
      }
    }
    CGAL_precondition_msg(consistent, "the attribute values must all have the same number of channels");
    if(!consistent) {
      channels_ = 0;
      attributes_.clear();
    }
    Eigen::Matrix<long double, D, 1> sum = Eigen::Matrix<long double, D, 1>::Zero();
    for(const auto& p : world) sum += p.template cast<long double>();
    if(!world.empty()) centre_ = (sum / static_cast<long double>(world.size())).template cast<double>();
    else centre_.setZero();
    points_.reserve(world.size());
    for(const auto& p : world) points_.push_back(p - centre_);
    normals_ = std::move(normals);
    tree_ = internal::Point_tree<D>(points_);
  }

  Sample_set(const Sample_set&) = delete;
  Sample_set& operator=(const Sample_set&) = delete;

  /// The number of (finite) input points kept.
  std::size_t size() const { return points_.size(); }
  /// The number of input points dropped because a coordinate was NaN or infinite.
  std::size_t number_of_ignored_points() const { return ignored_; }
  /// Whether the input has normals (a `normal_map` was given).
  bool has_normals() const { return !normals_.empty(); }
  /// The number of attribute channels per point (0 without an `attribute_map`).
  std::size_t number_of_attributes() const { return channels_; }
  /// The `number_of_attributes()` attribute values of the `i`-th point.
  const double* attributes(std::size_t i) const { return attributes_.data() + i * channels_; }

  /// The translation applied to the input: local coordinates are world coordinates minus `centre()`.
  const Local_point& centre() const { return centre_; }
  /// The local coordinates of the world point `p`.
  Local_point to_local(const Point& p) const { return KT::to_eigen(p) - centre_; }
  /// The world point of local coordinates `p`.
  Point to_world(const Local_point& p) const { return KT::to_point(p + centre_); }

  /// The `i`-th point, in local (centred) coordinates.
  const Local_point& local_point(std::size_t i) const { return points_[i]; }
  /// The `i`-th unit normal (null if the input normal was null or not finite). \pre `has_normals()`
  const Local_point& local_normal(std::size_t i) const { return normals_[i]; }

  /// Writes to `out` the indices of the `k` points nearest to `x` (local coordinates) among those
  /// within `radius` of it, nearest first (ties by index).
  void k_nearest(const Local_point& x, std::size_t k, std::vector<std::size_t>& out,
                 double radius = std::numeric_limits<double>::infinity()) const {
    thread_local std::vector<std::pair<double, std::size_t>> found;
    tree_.k_nearest(x, k, found, radius);
    out.resize(found.size());
    for(std::size_t i = 0; i < found.size(); ++i) out[i] = found[i].second;
  }

  /// The distance from `x` (local coordinates) to its `k`-th nearest input point (0 if there is none).
  double kth_neighbor_distance(const Local_point& x, std::size_t k) const {
    thread_local std::vector<std::pair<double, std::size_t>> found;
    tree_.k_nearest(x, k, found);
    return found.empty() ? 0. : std::sqrt(found.back().first);
  }

  /// Calls `f(i, p)` for every input point `p` (local coordinates, index `i`) within distance
  /// `radius` of `x`, in an order that depends only on the input (so that sums over the points
  /// are the same whatever the threads).
  template <class F>
  void for_each_in_ball(const Local_point& x, double radius, F&& f) const {
    tree_.for_each_in_ball(x, radius, std::forward<F>(f));
  }

  /// Writes to `out` the indices of the points within distance `radius` of `x` (local
  /// coordinates), in the order of `for_each_in_ball()`.
  void in_ball(const Local_point& x, double radius, std::vector<std::size_t>& out) const {
    out.clear();
    tree_.for_each_in_ball(x, radius, [&](std::size_t i, const Local_point&) { out.push_back(i); });
  }

  /// The mean, over input points, of the distance to their `k`-th nearest other input point.
  /// Computed on at most `max_points` points taken with a regular stride (deterministic).
  double mean_kth_neighbor_distance(std::size_t k, std::size_t max_points = 5000) const {
    if(points_.size() < 2) return 0.;
    const std::size_t stride = (std::max<std::size_t>)(1, points_.size() / (std::max<std::size_t>)(1, max_points));
    double sum = 0;
    std::size_t n = 0;
    for(std::size_t i = 0; i < points_.size(); i += stride, ++n)
      sum += kth_neighbor_distance(points_[i], k + 1); // the point itself is its own nearest
    return sum / double(n);
  }

private:
  std::vector<Local_point> points_;
  std::vector<Local_point> normals_;
  std::vector<double> attributes_; // channels_ values per point
  std::size_t channels_ = 0;
  Local_point centre_ = Local_point::Zero();
  std::size_t ignored_ = 0;
  internal::Point_tree<D> tree_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_SAMPLE_SET_H
