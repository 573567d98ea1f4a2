// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_WEDGE_FAN_FUNCTION_SPACE_H
#define CGAL_MLS_PROJECTION_WEDGE_FAN_FUNCTION_SPACE_H

#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctionSpaces
/// The space of piecewise-linear "fans" with apex at the frame origin, the non-smooth
/// function space of section 4.2 of the paper, which reconstructs creases and corners.
///
/// - In 2D, two rays from the origin with directions \f$(\cos\theta_1, \sin\theta_1)\f$ and
///   \f$(\cos\theta_2, \sin\theta_2)\f$: parameters \f$(\theta_1, \theta_2)\f$; the plane
///   \f$x_2 = 0\f$ is \f$(0, \pi)\f$. The angles are taken modulo \f$2\pi\f$ in
///   \f$[-\pi/2, 3\pi/2)\f$ (cut at the downward direction) and sorted: the curve goes in along
///   the second ray and out along the first, and its "up" side is the sector swept
///   counter-clockwise from the first ray to the second (the upper half-plane for the plane,
///   the inside of a valley, the outside of a ridge). The normal of a ray is its direction
///   rotated by \f$+\pi/2\f$ (first ray) or \f$-\pi/2\f$ (second ray).
/// - In 3D, `N` unit vectors \f$v_i = (\cos\phi_i\cos\lambda_i, \cos\phi_i\sin\lambda_i,
///   \sin\phi_i)\f$ given by their latitudes \f$\phi_i\f$ and longitudes \f$\lambda_i\f$, stored
///   as \f$(\phi_0, \lambda_0, \phi_1, \lambda_1, \dots)\f$. After sorting the vectors by
///   longitude (modulo \f$2\pi\f$), the surface is the union of the infinite triangles (cones)
///   \f$\{\alpha v_i + \beta v_{i+1} : \alpha, \beta \geq 0\}\f$ of consecutive vectors,
///   cyclically. As in the paper, the sort is explicit, so that the parameters are free.
///   The normal of the cone \f$(v_i, v_{i+1})\f$ is \f$v_i \times v_{i+1}\f$ normalised, which
///   points up (positive \f$e_3\f$ component) when the longitude gap \f$\lambda_{i+1} - \lambda_i\f$
///   is below \f$\pi\f$; it is reversed for a gap above \f$\pi\f$, whose cone spans the short way.
///   The plane \f$x_3 = 0\f$ is all latitudes 0 (identity() spreads the longitudes evenly).
///
/// Representable shapes, with `N = 4`: a plane; an edge of any dihedral angle (\f$v_0\f$ and
/// \f$v_2\f$ opposite along the crease, \f$v_1\f$ and \f$v_3\f$ in the two faces: two
/// consecutive coplanar cones make one half-plane); a corner of three faces, e.g. a cube
/// corner (the three edge directions, and a fourth vector inside one of the faces, so that
/// its two cones are coplanar and make that face).
///
/// A closest point is on a feature (`is_on_feature`) when it is on a ray (a crease, `direction` = the ray),
/// unless the two cones meeting there are coplanar (normals within \f$10^{-9}\f$), or at the
/// apex (unless all cones are coplanar; when the faces lie in two planes, the apex is a point of
/// their crease and `direction` is the crease's). A closest point within `ray_tolerance` of a
/// ray is on that ray.
///
/// \cgalModels `MLSFunctionSpace`
/// \tparam D the ambient dimension, 2 or 3
/// \tparam N the number of vectors of the fan in 3D (at least 3; ignored in 2D)
template <int D, int N = 4>
class Wedge_fan_function_space {
  static_assert(D == 2 || D == 3, "Wedge_fan_function_space: D must be 2 or 3");
  static_assert(D == 2 || N >= 3, "Wedge_fan_function_space: N must be at least 3");

public:
  /// As described by the concept `MLSFunctionSpace`; `number_of_vectors` is the number of unit
  /// vectors of the fan (2 in 2D, `N` in 3D).
  /// @{
  static constexpr int ambient_dimension = D;
  static constexpr int number_of_vectors = (D == 2) ? 2 : N;
  static constexpr int number_of_parameters = (D == 2) ? 2 : 2 * N;
  using Parameters = Eigen::Matrix<double, number_of_parameters, 1>;
  using Vector = Eigen::Matrix<double, D, 1>; ///< a point or vector in frame coordinates
  /// @}

