// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The combinatorial part of `detect_sharp_features()`: crease points (a position and an
// unsigned unit direction) and apex points are clustered, linked into a graph along their
// directions, the graph is split into polylines at corners (CGAL's
// `split_graph_into_polylines`), and the polylines are resampled. Everything is sequential and
// visits points in the order they are given, so the output depends on the input order only.
// Lengths are in the caller's units (the caller multiplies its knobs by h).

#ifndef CGAL_MLS_PROJECTION_INTERNAL_FEATURES_POLYLINE_CHAINING_H
#define CGAL_MLS_PROJECTION_INTERNAL_FEATURES_POLYLINE_CHAINING_H

#include <CGAL/boost/graph/split_graph_into_polylines.h>

#include <boost/graph/adjacency_list.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

using Feature_vec = Eigen::Vector3d;

// A uniform hash grid of cell size `cell` over points added one by one; `near()` lists the
// indices of the points within `radius` <= cell of x, in increasing index order.
class Point_grid {
public:
  explicit Point_grid(double cell) : cell_(cell > 0 ? cell : 1.) {}

  std::size_t add(const Feature_vec& p) {
    points_.push_back(p);
    cells_[key(cell_of(p))].push_back(points_.size() - 1);
    return points_.size() - 1;
  }
  const Feature_vec& point(std::size_t i) const { return points_[i]; }
  std::size_t size() const { return points_.size(); }

  void near(const Feature_vec& x, double radius, std::vector<std::size_t>& out) const {
    out.clear();
    const std::array<std::int64_t, 3> c = cell_of(x);
    const int reach = int(std::ceil(radius / cell_));
    for(int i = -reach; i <= reach; ++i)
      for(int j = -reach; j <= reach; ++j)
        for(int k = -reach; k <= reach; ++k) {
          const auto it = cells_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if(it == cells_.end()) continue;
          for(std::size_t idx : it->second)
            if((points_[idx] - x).squaredNorm() <= radius * radius) out.push_back(idx);
        }
    std::sort(out.begin(), out.end());
  }

private:
  std::array<std::int64_t, 3> cell_of(const Feature_vec& p) const {
    std::array<std::int64_t, 3> c;
    for(int d = 0; d < 3; ++d) {
      const double t = std::floor(p[d] / cell_);
      c[d] = std::int64_t(std::max(-1e15, std::min(1e15, t)));
    }
    return c;
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    std::uint64_t h = 1469598103934665603ull;
    for(std::int64_t v : c) h = (h ^ std::uint64_t(v)) * 1099511628211ull;
    return h;
  }

