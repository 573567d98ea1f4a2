// libFuzzer harness of the projection operators: random small point sets (0 to 48 points, in 2D
// or 3D, at random scales and offsets, with duplicates, near-degenerate sets, NaN, inf and huge
// coordinates), random options (k, h, weight) and random queries, through Levin_projection
// (polynomial and plane spaces), Unified_projection (quadratic and wedge-fan spaces) and
// Mixed_projection.
//
// Properties checked on every query (the contract of Projection_result): project() does not
// throw; the normal and the energy are finite; the point is finite when the query is; a failure
// keeps the query with a null normal; a success has a unit normal; a NaN or infinite query gives
// INVALID_QUERY. A violation aborts with a message (a finding), as do crashes, sanitizer reports
// and hangs (libFuzzer's -timeout).
//
// Built only with -DMLS_PROJECTION_BUILD_FUZZERS=ON and clang; see fuzz/README.md.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <vector>

namespace {

using K = CGAL::Simple_cartesian<double>;
namespace MLS = CGAL::MLS;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_projection: %s\n", what.c_str());
  std::abort();
}

/// A coordinate: mostly small integers times a scale (so that duplicates, collinear and coplanar
/// sets are frequent), sometimes a raw double or a special value.
double coordinate(FuzzedDataProvider& in, double scale, double offset) {
  switch(in.ConsumeIntegralInRange<int>(0, 15)) {
  case 0: return std::numeric_limits<double>::quiet_NaN();
  case 1: return in.ConsumeBool() ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  case 2: return in.ConsumeFloatingPoint<double>();
  case 3: return in.ConsumeBool() ? 1e300 : -1e300;
  default: return offset + scale * in.ConsumeIntegralInRange<int>(-8, 8);
  }
}

template <int D> struct Types;
template <> struct Types<2> {
  using Point = K::Point_2;
  static Point make(const double* c) { return Point(c[0], c[1]); }
  static bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }
  static double norm(const K::Vector_2& v) { return std::sqrt(v.squared_length()); }
  static bool finite(const K::Vector_2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }
};
template <> struct Types<3> {
  using Point = K::Point_3;
  static Point make(const double* c) { return Point(c[0], c[1], c[2]); }
  static bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }
  static double norm(const K::Vector_3& v) { return std::sqrt(v.squared_length()); }
  static bool finite(const K::Vector_3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
};

template <class Op>
void run(FuzzedDataProvider& in, const char* name) {
  constexpr int D = Op::dimension;
  using T = Types<D>;
  // scale 2^-40 .. 2^40, offset 0 or up to +-1e7
  const double scale = std::ldexp(1., in.ConsumeIntegralInRange<int>(-40, 40));
  const double offset = in.ConsumeBool() ? 0. : in.ConsumeIntegralInRange<int>(-10000, 10000) * 1000.;
  const int n = in.ConsumeIntegralInRange<int>(0, 48);
  std::vector<typename T::Point> points;
  double c[3];
  for(int i = 0; i < n; ++i) {
    for(int k = 0; k < D; ++k) c[k] = coordinate(in, scale, offset);
    points.push_back(T::make(c));
  }
  MLS::Projection_options options;
  options.k = in.ConsumeIntegralInRange<int>(0, 64);
  switch(in.ConsumeIntegralInRange<int>(0, 3)) {
  case 0: options.bandwidth = 0; break;
  case 1: options.bandwidth = scale * in.ConsumeIntegralInRange<int>(1, 64) / 8.; break;
  case 2: options.bandwidth = in.ConsumeFloatingPoint<double>(); break;
  default: options.bandwidth = std::ldexp(1., in.ConsumeIntegralInRange<int>(-60, 60)); break;
  }
  options.weight = in.ConsumeBool() ? MLS::Weight_kind::GAUSSIAN : MLS::Weight_kind::WENDLAND;
  const Op op(points, options);
  const int queries = in.ConsumeIntegralInRange<int>(1, 4);
  for(int j = 0; j < queries; ++j) {
    for(int k = 0; k < D; ++k) c[k] = coordinate(in, scale, offset);
    const typename T::Point q = T::make(c);
    typename Op::Result r;
    try {
      r = op.project(q);
    } catch(const std::exception& e) {
      finding(std::string(name) + ": project() threw " + e.what());
    }
    const std::string what = std::string(name) + " (" + MLS::to_string(r.status) + "): ";
    if(!T::finite(r.normal)) finding(what + "non-finite normal");
    if(!std::isfinite(r.energy)) finding(what + "non-finite energy");
    if(T::finite(q) && !T::finite(r.point)) finding(what + "non-finite point for a finite query");
    if(!T::finite(q) && r.status != MLS::Projection_status::INVALID_QUERY) finding(what + "a non-finite query");
    if(r.is_success() && !(std::abs(T::norm(r.normal) - 1) < 1e-9)) finding(what + "non-unit normal");
    if(!r.is_success() && T::finite(q) && !(r.point == q)) finding(what + "a failure moved the query");
    if(!r.is_success() && T::norm(r.normal) != 0) finding(what + "a failure with a non-null normal");
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  switch(in.ConsumeIntegralInRange<int>(0, 7)) {
  case 0: run<MLS::Levin_projection<K, MLS::Polynomial_function_space<3>>>(in, "levin quadratic 3D"); break;
  case 1: run<MLS::Levin_projection<K, MLS::Plane_function_space<3>>>(in, "levin plane 3D"); break;
  case 2: run<MLS::Unified_projection<K, MLS::Paraboloid_function_space<3>>>(in, "unified quadratic 3D"); break;
  case 3: run<MLS::Unified_projection<K, MLS::Wedge_fan_function_space<3>>>(in, "unified wedge 3D"); break;
  case 4: run<MLS::Mixed_projection<K, 3>>(in, "mixed 3D"); break;
  case 5: run<MLS::Levin_projection<K, MLS::Polynomial_function_space<2>>>(in, "levin quadratic 2D"); break;
  case 6: run<MLS::Unified_projection<K, MLS::Wedge_fan_function_space<2>>>(in, "unified wedge 2D"); break;
  default: run<MLS::Mixed_projection<K, 2>>(in, "mixed 2D"); break;
  }
  return 0;
}