  /// The tolerance on the normals of two adjacent cones under which they are one plane.
  static constexpr double coplanarity_tolerance = 1e-9;
  /// A closest point within this distance (times \f$1 + |x|\f$, in frame units: \f$h\f$ for the
  /// operators) of a ray of the fan is on that ray: the crease of an exact fit of sampled data is
  /// known to the fit's precision only (residuals of about \f$10^{-13}\f$).
  static constexpr double ray_tolerance = 1e-11;

  /// The name of the space, `"wedge_fan"`.
  static const char* name() { return "wedge_fan"; }
  /// The number of parameters of the member plus those of the frame (\f$D\f$).
  static constexpr std::size_t minimum_number_of_points() { return number_of_parameters + D; }

  /// The plane \f$x_D = 0\f$: \f$(0, \pi)\f$ in 2D; in 3D, latitudes 0 and longitudes
  /// \f$2\pi i / N\f$.
  Parameters identity() const {
    Parameters c;
    if constexpr(D == 2) {
      c << 0., CGAL_PI;
    } else {
      for(int i = 0; i < N; ++i) {
        c[2 * i] = 0.;
        c[2 * i + 1] = 2. * CGAL_PI * i / N;
      }
    }
    return c;
  }

  /// Whether the closest point can be on a feature: the operators then add starts at creases
  /// and apices proposed from the neighbourhood.
  static constexpr bool has_sharp_features = true;
  /// The vectors are free on the circle or sphere, so every rotation of the frame is a member:
  /// the operators optimise the frame origin only.
  static constexpr bool is_rotation_invariant = true;

  /// The initial member from the points `p` (frame coordinates) with weights `w`, the apex at
  /// the frame origin. 2D: each ray gets the weighted mean slope of the points on its side
  /// (\f$x > 0\f$, \f$x < 0\f$), so a line or a wedge through the origin is reproduced exactly. 3D:
  /// each vector, at the longitudes \f$2\pi i/N\f$ (the paper's even spread), gets the elevation
  /// of the weighted least-squares plane through the apex of the points of its sector
  /// (longitudes within \f$\pi/N\f$), or of all points when the sector has too few: a plane through
  /// the origin is reproduced exactly (zero latitudes for a level one, the paper's initial
  /// estimate), and an edge through the origin along the first axis approximately.
  Parameters fit(const Vector* p, const double* w, std::size_t n) const {
    // the least-squares plane through the origin, z = g . u
    using M = Eigen::Matrix<double, D - 1, D - 1>;
    using U = Eigen::Matrix<double, D - 1, 1>;
    M A = M::Zero();
    U b = U::Zero();
    for(std::size_t i = 0; i < n; ++i) {
      if(!(w[i] > 0)) continue;
      const U u = p[i].template head<D - 1>();
      A.noalias() += w[i] * u * u.transpose();
      b.noalias() += w[i] * p[i][D - 1] * u;
    }
    Eigen::CompleteOrthogonalDecomposition<M> cod(A);
    cod.setThreshold(1e-12);
    U g = cod.solve(b);
    if(!g.allFinite()) g.setZero();

    Parameters r;
    if constexpr(D == 2) {
      for(int side = 0; side < 2; ++side) { // side 0: x > 0 (first ray), side 1: x < 0
        double sx = 0, sz = 0;
        for(std::size_t i = 0; i < n; ++i)
          if(w[i] > 0 && (side == 0 ? p[i][0] > 0 : p[i][0] < 0)) {
            sx += w[i] * std::abs(p[i][0]);
            sz += w[i] * p[i][1];
          }
        const double slope = sx > 0 ? sz / sx : (side == 0 ? g[0] : -g[0]);
        r[side] = side == 0 ? std::atan(slope) : CGAL_PI - std::atan(slope);
      }
    } else {
      for(int k = 0; k < N; ++k) {
        // the least-squares plane through the apex of the points of the sector
        const double lon = 2. * CGAL_PI * k / N;
        M As = M::Zero();
        U bs = U::Zero();
        int count = 0;
        for(std::size_t i = 0; i < n; ++i) {
          if(!(w[i] > 0) || !(std::hypot(p[i][0], p[i][1]) > 0)) continue;
          double dl = std::atan2(p[i][1], p[i][0]) - lon;
          dl -= 2. * CGAL_PI * std::floor((dl + CGAL_PI) / (2. * CGAL_PI));
          if(std::abs(dl) >= CGAL_PI / N) continue;
          const U u = p[i].template head<2>();
          As.noalias() += w[i] * u * u.transpose();
          bs.noalias() += w[i] * p[i][2] * u;
          ++count;
        }
        U gs = g;
        if(count >= 3 && As.determinant() > 1e-12 * As.squaredNorm()) {
          const U sol = As.ldlt().solve(bs);
          if(sol.allFinite()) gs = sol;
        }
        r[2 * k] = std::atan(gs[0] * std::cos(lon) + gs[1] * std::sin(lon));
        r[2 * k + 1] = lon;
      }
    }
    return r;
  }

