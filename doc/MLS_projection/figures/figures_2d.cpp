// Data of the 2D figures of the manual (the paper's Figures 1, 2, 4, 5 and 8), written as CSV
// files into the directory given as first argument; the plots are drawn by plot_figures.py.
// Run by scripts/figures. Everything is deterministic (fixed seeds).
//
//   figures_2d OUTDIR
//
// Only the public API of the package is used, except that the energy landscapes evaluate the
// energies of equations 1 and 6 directly, with the package's Weight_function and the
// closest-point projection of Paraboloid_function_space<2>, on a grid of frames.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_2;
namespace MLS = CGAL::MLS;
using V2 = Eigen::Vector2d;

namespace {

const double pi = std::acos(-1.);
std::string out_dir;

std::ofstream open_csv(const std::string& name, const std::string& header) {
  std::ofstream f(out_dir + "/" + name);
  if(!f) {
    std::cerr << "cannot write " << out_dir << "/" << name << std::endl;
    std::exit(EXIT_FAILURE);
  }
  f << std::setprecision(10) << header << "\n";
  return f;
}

V2 eig(const Point& p) { return V2(p.x(), p.y()); }

// A 2D wedge: apex at the origin, bisector +y, opening angle phi; rays of length L sampled
// every s (the apex included).
struct Wedge {
  double phi, s, L;
  V2 ray(int side) const { return V2(side * std::sin(phi / 2), std::cos(phi / 2)); }
  std::vector<Point> sample() const {
    std::vector<Point> pts{Point(0, 0)};
    for(int i = 1; i * s <= L + 1e-12; ++i)
      for(int side : {-1, 1}) pts.emplace_back(i * s * ray(side)[0], i * s * ray(side)[1]);
    return pts;
  }
  double distance(const V2& x) const {
    double d = x.norm();
    for(int side : {-1, 1}) {
      const double t = x.dot(ray(side));
      if(t > 0) d = std::min(d, (x - std::min(t, L) * ray(side)).norm());
    }
    return d;
  }
  // The largest parameter along the rays of the closest point of x (to skip queries near the ends).
  double foot(const V2& x) const { return std::max(0., std::max(x.dot(ray(-1)), x.dot(ray(1)))); }
};

MLS::Projection_options wendland() {
  MLS::Projection_options o;
  o.weight = MLS::Weight_kind::WENDLAND;
  return o;
}

// theta in [-pi/2, pi/2] of a unit normal n: the angle from (0, 1), n flipped to n.y >= 0.
double angle_from_up(V2 n) {
  if(n[1] < 0 || (n[1] == 0 && n[0] < 0)) n = -n;
  return std::atan2(n[0], n[1]);
}

// ---------------------------------------------------------------------------------------------
// Figure 2: energy landscapes over the frames (theta, rho): normal n = (sin theta, cos theta),
// origin q = rho n (the wedge's apex, which is the query r, is at the origin).

struct Landscape_setup {
  std::vector<V2> p;
  MLS::Weight_function w;
  double h;
};

// Equation 1: weighted mean squared distance to the line through q with normal n, weights at q.
double energy_levin(const Landscape_setup& s, const V2& n, const V2& q) {
  double num = 0, den = 0;
  for(const V2& p : s.p) {
    const double wi = s.w((p - q).squaredNorm());
    const double z = (p - q).dot(n);
    num += wi * z * z;
    den += wi;
  }
  return den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN();
}

// Equation 6 for one member f(x) = k x^2 of Paraboloid_function_space<2> over the frame (n, q):
// closest-point residuals, weights at C_{H,f}(r), r = the origin.
double energy_unified(const Landscape_setup& s, const V2& n, const V2& q, double k) {
  const MLS::Paraboloid_function_space<2> space;
  MLS::Paraboloid_function_space<2>::Parameters c;
  c[0] = k;
  const V2 t(n[1], -n[0]); // tangent
  const auto local = [&](const V2& x) { return V2((x - q).dot(t), (x - q).dot(n)); };
  const MLS::Closest_point<2> cr = space.closest_point(c, local(V2(0, 0)));
  double num = 0, den = 0;
  for(const V2& p : s.p) {
    const V2 lp = local(p);
    const double wi = s.w((lp - cr.point).squaredNorm());
    if(wi == 0) continue;
    const double d = space.closest_point(c, lp).signed_distance;
    num += wi * d * d;
    den += wi;
  }
  return den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN();
}

// min over k in [-4/h, 4/h] (curvature 2|k| up to 8/h, the bound of the space's regulariser):
// a scan, then golden-section refinement around the best value.
double energy_unified_min(const Landscape_setup& s, const V2& n, const V2& q, double& best_k) {
  const double kmax = 4. / s.h;
  const int m = 128;
  double best = std::numeric_limits<double>::infinity();
  int ib = -1;
  std::vector<double> e(m + 1);
  for(int i = 0; i <= m; ++i) {
    e[i] = energy_unified(s, n, q, -kmax + 2 * kmax * i / m);
    if(e[i] < best) best = e[i], ib = i;
  }
  if(ib < 0) return std::numeric_limits<double>::quiet_NaN();
  double a = -kmax + 2 * kmax * std::max(0, ib - 1) / m, b = -kmax + 2 * kmax * std::min(m, ib + 1) / m;
  const double g = (std::sqrt(5.) - 1) / 2;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = energy_unified(s, n, q, x1), f2 = energy_unified(s, n, q, x2);
  for(int it = 0; it < 40; ++it) {
    if(f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = energy_unified(s, n, q, x1);
    else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = energy_unified(s, n, q, x2);
  }
  best_k = -kmax + 2 * kmax * ib / m;
  if(std::min(f1, f2) < best) best = std::min(f1, f2), best_k = (f1 < f2) ? x1 : x2;
  return best;
}

void landscapes() {
  auto grid = open_csv("landscape_grid.csv", "phi_deg,theta,rho_over_h,energy_levin_over_h2,energy_unified_over_h2");
  auto minima = open_csv("landscape_minima.csv",
                         "phi_deg,h,grid_theta_L,grid_rho_L,grid_theta_U,grid_rho_U,lib_theta_L,lib_rho_L,lib_theta_U,lib_rho_U,"
                         "lib_energy_L_over_h2,lib_energy_U_over_h2,lib_tangential_U_over_h");
  for(const double phi_deg : {25., 45., 66., 90., 120.}) {
    const Wedge wedge{phi_deg * pi / 180, 0.01, 1.};
    const auto pts = wedge.sample();
    // Default options (Gaussian weight truncated at 4h, h from the 6th neighbours), as in the
    // manual's measurement of the switch.
    const MLS::Levin_projection<K, MLS::Plane_function_space<2>> PL(pts);
    const MLS::Unified_projection<K, MLS::Paraboloid_function_space<2>> PU(PL.shared_samples());
    const double h = PL.bandwidth();
    Landscape_setup s{{}, MLS::Weight_function(MLS::Weight_kind::GAUSSIAN, h), h};
    for(const Point& p : pts)
      if(eig(p).norm() < 12 * h) s.p.push_back(eig(p)); // the rest has zero weight on the grid
    const int nt = 121, nr = 81;
    const double rmax = 3.;
    double bestL = HUGE_VAL, bestU = HUGE_VAL, tL = 0, rL = 0, tU = 0, rU = 0;
    for(int i = 0; i < nt; ++i) {
      const double theta = -pi / 2 + pi * i / (nt - 1);
      const V2 n(std::sin(theta), std::cos(theta));
      for(int j = 0; j < nr; ++j) {
        const double rho = -rmax + 2 * rmax * j / (nr - 1);
        const V2 q = rho * h * n;
        double k;
        const double eL = energy_levin(s, n, q) / (h * h);
        const double eU = energy_unified_min(s, n, q, k) / (h * h);
        grid << phi_deg << "," << theta << "," << rho << "," << eL << "," << eU << "\n";
        if(eL < bestL) bestL = eL, tL = theta, rL = rho;
        if(eU < bestU) bestU = eU, tU = theta, rU = rho;
      }
    }
    // What the library's optimisers find when projecting the apex.
    const auto rl = PL.project(Point(0, 0));
    const auto ru = PU.project(Point(0, 0));
    const auto frame_coords = [&](const auto& res, double& theta, double& rho) {
      V2 n = eig(CGAL::ORIGIN + res.frame.normal);
      theta = angle_from_up(n);
      if(n[1] < 0 || (n[1] == 0 && n[0] < 0)) n = -n;
      rho = eig(res.frame.origin).dot(n) / h;
    };
    double ltL, lrL, ltU, lrU;
    frame_coords(rl, ltL, lrL);
    frame_coords(ru, ltU, lrU);
    // The library's P_U moves the frame origin freely: its offset along the frame's tangent
    // (zero on the slice q = rho n of the landscape).
    const V2 nU = eig(CGAL::ORIGIN + ru.frame.normal);
    const double tangential = eig(ru.frame.origin).dot(V2(nU[1], -nU[0])) / h;
    minima << phi_deg << "," << h << "," << tL << "," << rL << "," << tU << "," << rU << "," << ltL << "," << lrL << ","
           << ltU << "," << lrU << "," << rl.energy / (h * h) << "," << ru.energy / (h * h) << "," << tangential
           << "\n";
    std::cout << "landscape phi=" << phi_deg << " h=" << h << ": grid minimum P_L (theta, rho/h) = (" << tL << ", "
              << rL << "), P_U quadratic (" << tU << ", " << rU << "); library P_L frame (" << ltL << ", " << lrL
              << "), P_U (" << ltU << ", " << lrU << ")" << std::endl;
  }
}

// The switch of Levin's frame at the apex (section "Levin's Frame at a Wedge Apex"): |n . b| of
// the frame normal with the bisector b = (0, 1), for opening angles 20..170 degrees, and the same
// for P_U with the quadratic space.
void switch_sweep() {
  auto f = open_csv("levin_switch.csv", "phi_deg,levin_alignment,unified_quadratic_alignment");
  double last_low = -1, first_high = -1;
  for(double phi_deg = 20; phi_deg <= 170 + 1e-9; phi_deg += 0.5) {
    const Wedge wedge{phi_deg * pi / 180, 0.01, 1.};
    const MLS::Levin_projection<K, MLS::Plane_function_space<2>> PL(wedge.sample());
    const MLS::Unified_projection<K, MLS::Paraboloid_function_space<2>> PU(PL.shared_samples());
    const auto rl = PL.project(Point(0, 0));
    const auto ru = PU.project(Point(0, 0));
    const double aL = std::abs(rl.frame.normal.y()), aU = std::abs(ru.frame.normal.y());
    f << phi_deg << "," << aL << "," << aU << "\n";
    if(aL < 0.5) last_low = phi_deg;
    if(aL >= 0.5 && first_high < 0) first_high = phi_deg;
  }
  std::cout << "Levin frame at the apex: normal along the bisector's orthogonal (frame = bisector) up to "
            << last_low << " degrees, normal along the bisector from " << first_high << " degrees" << std::endl;
}

// ---------------------------------------------------------------------------------------------
// Figures 1 and 5: reconstructions, i.e. projections of queries, with the paths query -> projection.

// Writes, per query: the operator, the query set, the query, its projection, the status, whether
// the projection is on a feature, and the distance of the projection to the true curve.
template <class Projection, class Distance>
void project_all(std::ofstream& f, const std::string& op, const Projection& P, const std::vector<V2>& queries,
                 const std::string& set, const Distance& distance) {
  for(const V2& x : queries) {
    const auto r = P.project(Point(x[0], x[1]));
    f << op << "," << set << "," << x[0] << "," << x[1] << "," << r.point.x() << "," << r.point.y() << ","
      << int(r.is_success()) << "," << int(r.is_on_feature) << "," << distance(eig(r.point)) << ","
      << MLS::to_string(r.status) << "\n";
  }
}

void wedge_reconstruction() {
  const Wedge wedge{50 * pi / 180, 0.02, 1.};
  const auto pts = wedge.sample();
  const auto o = wendland();
  const MLS::Levin_projection<K, MLS::Polynomial_function_space<2>> PL(pts, o);
  const MLS::Unified_projection<K, MLS::Paraboloid_function_space<2>> PQ(PL.shared_samples(), o);
  const MLS::Unified_projection<K, MLS::Wedge_fan_function_space<2>> PW(PL.shared_samples(), o);
  const double h = PL.bandwidth();
  auto samples = open_csv("wedge_samples.csv", "x,y,h");
  for(const Point& p : pts) samples << p.x() << "," << p.y() << "," << h << "\n";
  // Queries: a grid of spacing h/2 in the band of half-width 1.5h around the wedge, along the
  // first 0.8 of the rays.
  std::vector<V2> queries;
  const double step = h / 2;
  for(double x = -0.6; x <= 0.6; x += step)
    for(double y = -0.3; y <= 1.0; y += step) {
      const V2 q(x, y);
      if(wedge.distance(q) <= 1.5 * h && wedge.foot(q) <= 0.8) queries.push_back(q);
    }
  auto f = open_csv("wedge_projections.csv", "operator,set,qx,qy,px,py,success,on_feature,distance,status");
  const auto dist = [&](const V2& x) { return wedge.distance(x); };
  project_all(f, "PL_quadratic", PL, queries, "grid", dist);
  project_all(f, "PU_quadratic", PQ, queries, "grid", dist);
  project_all(f, "PU_wedge", PW, queries, "grid", dist);
  std::cout << "wedge reconstruction: 50 degrees, spacing 0.02, h=" << h << ", " << queries.size() << " queries"
            << std::endl;
}

// A lens: two circular arcs of radius 1 centred at (0, -c) (upper arc) and (0, c) (lower arc),
// meeting at the corners (+-sqrt(1 - c^2), 0).
struct Lens {
  double c = 0.6;
  double xc() const { return std::sqrt(1 - c * c); }
  double half_angle() const { return std::asin(xc()); } // half the angular extent of an arc
  double corner_angle_deg() const { return 180. - 2. * std::acos(c) * 180. / pi; }
  // The point at parameter u in [0, 1): the upper arc for u < 0.5, left to right, then the lower.
  V2 point(double u, V2* normal = nullptr) const {
    const double a = half_angle();
    const bool upper = u < 0.5;
    const double t = upper ? 2 * u : 2 * u - 1;
    const double ang = upper ? (pi / 2 + a - 2 * a * t) : (-pi / 2 - a + 2 * a * t);
    const V2 centre(0, upper ? -c : c);
    const V2 d(std::cos(ang), std::sin(ang));
    if(normal) *normal = d;
    return centre + d;
  }
  double distance(const V2& x) const {
    double d = HUGE_VAL;
    for(int side : {1, -1}) { // upper arc: centre (0, -c), points with y >= 0
      const V2 centre(0, -side * c);
      const V2 v = x - centre;
      const double ang = std::atan2(v[1], v[0]);
      const double mid = side * pi / 2;
      double diff = std::remainder(ang - mid, 2 * pi);
      if(std::abs(diff) <= half_angle()) d = std::min(d, std::abs(v.norm() - 1));
    }
    for(int sx : {-1, 1}) d = std::min(d, (x - V2(sx * xc(), 0)).norm());
    return d;
  }
};

void noisy_curve_reconstruction() {
  const Lens lens;
  std::mt19937 gen(2026);
  std::uniform_real_distribution<double> uni(0, 1);
  std::normal_distribution<double> noise(0, 0.01);
  // Irregular sampling: 300 parameters drawn with a density varying by a factor 4.4 along the
  // curve (u = v + 0.05 sin(4 pi v) with v uniform: du/dv in [0.37, 1.63]), Gaussian noise
  // sigma = 0.01 in each coordinate.
  std::vector<Point> pts;
  std::vector<V2> samples;
  for(int i = 0; i < 300; ++i) {
    const double v = uni(gen);
    double u = v + 0.05 * std::sin(4 * pi * v);
    u -= std::floor(u);
    const V2 p = lens.point(u) + V2(noise(gen), noise(gen));
    pts.emplace_back(p[0], p[1]);
    samples.push_back(p);
  }
  // The bandwidth: the default (from the 6th neighbours, about 0.04 here) is only 4 times the
  // noise; 0.08 (about 4 mean spacings, 8 sigma) averages the noise, as the manual advises for
  // noisy input.
  auto o = wendland();
  o.bandwidth = 0.08;
  const MLS::Levin_projection<K, MLS::Polynomial_function_space<2>> PL(pts, o);
  const MLS::Unified_projection<K, MLS::Paraboloid_function_space<2>> PQ(PL.shared_samples(), o);
  const MLS::Unified_projection<K, MLS::Wedge_fan_function_space<2>> PW(PL.shared_samples(), o);
  const double h = PL.bandwidth();
  auto sf = open_csv("curve_samples.csv", "x,y,h,corner_angle_deg");
  for(const V2& p : samples) sf << p[0] << "," << p[1] << "," << h << "," << lens.corner_angle_deg() << "\n";
  // Queries: the samples themselves, and 400 regular points of the true curve moved by +-h/2
  // along its normal (alternately), which trace the reconstructed curve.
  std::vector<V2> band;
  for(int i = 0; i < 400; ++i) {
    V2 n;
    const V2 p = lens.point((i + 0.5) / 400, &n);
    band.push_back(p + ((i % 2 == 0) ? 0.5 : -0.5) * h * n);
  }
  auto f = open_csv("curve_projections.csv", "operator,set,qx,qy,px,py,success,on_feature,distance,status");
  const auto dist = [&](const V2& x) { return lens.distance(x); };
  project_all(f, "PL_quadratic", PL, samples, "samples", dist);
  project_all(f, "PU_quadratic", PQ, samples, "samples", dist);
  project_all(f, "PU_wedge", PW, samples, "samples", dist);
  project_all(f, "PL_quadratic", PL, band, "band", dist);
  project_all(f, "PU_quadratic", PQ, band, "band", dist);
  project_all(f, "PU_wedge", PW, band, "band", dist);
  // The true curve, for the plots and the distances computed by the plotting script.
  auto tf = open_csv("curve_true.csv", "x,y");
  for(int i = 0; i <= 2000; ++i) {
    const V2 p = lens.point(std::min(i / 2000., 1 - 1e-12));
    tf << p[0] << "," << p[1] << "\n";
  }
  std::cout << "noisy curve: 300 samples, sigma 0.01, corner angle " << lens.corner_angle_deg() << " deg, h=" << h
            << std::endl;
}

// ---------------------------------------------------------------------------------------------
// Figure 4: the region of queries that P_U (wedge) projects onto the apex.

void collapse_region() {
  auto f = open_csv("collapse_region.csv", "phi_deg,h,qx_over_h,qy_over_h,px_over_h,py_over_h,success,on_feature,in_cone");
  for(const double phi_deg : {90., 60.}) {
    const Wedge wedge{phi_deg * pi / 180, 0.01, 1.};
    const MLS::Unified_projection<K, MLS::Wedge_fan_function_space<2>> PW(wedge.sample(), wendland());
    const double h = PW.bandwidth();
    const int n = 61;
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j) {
        const V2 x = h * V2(-3 + 6. * i / (n - 1), -3 + 6. * j / (n - 1));
        const auto r = PW.project(Point(x[0], x[1]));
        // The apex is the closest point of the wedge iff x is in the normal cone of the apex:
        // x . ray <= 0 for both rays (up to rounding: grid points on the cone's boundary count).
        const bool in_cone = x.dot(wedge.ray(-1)) <= 1e-12 * h && x.dot(wedge.ray(1)) <= 1e-12 * h;
        f << phi_deg << "," << h << "," << x[0] / h << "," << x[1] / h << "," << r.point.x() / h << ","
          << r.point.y() / h << "," << int(r.is_success()) << "," << int(r.is_on_feature) << "," << int(in_cone)
          << "\n";
      }
    std::cout << "collapse region: phi=" << phi_deg << " h=" << h << std::endl;
  }
}

// ---------------------------------------------------------------------------------------------
// Figure 8: completion of a gap, with a smooth prior (quadratic space) and a wedge prior.

void gap_completion() {
  // A noiseless 70-degree wedge sampled every 0.01 on rays of length 1, without the samples within
  // 0.1 of the apex (a gap of 0.2 around the corner); h = 0.07 (Gaussian weight truncated at 4h),
  // so that the neighbourhoods of the gap reach the data on both rays.
  const Wedge wedge{70 * pi / 180, 0.01, 1.};
  const double gap = 0.1;
  std::vector<Point> pts;
  for(const Point& p : wedge.sample())
    if(eig(p).norm() > gap) pts.push_back(p);
  MLS::Projection_options o;
  o.bandwidth = 0.07;
  const MLS::Unified_projection<K, MLS::Paraboloid_function_space<2>> PQ(pts, o);
  const MLS::Unified_projection<K, MLS::Wedge_fan_function_space<2>> PW(PQ.shared_samples(), o);
  const double h = PQ.bandwidth();
  auto samples = open_csv("gap_samples.csv", "x,y,h,gap");
  for(const Point& p : pts) samples << p.x() << "," << p.y() << "," << h << "," << gap << "\n";
  // Queries: a grid of spacing h/4 within h of the wedge, up to 0.35 along the rays; and the
  // bisector from 1.5h below to 1.5h above the apex, where the reconstruction crosses it.
  std::vector<V2> grid, bisector;
  for(double x = -0.3; x <= 0.3; x += h / 4)
    for(double y = -0.1; y <= 0.35; y += h / 4) {
      const V2 q(x, y);
      if(wedge.distance(q) <= h && wedge.foot(q) <= 0.35) grid.push_back(q);
    }
  for(int i = 0; i <= 30; ++i) bisector.push_back(V2(0, h * (-1.5 + 3. * i / 30)));
  auto f = open_csv("gap_projections.csv", "operator,set,qx,qy,px,py,success,on_feature,distance,status");
  const auto dist = [&](const V2& x) { return wedge.distance(x); };
  project_all(f, "PU_quadratic", PQ, grid, "grid", dist);
  project_all(f, "PU_wedge", PW, grid, "grid", dist);
  project_all(f, "PU_quadratic", PQ, bisector, "bisector", dist);
  project_all(f, "PU_wedge", PW, bisector, "bisector", dist);
  std::cout << "gap completion: 70 degrees, spacing 0.01, gap radius " << gap << ", h=" << h << ", " << grid.size()
            << " queries" << std::endl;
}

} // namespace

int main(int argc, char** argv) {
  if(argc != 2) {
    std::cerr << "usage: figures_2d OUTDIR" << std::endl;
    return EXIT_FAILURE;
  }
  out_dir = argv[1];
  const std::string only = std::getenv("MLS_FIGURES_ONLY") ? std::getenv("MLS_FIGURES_ONLY") : "";
  const auto want = [&](const char* name) { return only.empty() || only.find(name) != std::string::npos; };
  if(want("switch")) switch_sweep();
  if(want("landscape")) landscapes();
  if(want("wedge")) wedge_reconstruction();
  if(want("curve")) noisy_curve_reconstruction();
  if(want("collapse")) collapse_region();
  if(want("gap")) gap_completion();
  return EXIT_SUCCESS;
}