  double cell_;
  std::vector<Feature_vec> points_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

struct Crease_point {
  Feature_vec point;
  Feature_vec direction; // unit, sign irrelevant
};

// Greedy clustering in input order: a crease point joins the first cluster whose first member is
// within `radius` and whose direction agrees within `cos_angle` (|cos|); a cluster is the mean of
// its members' positions and of their directions (signs aligned with the first member's).
inline std::vector<Crease_point> cluster_crease_points(const std::vector<Crease_point>& in, double radius,
                                                       double cos_angle) {
  Point_grid grid(radius);
  std::vector<Feature_vec> sum_p, sum_d, first_d;
  std::vector<int> count;
  std::vector<std::size_t> near;
  for(const Crease_point& c : in) {
    grid.near(c.point, radius, near);
    std::size_t found = near.size();
    for(std::size_t k = 0; k < near.size(); ++k)
      if(std::abs(first_d[near[k]].dot(c.direction)) >= cos_angle) {
        found = k;
        break;
      }
    if(found == near.size()) {
      grid.add(c.point);
      sum_p.push_back(c.point);
      sum_d.push_back(c.direction);
      first_d.push_back(c.direction);
      count.push_back(1);
    } else {
      const std::size_t j = near[found];
      sum_p[j] += c.point;
      sum_d[j] += (first_d[j].dot(c.direction) < 0 ? -1. : 1.) * c.direction;
      ++count[j];
    }
  }
  std::vector<Crease_point> out(count.size());
  for(std::size_t j = 0; j < count.size(); ++j) {
    out[j].point = sum_p[j] / count[j];
    const double len = sum_d[j].norm();
    out[j].direction = len > 0 ? Feature_vec(sum_d[j] / len) : first_d[j];
  }
  return out;
}

// Greedy clustering of apex points in input order (a point joins the first cluster whose first
// member is within `radius`); each cluster is represented by its member nearest to the mean of
// its members (a point some projection put on an apex, not an average off the surface).
inline std::vector<Feature_vec> cluster_apex_points(const std::vector<Feature_vec>& in, double radius) {
  Point_grid grid(radius);
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::size_t> near;
  for(std::size_t i = 0; i < in.size(); ++i) {
    grid.near(in[i], radius, near);
    if(near.empty()) {
      grid.add(in[i]);
      members.push_back({i});
    } else {
      members[near.front()].push_back(i);
    }
  }
  std::vector<Feature_vec> out;
  for(const auto& m : members) {
    Feature_vec mean = Feature_vec::Zero();
    for(std::size_t i : m) mean += in[i];
    mean /= double(m.size());
    std::size_t best = m.front();
    for(std::size_t i : m)
      if((in[i] - mean).squaredNorm() < (in[best] - mean).squaredNorm()) best = i;
    out.push_back(in[best]);
  }
  return out;
}

struct Chaining_parameters {
  double link_radius;        // largest length of a link between two crease nodes
  double cos_link_angle;     // links and directions agree within this angle (cosine)
  double corner_radius;      // crease nodes this close to a corner are dropped (the corner stands for them)
  double corner_link_radius; // largest length of a link from a branch end to a corner
  double gap_radius;         // largest length of a link between two branch ends
};

// The feature graph: vertices are the crease nodes, then the corners. Returns the polylines as
// sequences of vertex indices (a closed one repeats its first vertex), split at the corners and
// at vertices of degree other than 2, in a deterministic order.
inline std::vector<std::vector<std::size_t>> chain_features(std::vector<Crease_point>& nodes,
                                                            std::vector<Feature_vec>& corners,
                                                            const Chaining_parameters& prm) {
  // drop the nodes inside a corner's ball
  {
    std::vector<Crease_point> kept;
    for(const Crease_point& c : nodes) {
      bool inside = false;
      for(const Feature_vec& q : corners) inside |= (c.point - q).norm() < prm.corner_radius;
      if(!inside) kept.push_back(c);
    }
    nodes.swap(kept);
  }
  const std::size_t n = nodes.size();
  Point_grid grid(prm.link_radius);
  for(const Crease_point& c : nodes) grid.add(c.point);

  // On each side (+d, -d) of each node, its nearest node within `radius`, roughly along d, with a
  // similar direction; links are made for mutual choices only, so that every node gets at most
  // one link on each side. The second pass closes gaps: it considers the free sides only, over
  // a larger radius.
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph g(n + corners.size());
  std::vector<std::array<bool, 2>> linked(n, {false, false});
  std::vector<std::size_t> near;
  const auto side_towards = [&](std::size_t i, const Feature_vec& x, double& cs) {
    const Feature_vec e = x - nodes[i].point;
    const double len = e.norm();
    cs = len > 0 ? e.dot(nodes[i].direction) / len : 0.;
    return cs > 0 ? 0 : 1;
  };
  const auto link_pass = [&](double radius, bool free_only) {
    std::vector<std::array<std::size_t, 2>> side(n, {none, none});
    for(std::size_t i = 0; i < n; ++i) {
      const Feature_vec& p = nodes[i].point;
      grid.near(p, radius, near);
      std::array<double, 2> best{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
      for(std::size_t j : near) {
        if(j == i || std::abs(nodes[j].direction.dot(nodes[i].direction)) < prm.cos_link_angle) continue;
        double ci, cj;
        const int s = side_towards(i, nodes[j].point, ci), t = side_towards(j, p, cj);
        if(std::abs(ci) < prm.cos_link_angle || std::abs(cj) < prm.cos_link_angle) continue;
        if(free_only && (linked[i][s] || linked[j][t])) continue;
        const double len = (nodes[j].point - p).norm();
        if(len < best[s]) {
          best[s] = len;
          side[i][s] = j;
        }
      }
    }
    for(std::size_t i = 0; i < n; ++i)
      for(int s = 0; s < 2; ++s) {
        const std::size_t j = side[i][s];
        if(j == none || j < i || (free_only && linked[i][s])) continue;
        double cj;
        const int t = side_towards(j, nodes[i].point, cj);
        if(side[j][t] != i || (free_only && linked[j][t])) continue;
        boost::add_edge(i, j, g);
        linked[i][s] = linked[j][t] = true;
      }
  };
  link_pass(prm.link_radius, false);
  link_pass(prm.gap_radius, true);
  // Junctions: where three branch ends or more, far from every known corner, point at a common
  // point (their lines pass within corner_radius / 2 of each other, less than corner_link_radius
  // ahead of each end), a corner is added at the least-squares point of their lines. This finds
  // the corners no projection put on an apex.
  {
    std::vector<std::size_t> ends;
    std::vector<Feature_vec> ray; // the direction of the free side, away from the branch
    for(std::size_t i = 0; i < n; ++i) {
      if(linked[i][0] == linked[i][1]) continue;
      bool near_corner = false;
      for(const Feature_vec& c : corners) near_corner |= (c - nodes[i].point).norm() <= prm.corner_link_radius;
      if(near_corner) continue;
      ends.push_back(i);
      ray.push_back(linked[i][0] ? Feature_vec(-nodes[i].direction) : nodes[i].direction);
    }
    // closest approach of the rays of ends a and b: parameters ta, tb, and the distance
    const auto approach = [&](std::size_t a, std::size_t b, double& ta, double& tb) {
      const Feature_vec &pa = nodes[ends[a]].point, &pb = nodes[ends[b]].point, &da = ray[a], &db = ray[b];
      const double c = da.dot(db), den = 1 - c * c;
      if(!(den > 1e-9)) return std::numeric_limits<double>::infinity();
      const Feature_vec w = pa - pb;
      ta = (c * db.dot(w) - da.dot(w)) / den;
      tb = (db.dot(w) - c * da.dot(w)) / den;
      return ((pa + ta * da) - (pb + tb * db)).norm();
    };
    std::vector<bool> used(ends.size(), false);
    for(std::size_t a = 0; a < ends.size(); ++a) {
      if(used[a]) continue;
      std::vector<std::size_t> group{a};
      for(std::size_t b = 0; b < ends.size(); ++b) {
        if(b == a || used[b] || std::abs(ray[a].dot(ray[b])) >= prm.cos_link_angle) continue;
        double ta = 0, tb = 0;
        const double gap = approach(a, b, ta, tb);
        if(gap <= 0.5 * prm.corner_radius && ta > -0.5 * prm.corner_radius && tb > -0.5 * prm.corner_radius &&
           ta <= prm.corner_link_radius && tb <= prm.corner_link_radius)
          group.push_back(b);
      }
      if(group.size() < 3) continue;
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      Feature_vec rhs = Feature_vec::Zero();
      for(std::size_t k : group) {
        const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - ray[k] * ray[k].transpose();
        A += P;
        rhs += P * nodes[ends[k]].point;
      }
      const Feature_vec x = A.ldlt().solve(rhs);
      if(!x.allFinite()) continue;
      for(std::size_t k : group) used[k] = true;
      corners.push_back(x);
      boost::add_vertex(g);
    }
  }

  // Branch ends near a corner, pointing at it with a free side, are linked to it: the nearest
  // end of each branch (ends in directions within the link angle of an accepted one are the
  // same branch).
  for(std::size_t c = 0; c < corners.size(); ++c) {
    std::vector<std::pair<double, std::size_t>> candidates;
    for(std::size_t i = 0; i < n; ++i) {
      const Feature_vec e = corners[c] - nodes[i].point;
      const double len = e.norm();
      if(!(len > 0) || len > prm.corner_link_radius) continue;
      const double cs = e.dot(nodes[i].direction) / len;
      if(std::abs(cs) < prm.cos_link_angle) continue;
      if(linked[i][cs > 0 ? 0 : 1]) continue;
      candidates.emplace_back(len, i);
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<Feature_vec> branches;
    for(const auto& cand : candidates) {
      const Feature_vec u = (nodes[cand.second].point - corners[c]).normalized();
      bool same = false;
      for(const Feature_vec& b : branches) same |= u.dot(b) >= prm.cos_link_angle;
      if(same) continue;
      branches.push_back(u);
      boost::add_edge(cand.second, n + c, g);
    }
  }

  struct Visitor {
    std::vector<std::vector<std::size_t>>* out;
    void start_new_polyline() { out->emplace_back(); }
    void add_node(std::size_t v) { out->back().push_back(v); }
    void end_polyline() {}
  };
  std::vector<std::vector<std::size_t>> polylines;
  Visitor visitor{&polylines};
  const std::size_t first_corner = n;
  const auto is_terminal = [first_corner](std::size_t v, const Graph&) { return v >= first_corner; };
  CGAL::split_graph_into_polylines(g, visitor, is_terminal);
  polylines.erase(std::remove_if(polylines.begin(), polylines.end(),
                                 [](const std::vector<std::size_t>& p) { return p.size() < 2; }),
                  polylines.end());
  return polylines;
}

inline double polyline_length(const std::vector<Feature_vec>& p) {
  double L = 0;
  for(std::size_t i = 1; i < p.size(); ++i) L += (p[i] - p[i - 1]).norm();
  return L;
}

// The distance from `x` to the polyline `p`.
inline double distance_to_polyline(const Feature_vec& x, const std::vector<Feature_vec>& p) {
  double d = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < p.size(); ++i) {
    d = (std::min)(d, (x - p[i]).norm());
    if(i == 0) continue;
    const Feature_vec e = p[i] - p[i - 1];
    const double l2 = e.squaredNorm();
    if(!(l2 > 0)) continue;
    const double t = (x - p[i - 1]).dot(e) / l2;
    if(t > 0 && t < 1) d = (std::min)(d, (x - (p[i - 1] + t * e)).norm());
  }
  return d;
}

// Whether a vertex of `a` lies closer than `distance` to `b`, or a vertex of `b` to `a`, not
// counting the vertices within `distance` of a point of `shared` (the corners where both end).
inline bool polylines_come_closer(const std::vector<Feature_vec>& a, const std::vector<Feature_vec>& b, double distance,
                                  const std::vector<Feature_vec>& shared) {
  const auto near_shared = [&](const Feature_vec& x) {
    for(const Feature_vec& c : shared)
      if((x - c).norm() < distance) return true;
    return false;
  };
  for(int pass = 0; pass < 2; ++pass) {
    const auto& from = pass == 0 ? a : b;
    const auto& to = pass == 0 ? b : a;
    for(const Feature_vec& x : from)
      if(!near_shared(x) && distance_to_polyline(x, to) < distance) return true;
  }
  return false;
}

// `p` resampled at equal arc lengths, about `spacing` apart (at least one segment); the
// endpoints are kept exactly.
inline std::vector<Feature_vec> resample_polyline(const std::vector<Feature_vec>& p, double spacing) {
  const double L = polyline_length(p);
  const int segments = (std::max)(1, int(std::lround(L / spacing)));
  std::vector<Feature_vec> out{p.front()};
  std::size_t k = 1;
  double before = 0; // arc length at p[k-1]
  for(int s = 1; s < segments; ++s) {
    const double t = L * s / segments;
    while(k + 1 < p.size() && before + (p[k] - p[k - 1]).norm() < t) {
      before += (p[k] - p[k - 1]).norm();
      ++k;
    }
    const double seg = (p[k] - p[k - 1]).norm();
    const double a = seg > 0 ? std::min(1., std::max(0., (t - before) / seg)) : 0.;
    out.push_back((1 - a) * p[k - 1] + a * p[k]);
  }
  out.push_back(p.back());
  return out;
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_FEATURES_POLYLINE_CHAINING_H