  /// The member made of the `k` hyperplanes through the frame origin with unit normals
  /// `normals[0..k-1]` (frame coordinates): the boundary of the intersection of the half-spaces
  /// behind them (a crease for two, a corner for three in 3D). Its rays: in 2D, along each line,
  /// away from the other; in 3D, along the crease both ways and into each plane across it
  /// (two), or along the three pairwise intersections (three); further vectors bisect the
  /// widest angle between consecutive rays, which both lie in one plane. Returns false when the
  /// hyperplanes are within about 0.6 degrees of parallel or the fan has too few vectors.
  bool member_of_hyperplanes(const Vector* normals, int k, Parameters& c) const {
    constexpr double tolerance = 1e-2;
    if constexpr(D == 2) {
      if(k != 2) return false;
      for(int i = 0; i < 2; ++i) {
        V d(-normals[i][1], normals[i][0]);
        const double across = normals[1 - i].dot(d);
        if(!(std::abs(across) > tolerance)) return false;
        if(across > 0) d = -d;
        c[i] = std::atan2(d[1], d[0]);
      }
      return true;
    } else {
      std::array<V, number_of_vectors> rays;
      int m = 0;
      if(k == 2 && N >= 4) {
        V e = normals[0].cross(normals[1]);
        if(!(e.norm() > tolerance)) return false;
        e.normalize();
        V d0 = normals[0].cross(e), d1 = normals[1].cross(e);
        if(normals[1].dot(d0) > 0) d0 = -d0;
        if(normals[0].dot(d1) > 0) d1 = -d1;
        rays[m++] = e;
        rays[m++] = d0;
        rays[m++] = -e;
        rays[m++] = d1;
      } else if(k == 3) {
        for(int i = 0; i < 3; ++i) {
          V e = normals[(i + 1) % 3].cross(normals[(i + 2) % 3]);
          if(!(e.norm() > tolerance)) return false;
          e.normalize();
          const double across = normals[i].dot(e);
          if(!(std::abs(across) > tolerance)) return false;
          rays[m++] = across > 0 ? V(-e) : e;
        }
      } else {
        return false;
      }
      // The rays in the order of their longitudes, then the widest gaps bisected.
      std::array<double, number_of_vectors> lon;
      for(int i = 0; i < m; ++i) lon[i] = std::atan2(rays[i][1], rays[i][0]);
      for(int i = 1; i < m; ++i)
        for(int j = i; j > 0 && lon[j] < lon[j - 1]; --j) {
          std::swap(lon[j], lon[j - 1]);
          std::swap(rays[j], rays[j - 1]);
        }
      while(m < N) {
        int widest = 0;
        double angle = -1;
        for(int i = 0; i < m; ++i) {
          const double a = std::acos((std::max)(-1., (std::min)(1., rays[i].dot(rays[(i + 1) % m]))));
          if(a > angle) {
            angle = a;
            widest = i;
          }
        }
        const V b = (rays[widest] + rays[(widest + 1) % m]).normalized();
        for(int i = m; i > widest + 1; --i) rays[i] = rays[i - 1];
        rays[widest + 1] = b;
        ++m;
      }
      for(int i = 0; i < N; ++i) {
        c[2 * i] = std::asin((std::max)(-1., (std::min)(1., rays[i][2])));
        c[2 * i + 1] = std::atan2(rays[i][1], rays[i][0]);
      }
      return c.allFinite();
    }
  }

