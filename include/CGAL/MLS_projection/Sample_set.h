// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_SAMPLE_SET_H
#define CGAL_MLS_PROJECTION_SAMPLE_SET_H

#include <CGAL/MLS_projection/internal/Dimension.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/Dimension.h>
#include <CGAL/Search_traits.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionRef
/// The input of every projection operator: the input points (and optional unit normals)
/// copied once, translated so that their centroid is the origin, and a kd-tree over them
/// (CGAL's spatial searching) for k-nearest and ball queries.
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
  using Local_point = internal::Vec<D>; ///< a point in local (centred) coordinates: `Eigen::Matrix<double, D, 1>`

private:
  using KT = internal::Kernel_types<GeomTraits, D>;

  struct Coordinate_iterator {
    using result_type = const double*;
    const double* operator()(const Local_point& p) const { return p.data(); }
    const double* operator()(const Local_point& p, int) const { return p.data() + D; }
  };
  // Index -> local point, as a CGAL lvalue property map.
  struct Index_map {
    using key_type = std::size_t;
    using value_type = Local_point;
    using reference = const Local_point&;
    using category = boost::lvalue_property_map_tag;
    const Local_point* points = nullptr;
    friend reference get(const Index_map& m, std::size_t i) { return m.points[i]; }
  };
  using Base_traits = CGAL::Search_traits<double, Local_point, const double*, Coordinate_iterator, CGAL::Dimension_tag<D>>;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Index_map, Base_traits>;
  using Distance = CGAL::Distance_adapter<std::size_t, Index_map, CGAL::Euclidean_distance<Base_traits>>;
  using K_search = CGAL::Orthogonal_k_neighbor_search<Traits, Distance>;
  using Tree = typename K_search::Tree;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;

public:
  /// Copies the points of `points` (and the normals, when the named parameter `normal_map`
  /// is given) and builds the kd-tree.
  ///
  /// \param points a range of input points
  /// \param np optional named parameters: `point_map` (default: identity),
  ///        `normal_map` (default: none; input normals are used to orient the results)
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  explicit Sample_set(const PointRange& points, const NamedParameters& np = parameters::default_values()) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using Value = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
    using Default_point_map = CGAL::Identity_property_map<Value>;
    auto point_map = choose_parameter(get_parameter(np, internal_np::point_map), Default_point_map());
    constexpr bool has_normals = !parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value;

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
    }
    Eigen::Matrix<long double, D, 1> sum = Eigen::Matrix<long double, D, 1>::Zero();
    for(const auto& p : world) sum += p.template cast<long double>();
    if(!world.empty()) centre_ = (sum / static_cast<long double>(world.size())).template cast<double>();
    else centre_.setZero();
    points_.reserve(world.size());
    for(const auto& p : world) points_.push_back(p - centre_);
    normals_ = std::move(normals);
    build_tree();
  }

  Sample_set(const Sample_set&) = delete;
  Sample_set& operator=(const Sample_set&) = delete;

  /// The number of (finite) input points kept.
  std::size_t size() const { return points_.size(); }
  /// The number of input points dropped because a coordinate was NaN or infinite.
  std::size_t number_of_ignored_points() const { return ignored_; }
  /// Whether the input has normals (a `normal_map` was given).
  bool has_normals() const { return !normals_.empty(); }

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

  /// Appends to `out` the indices of the `k` points nearest to `x` (local coordinates),
  /// sorted by index.
  void k_nearest(const Local_point& x, std::size_t k, std::vector<std::size_t>& out) const {
    out.clear();
    if(points_.empty() || k == 0) return;
    K_search search(*tree_, x, static_cast<unsigned int>((std::min)(k, points_.size())), 0., true,
                    Distance(Index_map{points_.data()}));
    for(const auto& it : search) out.push_back(it.first);
    std::sort(out.begin(), out.end());
  }

  /// The distance from `x` (local coordinates) to its `k`-th nearest input point (0 if there is none).
  double kth_neighbor_distance(const Local_point& x, std::size_t k) const {
    if(points_.empty() || k == 0) return 0.;
    K_search search(*tree_, x, static_cast<unsigned int>((std::min)(k, points_.size())), 0., true,
                    Distance(Index_map{points_.data()}));
    double d2 = 0;
    for(const auto& it : search) d2 = (std::max)(d2, it.second);
    return std::sqrt(d2);
  }

  /// Appends to `out` the indices of the points within distance `radius` of `x`
  /// (local coordinates), sorted by index so that sums over them do not depend on the tree.
  void in_ball(const Local_point& x, double radius, std::vector<std::size_t>& out) const {
    out.clear();
    if(points_.empty()) return;
    Sphere sphere(x, radius, 0., Traits(Index_map{points_.data()}));
    tree_->search(std::back_inserter(out), sphere);
    std::sort(out.begin(), out.end());
  }

  /// The mean, over input points, of the distance to their `k`-th nearest other input point.
  /// Computed on at most 20000 points taken with a regular stride (deterministic).
  double mean_kth_neighbor_distance(std::size_t k) const {
    if(points_.size() < 2) return 0.;
    const std::size_t stride = (std::max<std::size_t>)(1, points_.size() / 20000);
    double sum = 0;
    std::size_t n = 0;
    for(std::size_t i = 0; i < points_.size(); i += stride, ++n)
      sum += kth_neighbor_distance(points_[i], k + 1); // the point itself is its own nearest
    return sum / double(n);
  }

private:
  void build_tree() {
    // CGAL's Kd_tree::build() asserts a non-empty point set (no finite input point: no tree;
    // every query function returns early on an empty set)
    if(points_.empty()) return;
    std::vector<std::size_t> indices(points_.size());
    for(std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
    tree_ = std::make_unique<Tree>(indices.begin(), indices.end(), typename Tree::Splitter(),
                                   Traits(Index_map{points_.data()}));
    tree_->build(); // before any concurrent query
  }

  std::vector<Local_point> points_;
  std::vector<Local_point> normals_;
  Local_point centre_ = Local_point::Zero();
  std::size_t ignored_ = 0;
  std::unique_ptr<Tree> tree_;
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_SAMPLE_SET_H
