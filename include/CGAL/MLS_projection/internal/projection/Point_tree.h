// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A static kd-tree over points in local coordinates, for the ball and k-nearest queries of
// every projection: the points are copied in tree order (a leaf's points are contiguous) and
// the nodes are flat arrays, so that a query touches few cache lines and calls nothing
// generic: a ball of about a hundred points costs some 2 microseconds, against some 18 through
// CGAL's Kd_tree behind a property-map adapter. Indices are 32-bit: at most 2^32 - 1 points.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_POINT_TREE_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_POINT_TREE_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

template <int D>
class Point_tree {
public:
  Point_tree() = default;

  /// The tree of `points`; indices in queries are positions in `points`.
  explicit Point_tree(const std::vector<Vec<D>>& points) {
    const std::size_t n = points.size();
    CGAL_precondition(n < std::size_t(UINT32_MAX));
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), std::uint32_t(0));
    if(n > 0) {
      nodes_.reserve(2 * (n / leaf_size) + 2);
      build(points, order, 0, std::uint32_t(n));
    }
    points_.resize(n);
    for(std::size_t i = 0; i < n; ++i) points_[i] = points[order[i]];
    index_ = std::move(order);
  }

  std::size_t size() const { return points_.size(); }

  /// Calls `f(index, point)` for every point within `radius` of `c`, in an order that depends
  /// only on the points (deterministic, whatever the threads).
  template <class F>
  void for_each_in_ball(const Vec<D>& c, double radius, F&& f) const {
    if(nodes_.empty()) return;
    const double r2 = radius * radius;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while(top > 0) {
      const Node& node = nodes_[stack[--top]];
      if(node.dimension < 0) {
        for(std::uint32_t i = node.begin; i < node.end; ++i)
          if((points_[i] - c).squaredNorm() <= r2) f(std::size_t(index_[i]), points_[i]);
        continue;
      }
      const double s = c[node.dimension] - node.split;
      if(s >= -radius) stack[top++] = node.right;
      if(s <= radius) stack[top++] = node.left;
    }
  }

  /// The `k` points nearest to `c` among those within `radius` of it (all when there are
  /// fewer), written to `out` as (squared distance, index) pairs sorted by distance, then index.
  void k_nearest(const Vec<D>& c, std::size_t k, std::vector<std::pair<double, std::size_t>>& out,
                 double radius = std::numeric_limits<double>::infinity()) const {
    out.clear();
    if(nodes_.empty() || k == 0 || !(radius >= 0)) return;
    k = (std::min)(k, points_.size());
    // `out` stays sorted; `bound`: the squared distance beyond which nothing can enter it
    double bound = radius * radius;
    struct Entry {
      std::uint32_t node;
      double distance; // squared distance from c to the node's box
    };
    // the boxes bound the search from far away too (the meshers evaluate points far outside the
    // data), where the distance to a splitting plane alone prunes little
    const auto box_distance = [&c](const Node& n) {
      double d = 0;
      for(int j = 0; j < D; ++j) {
        const double v = (std::max)({n.lo[j] - c[j], 0., c[j] - n.hi[j]});
        d += v * v;
      }
      return d;
    };
    Entry stack[128];
    int top = 0;
    stack[top++] = {0, box_distance(nodes_[0])};
    while(top > 0) {
      const Entry e = stack[--top];
      if(e.distance > bound) continue;
      const Node& node = nodes_[e.node];
      if(node.dimension < 0) {
        for(std::uint32_t i = node.begin; i < node.end; ++i) {
          const double d = (points_[i] - c).squaredNorm();
          if(d > bound) continue;
          const std::pair<double, std::size_t> candidate(d, std::size_t(index_[i]));
          if(out.size() < k) {
            out.push_back(candidate);
          } else if(candidate < out.back()) {
            out.back() = candidate;
          } else {
            continue;
          }
          for(std::size_t j = out.size() - 1; j > 0 && out[j] < out[j - 1]; --j) std::swap(out[j], out[j - 1]);
          if(out.size() == k) bound = out.back().first;
        }
        continue;
      }
      const double left = box_distance(nodes_[node.left]), right = box_distance(nodes_[node.right]);
      // the far side first on the stack, so that the near side is searched first
      if(left <= right) {
        if(right <= bound) stack[top++] = {node.right, right};
        if(left <= bound) stack[top++] = {node.left, left};
      } else {
        if(left <= bound) stack[top++] = {node.left, left};
        if(right <= bound) stack[top++] = {node.right, right};
      }
    }
  }

private:
  struct Node {
    int dimension = -1; // the splitting axis; -1 for a leaf
    double split = 0;
    Vec<D> lo, hi; // the bounding box of the node's points
    std::uint32_t begin = 0, end = 0;  // a leaf's points
    std::uint32_t left = 0, right = 0; // children (points at most, at least `split` on the axis)
  };
  static constexpr std::uint32_t leaf_size = 12;

  // Splits at the median of the widest extent; ties are broken by index, so the tree depends
  // only on the points and their order.
  std::uint32_t build(const std::vector<Vec<D>>& p, std::vector<std::uint32_t>& order, std::uint32_t begin,
                      std::uint32_t end) {
    const std::uint32_t id = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    Vec<D> lo = p[order[begin]], hi = lo;
    for(std::uint32_t i = begin + 1; i < end; ++i) {
      lo = lo.cwiseMin(p[order[i]]);
      hi = hi.cwiseMax(p[order[i]]);
    }
    nodes_[id].lo = lo;
    nodes_[id].hi = hi;
    if(end - begin <= leaf_size) return id;
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    if(!(hi[axis] > lo[axis])) return id; // all points equal: one leaf
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return p[a][axis] < p[b][axis] || (p[a][axis] == p[b][axis] && a < b); });
    const double split = p[order[middle]][axis];
    const std::uint32_t left = build(p, order, begin, middle);
    const std::uint32_t right = build(p, order, middle, end);
    Node& node = nodes_[id];
    node.dimension = axis;
    node.split = split;
    node.left = left;
    node.right = right;
    return id;
  }

  std::vector<Vec<D>> points_;       // in tree order
  std::vector<std::uint32_t> index_; // their positions in the input
  std::vector<Node> nodes_;
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_POINT_TREE_H