  /// The unit vector of latitude `lat` and longitude `lon`.
  static Eigen::Vector3d direction(double lat, double lon) {
    const double cl = std::cos(lat);
    return Eigen::Vector3d(cl * std::cos(lon), cl * std::sin(lon), std::sin(lat));
  }

  /// The closest point of `x` (frame coordinates) on the fan `c`.
  Closest_point<D> closest_point(const Parameters& c, const Vector& x) const {
    return project(prepare(c), x, nullptr);
  }

  class Prepared_member; // defined after the private type it holds

  /// The fan `c` prepared for `closest_point(const Prepared_member&, x)`.
  Prepared_member prepare_member(const Parameters& c) const {
    Prepared_member m;
    m.pieces_ = prepare(c);
    return m;
  }

  /// The closest point of `x` (frame coordinates) on the prepared fan `m`: the same as
  /// `closest_point(c, x)` for the fan `c` that `m` was prepared from.
  Closest_point<D> closest_point(const Prepared_member& m, const Vector& x) const {
    return closest_point_on(m.pieces_, x);
  }

  /// The closest point `cp` of `x` on the fan `c` and the derivatives of its position on the cone
  /// or ray that holds it: by the parameters in `d_parameters`, by `x` in `d_point`. Returns false
  /// (the derivatives zero) where they are one-sided, the closest point moving onto a face beside
  /// its piece when the fan or `x` moves: at the apex; in 3D, on a ray between two coplanar cones,
  /// or on a crease ray with `x` on the fan (within \f$10^{-7}(1 + |x|)\f$).
  bool closest_point_derivatives(const Parameters& c, const Vector& x, Closest_point<D>& cp,
                                 Eigen::Matrix<double, D, number_of_parameters>& d_parameters,
                                 Eigen::Matrix<double, D, D>& d_point) const {
    const Fan f = prepare(c);
    std::array<double, number_of_vectors> coef;
    cp = closest_point_on(f, x, coef);
    d_parameters.setZero();
    d_point.setZero();
    // a cone holds the foot when two consecutive coefficients are not zero, a ray when one is
    int ray = -1;
    for(int j = 0; j < number_of_vectors; ++j) {
      if(coef[j] == 0.) continue;
      if constexpr(D == 3) {
        const int k = (j + 1) % number_of_vectors;
        if(coef[k] != 0.) {
          cone_derivatives(f, x, j, k, d_parameters, d_point);
          return true;
        }
      }
      ray = j;
    }
    // Elsewhere the closest point moves onto a face beside its piece when the fan or x moves: at
    // the apex (a corner's, a crease's or a plane's), and in 3D on a ray between coplanar cones
    // or on a crease ray that x lies on.
    if(ray < 0) return false;
    if constexpr(D == 3)
      if(!cp.is_on_feature || std::abs(cp.signed_distance) <= 1e-7 * (1. + x.norm())) return false;
    // on a ray, the foot is (x . v) v
    const V& v = f.v[ray];
    const double t = x.dot(v);
    for(int a = 0; a < (D == 2 ? 1 : 2); ++a) {
      const V& dv = f.dv[ray][a];
      d_parameters.col(D == 2 ? f.order[ray] : 2 * f.order[ray] + a) = x.dot(dv) * v + t * dv;
    }
    d_point = v * v.transpose();
    return true;
  }

  /// The closest points of the `n` points `x` on the fan `c` (the fan is prepared once) and,
  /// when `gradients` is not null, the derivatives of their signed distances with respect to
  /// the parameters: by the envelope theorem, \f$-g \cdot \partial S/\partial c\f$ at the closest
  /// point \f$S\f$, with \f$g = (x - S)/d\f$ (the normal when \f$d = 0\f$).
  void closest_points(const Parameters& c, const Vector* x, std::size_t n, Closest_point<D>* out,
                      Parameters* gradients) const {
    const Fan fan = prepare(c);
    for(std::size_t i = 0; i < n; ++i) out[i] = project(fan, x[i], gradients ? gradients + i : nullptr);
  }

private:
  using V = Vector;

  static double wrap(double t, double lo) { // t modulo 2 pi, in [lo, lo + 2 pi)
    double r = t - 2. * CGAL_PI * std::floor((t - lo) / (2. * CGAL_PI));
    if(r >= lo + 2. * CGAL_PI) r -= 2. * CGAL_PI; // rounding
    return r;
  }

  // The pieces of a fan, what its closest points need: the vectors sorted by angle or longitude
  // and the normals of the pieces.
  struct Pieces {
    std::array<V, number_of_vectors> v;      // sorted vectors
    std::array<V, number_of_vectors> fn;     // 3D: normal of cone j = (v[j], v[j+1]); 2D: normal of ray j
    std::array<bool, number_of_vectors> ok;  // 3D: cone j is not degenerate
    std::array<double, number_of_vectors> cn{}; // 3D: v[j] . v[j+1]
    std::array<double, number_of_vectors> inverse_det{}; // 3D: 1 / (1 - cn[j]^2) for a cone that is not degenerate
  };

public:
  /// A fan prepared for many closest-point queries: its vectors and faces, computed once from
  /// their angles.
  class Prepared_member {
    friend class Wedge_fan_function_space;
    Pieces pieces_;
  };

private:
  // A fan prepared for many closest-point queries: its pieces, and the derivatives of the vectors
  // by their parameters.
  struct Fan : Pieces {
    std::array<int, number_of_vectors> order; // index (in the parameters) of the j-th sorted vector
    std::array<std::array<V, 2>, number_of_vectors> dv; // d v[j] / d (its parameters)
  };

  // The closest point of x on the fan of `pieces`, and the foot's coefficients on the sorted vectors.
  static Closest_point<D> closest_point_on(const Pieces& pieces, const V& x, std::array<double, number_of_vectors>& coef) {
    coef.fill(0.);
    Closest_point<D> cp;
    if constexpr(D == 2) cp = project_2(pieces, x, coef);
    else cp = project_3(pieces, x, coef);
    internal::set_signed_distance(cp, x);
    return cp;
  }

  static Closest_point<D> closest_point_on(const Pieces& pieces, const V& x) {
    std::array<double, number_of_vectors> coef;
    return closest_point_on(pieces, x, coef);
  }

  static Fan prepare(const Parameters& c) {
    Fan f;
    if constexpr(D == 2) {
      const double t0 = wrap(c[0], -CGAL_PI / 2), t1 = wrap(c[1], -CGAL_PI / 2);
      f.order = t1 < t0 ? std::array<int, 2>{1, 0} : std::array<int, 2>{0, 1};
      const double ta = f.order[0] == 0 ? t0 : t1, tb = f.order[0] == 0 ? t1 : t0;
      f.v[0] = V(std::cos(ta), std::sin(ta));
      f.v[1] = V(std::cos(tb), std::sin(tb));
      f.fn[0] = V(-f.v[0][1], f.v[0][0]);
      f.fn[1] = V(f.v[1][1], -f.v[1][0]);
      for(int j = 0; j < 2; ++j) {
        f.ok[j] = true;
        f.dv[j][0] = V(-f.v[j][1], f.v[j][0]);
        f.dv[j][1] = V::Zero();
      }
    } else {
      // Sort the vectors by longitude modulo 2 pi (insertion sort: N is small).
      std::array<double, N> lon;
      for(int i = 0; i < N; ++i) {
        lon[i] = wrap(c[2 * i + 1], 0.);
        f.order[i] = i;
      }
      for(int i = 1; i < N; ++i)
        for(int j = i; j > 0 && lon[f.order[j]] < lon[f.order[j - 1]]; --j) std::swap(f.order[j], f.order[j - 1]);
      for(int j = 0; j < N; ++j) {
        const double la = c[2 * f.order[j]], lo = c[2 * f.order[j] + 1];
        const double cla = std::cos(la), sla = std::sin(la), clo = std::cos(lo), slo = std::sin(lo);
        f.v[j] = V(cla * clo, cla * slo, sla);
        f.dv[j][0] = V(-sla * clo, -sla * slo, cla);
        f.dv[j][1] = V(-cla * slo, cla * clo, 0.);
      }
      for(int j = 0; j < N; ++j) {
        const int k = (j + 1) % N;
        double gap = lon[f.order[k]] - lon[f.order[j]];
        if(k == 0) gap += 2. * CGAL_PI;
        const V n = f.v[j].cross(f.v[k]);
        const double len = n.norm();
        f.cn[j] = f.v[j].dot(f.v[k]);
        f.ok[j] = len > 1e-12 && 1. - f.cn[j] * f.cn[j] > 0.;
        f.inverse_det[j] = f.ok[j] ? 1. / (1. - f.cn[j] * f.cn[j]) : 0.;
        f.fn[j] = f.ok[j] ? V(((gap > CGAL_PI) ? -1. : 1.) * n / len) : V::Zero();
      }
    }
    return f;
  }

  // The closest point of x on the prepared fan; the foot is sum_j coef[j] v[j] (sorted order).
  static Closest_point<D> project(const Fan& f, const V& x, Parameters* gradient) {
    std::array<double, number_of_vectors> coef;
    const Closest_point<D> cp = closest_point_on(f, x, coef);
    if(gradient) {
      V g = cp.normal;
      if(std::abs(cp.signed_distance) > 0.) g = (x - cp.point) / cp.signed_distance;
      gradient->setZero();
      for(int j = 0; j < number_of_vectors; ++j) {
        if(coef[j] == 0.) continue;
        const int i = f.order[j];
        if constexpr(D == 2) {
          (*gradient)[i] = -coef[j] * g.dot(f.dv[j][0]);
        } else {
          (*gradient)[2 * i] = -coef[j] * g.dot(f.dv[j][0]);
          (*gradient)[2 * i + 1] = -coef[j] * g.dot(f.dv[j][1]);
        }
      }
    }
    return cp;
  }

  // The derivatives of the foot x - (x . n) n on the plane of the cone (v[j], v[k]), n = u / |u|,
  // u = v[j] x v[k].
  static void cone_derivatives(const Fan& f, const V& x, int j, int k,
                               Eigen::Matrix<double, D, number_of_parameters>& d_parameters, Eigen::Matrix<double, D, D>& d_point) {
    if constexpr(D == 3) {
      const V u = f.v[j].cross(f.v[k]);
      const double len = u.norm();
      const V n = u / len;
      const double xn = x.dot(n);
      for(int a = 0; a < 2; ++a)
        for(int side = 0; side < 2; ++side) {
          const V du = side == 0 ? V(f.dv[j][a].cross(f.v[k])) : V(f.v[j].cross(f.dv[k][a]));
          const V dn = (du - n * n.dot(du)) / len;
          d_parameters.col(2 * f.order[side == 0 ? j : k] + a) = -x.dot(dn) * n - xn * dn;
        }
      d_point = Eigen::Matrix<double, D, D>::Identity() - n * n.transpose();
    }
  }

  static Closest_point<2> project_2(const Pieces& f, const V& x, std::array<double, 2>& coef) {
    const V &da = f.v[0], &db = f.v[1], &na = f.fn[0], &nb = f.fn[1];
    const double sa = std::max(0., x.dot(da)), sb = std::max(0., x.dot(db));
    const double ea = (x - sa * da).squaredNorm(), eb = (x - sb * db).squaredNorm();
    Closest_point<2> cp;
    const bool a_wins = ea <= eb;
    const double s = a_wins ? sa : sb;
    if(s > 0.) {
      cp.point = a_wins ? V(sa * da) : V(sb * db);
      cp.normal = a_wins ? na : nb;
      coef[a_wins ? 0 : 1] = s;
    } else { // the apex
      cp.point = V::Zero();
      const bool flat = std::abs(na[0] * nb[1] - na[1] * nb[0]) <= coplanarity_tolerance && na.dot(nb) > 0;
      cp.is_on_feature = !flat;
      const V sum = na + nb;
      const double len = sum.norm();
      cp.normal = (len > 1e-12) ? V(sum / len) : na;
    }
    return cp;
  }

  static Closest_point<3> project_3(const Pieces& f, const V& x, std::array<double, N>& coef) {
    const auto& v = f.v;
    const auto& fn = f.fn;
    const auto& ok = f.ok;
    auto coplanar = [&](int i, int j) {
      return ok[i] && ok[j] && fn[i].dot(fn[j]) > 0 && fn[i].cross(fn[j]).norm() <= coplanarity_tolerance;
    };

    // Nearest piece: 0 = apex, 1 = interior of cone `which`, 2 = ray `which`. The squared
    // distances: |x|^2 to the apex, (x . n)^2 to a cone's plane (its unit normal n) when the foot
    // is inside the cone, |x - t v|^2 to a ray (t = x . v > 0); the foot of the nearest only is built.
    const double x2 = x.squaredNorm();
    int kind = 0, which = -1;
    double best = x2, ca = 0., cb = 0.;
    std::array<double, N> xv; // x . v[j]
    for(int j = 0; j < N; ++j) xv[j] = x.dot(v[j]);
    for(int j = 0; j < N; ++j) {
      if(!ok[j]) continue;
      const int k = (j + 1) % N;
      const double cjk = f.cn[j], rj = xv[j], rk = xv[k];
      const double alpha = (rj - cjk * rk) * f.inverse_det[j], beta = (rk - cjk * rj) * f.inverse_det[j];
      if(!(alpha >= 0.) || !(beta >= 0.)) continue;
      const double s = x.dot(fn[j]), e = s * s;
      if(e < best) {
        best = e;
        kind = 1;
        which = j;
        ca = alpha;
        cb = beta;
      }
    }
    for(int j = 0; j < N; ++j) {
      const double t = xv[j];
      if(!(t > 0.)) continue;
      const double e = (x - t * v[j]).squaredNorm(); // not |x|^2 - t^2, which cancels on the ray
      if(e < best) {
        best = e;
        kind = 2;
        which = j;
        ca = t;
      }
    }
    // A foot within `ray_tolerance` of a boundary ray of its cone is on that ray (on the crease,
    // when the cones there are not coplanar): a query on a sampled crease is not to fall on a face
    // by the error of an exact fit.
    if(kind == 1) {
      const int k = (which + 1) % N;
      const double sine = std::sqrt(1. - f.cn[which] * f.cn[which]), tolerance = ray_tolerance * (1. + std::sqrt(x2));
      if(cb * sine <= tolerance) {
        kind = 2;
        ca = xv[which];
      } else if(ca * sine <= tolerance) {
        kind = 2;
        which = k;
        ca = xv[k];
      }
    }
    V point = V::Zero();
    if(kind == 1) point = ca * v[which] + cb * v[(which + 1) % N];
    else if(kind == 2) point = ca * v[which];

    Closest_point<3> cp;
    cp.point = point;
    if(kind == 1) {
      cp.normal = fn[which];
      coef[which] = ca;
      coef[(which + 1) % N] = cb;
    } else if(kind == 2) {
      coef[which] = ca;
      const int prev = (which + N - 1) % N;
      if(coplanar(prev, which)) {
        cp.normal = fn[which];
      } else {
        cp.is_on_feature = true;
        cp.direction = v[which];
        cp.normal = fn[prev] + fn[which];
      }
    } else {
      // The apex: sum the normals of the distinct faces (a run of coplanar cones is one face).
      // When the faces lie in two planes only, the apex is a point of their crease: its direction
      // is the crease's.
      V sum = V::Zero();
      int first = -1, second = -1;
      bool all_coplanar = true, two_planes = true;
      for(int j = 0; j < N; ++j) {
        if(!ok[j]) continue;
        if(first < 0) first = j;
        else if(!coplanar(first, j)) {
          all_coplanar = false;
          if(second < 0) second = j;
          else if(!coplanar(second, j)) two_planes = false;
        }
        if(!coplanar((j + N - 1) % N, j)) sum += fn[j];
      }
      if(first >= 0 && all_coplanar) {
        cp.normal = fn[first];
      } else {
        cp.is_on_feature = true;
        cp.normal = sum;
        if(second >= 0 && two_planes) {
          const V e = fn[first].cross(fn[second]);
          if(e.norm() > 1e-9) cp.direction = e.normalized();
        }
      }
    }
    const double len = cp.normal.norm();
    if(len > 1e-12) cp.normal /= len;
    else cp.normal = V::UnitZ(); // degenerate fan (e.g. all vectors parallel): any unit normal
    return cp;
  }
};

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_WEDGE_FAN_FUNCTION_SPACE_H
