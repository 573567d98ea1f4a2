// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Speed and accuracy of the package's projections next to CGAL's jet smoothing.
//
// Inputs (fixed seeds: the same options give the same points on every machine):
//   - a torus (R = 1, r = 0.35) of n points with isotropic Gaussian noise, for each --sizes n;
//   - a cube [-0.5, 0.5]^3 sampled uniformly on its faces (--cube points), noiseless and with
//     Gaussian noise of --cube-noise times the bandwidth h of the noiseless sample: the sharp
//     edges and corners, where the wedge-fan space is exact and the quadratic ones round off;
//   - with --solid S, mls_mesh's built-in solid (a box with a cylindrical bore and a rounded
//     edge: planes, cylinders, 15 sharp edges) sampled at spacing S, noiseless and noisy
//     (--solid-noise): a CAD part with curved patches, to choose the tools' default space.
// On each input, table 1 (every input point projected):
//   - P_L quadratic: Levin_projection<Epick, Polynomial_function_space<3>> (default options),
//   - P_L plane:     Levin_projection<Epick, Plane_function_space<3>>      (default options),
//     each timed as "build" (sample set: copy + kd-tree, and the bandwidth) and "project"
//     (project_points<Parallel_if_available_tag> of all n input points),
//   - jet: CGAL::jet_smooth_point_set<Parallel_if_available_tag> on a copy of the same points
//     (k = 18 by default, degree 2 fit and 2 Monge; its own kd-tree is inside its time).
// Table 2: the closest-point operators, 10-1000 times slower per query, on a random subset of
// the input points (--subset, fixed seed), with the same function spaces' default options:
//   - P_S:            Single_phase_projection<Epick, Paraboloid_function_space<3>>,
//   - P_E:            Enriched_projection<Epick, Paraboloid_function_space<3>>,
//   - P_U quadratic:  Unified_projection<Epick, Paraboloid_function_space<3>>,
//   - P_U wedge:      Unified_projection<Epick, Wedge_fan_function_space<3>>,
//   - mixed:          Mixed_projection<Epick, 3> (P_U quadratic and P_U wedge, the better kept),
// reported per query, as ratios of CPU time per query to P_L quadratic and to jet measured in
// the same run on the same input (their per-query cost is that of the whole input), and with the
// accuracy of P_L and jet on the same subset for comparison. The queries of a random subset are
// far apart: table 2 projects each one cold (Projection_options::warm_starts = false).
// Table 3 (--warm-operators): project_points of every input point with warm starts (the default:
// queries along a Hilbert curve, each continued from the fit of the one before), the way
// mls_project and the mesher's seeds use the operators, reported per query as ratios to P_L
// quadratic (table 1) and to the same operator's cold queries (table 2) of the same run.
// Distances are to the exact surface. Wall times use std::chrono::steady_clock; the process CPU
// time (getrusage, all threads) is reported next to them.
//
// Usage: bench_projection --help

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/tags.h>

#include <mls_tools/builtin_solid.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#endif

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

constexpr double major_radius = 1.0;
constexpr double minor_radius = 0.35;
constexpr double pi = 3.14159265358979323846;

// Portable deterministic random numbers: the standard distributions are implementation-defined,
// so the uniform and normal variates are derived here from mt19937_64's (specified) output.
class Random {
public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * (1.0 / 9007199254740992.0); } // [0, 1)
  double normal() {
    if(has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0;
    while(u <= 0) u = uniform();
    const double v = uniform();
    const double radius = std::sqrt(-2. * std::log(u));
    spare_ = radius * std::sin(2 * pi * v);
    has_spare_ = true;
    return radius * std::cos(2 * pi * v);
  }
  std::uint64_t raw() { return engine_(); }

private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// n points uniformly distributed (by area) on the torus, plus isotropic Gaussian noise of
// standard deviation `sigma` on each coordinate.
std::vector<Point> sample_torus(std::size_t n, double sigma, std::uint64_t seed) {
  Random rng(seed);
  std::vector<Point> points;
  points.reserve(n);
  while(points.size() < n) {
    const double u = 2 * pi * rng.uniform();
    const double v = 2 * pi * rng.uniform();
    // Area element (R + r cos v): rejection against its maximum R + r.
    if(rng.uniform() * (major_radius + minor_radius) > major_radius + minor_radius * std::cos(v)) continue;
    const double rho = major_radius + minor_radius * std::cos(v);
    const double x = rho * std::cos(u) + sigma * rng.normal();
    const double y = rho * std::sin(u) + sigma * rng.normal();
    const double z = minor_radius * std::sin(v) + sigma * rng.normal();
    points.emplace_back(x, y, z);
  }
  return points;
}

// n points uniformly distributed on the faces of the cube [-0.5, 0.5]^3 (a face chosen
// uniformly, then a uniform point on it), without noise.
std::vector<Point> sample_cube(std::size_t n, std::uint64_t seed) {
  Random rng(seed);
  std::vector<Point> points;
  points.reserve(n);
  while(points.size() < n) {
    const int face = std::min(5, int(6 * rng.uniform()));
    double c[3];
    c[face / 2] = face % 2 == 0 ? -0.5 : 0.5;
    c[(face / 2 + 1) % 3] = rng.uniform() - 0.5;
    c[(face / 2 + 2) % 3] = rng.uniform() - 0.5;
    points.emplace_back(c[0], c[1], c[2]);
  }
  return points;
}

std::vector<Point> add_noise(const std::vector<Point>& points, double sigma, std::uint64_t seed) {
  Random rng(seed);
  std::vector<Point> noisy;
  noisy.reserve(points.size());
  for(const Point& p : points) {
    const double x = p.x() + sigma * rng.normal();
    const double y = p.y() + sigma * rng.normal();
    const double z = p.z() + sigma * rng.normal();
    noisy.emplace_back(x, y, z);
  }
  return noisy;
}

enum class Shape { TORUS, CUBE, SOLID };

double distance_to_torus(const Point& p) {
  const double rho = std::hypot(p.x(), p.y());
  return std::abs(std::hypot(rho - major_radius, p.z()) - minor_radius);
}

// Unsigned distance to the surface of the cube [-0.5, 0.5]^3.
double distance_to_cube(const Point& p) {
  const double q[3] = {std::abs(p.x()) - 0.5, std::abs(p.y()) - 0.5, std::abs(p.z()) - 0.5};
  double outside = 0;
  for(const double c : q) outside += c > 0 ? c * c : 0;
  if(outside > 0) return std::sqrt(outside);
  return std::abs((std::max)({q[0], q[1], q[2]}));
}

// Distance to the nearest of the cube's 12 edges.
double distance_to_cube_edge(const Point& p) {
  const double a[3] = {std::abs(p.x()) - 0.5, std::abs(p.y()) - 0.5, std::abs(p.z()) - 0.5};
  double best = std::numeric_limits<double>::infinity();
  for(int along = 0; along < 3; ++along) {
    const int i = (along + 1) % 3, j = (along + 2) % 3;
    const double beyond = (std::max)(a[along], 0.);
    best = (std::min)(best, std::sqrt(a[i] * a[i] + a[j] * a[j] + beyond * beyond));
  }
  return best;
}

// The tools' built-in solid (a box with a bore and a rounded edge): exact distance, and the
// distance to its true sharp edges (polylines sampled every 0.002: exact to 1e-6).
struct Solid {
  mls_tools::Bored_filleted_box shape;
  std::vector<Point> edge_points;
  Solid() {
    for(const auto& polyline : shape.sharp_edges(0.002))
      for(const auto& v : polyline) edge_points.emplace_back(v[0], v[1], v[2]);
  }
  double distance(const Point& p) const { return std::abs(shape.signed_distance({p.x(), p.y(), p.z()})); }
  double edge_distance(const Point& p) const {
    double best = std::numeric_limits<double>::infinity();
    for(const Point& e : edge_points) best = (std::min)(best, CGAL::squared_distance(p, e));
    return std::sqrt(best);
  }
};

struct Input {
  std::string name;
  Shape shape = Shape::TORUS;
  std::vector<Point> points;
  double noise = 0;
  std::shared_ptr<const Solid> solid; // Shape::SOLID
  double distance(const Point& p) const {
    return shape == Shape::TORUS ? distance_to_torus(p) : shape == Shape::CUBE ? distance_to_cube(p) : solid->distance(p);
  }
  // Queries "near a feature" (within 2h of a sharp edge) get their own accuracy column.
  bool near_feature(const Point& p, double h) const {
    return (shape == Shape::CUBE && distance_to_cube_edge(p) < 2 * h) || (shape == Shape::SOLID && solid->edge_distance(p) < 2 * h);
  }
};

struct Accuracy {
  double mean = 0, p99 = 0, max = 0;
  double feature_mean = -1, feature_max = -1; // over the queries near a feature (-1: none)
  std::size_t feature_count = 0;
};

// Accuracy of outputs[i], the projection of queries[i].
Accuracy accuracy(const Input& input, const std::vector<Point>& queries, const std::vector<Point>& outputs, double h) {
  Accuracy a;
  std::vector<double> d;
  double feature_sum = 0, feature_max = 0;
  for(std::size_t i = 0; i < outputs.size(); ++i) {
    d.push_back(input.distance(outputs[i]));
    if(h > 0 && input.near_feature(queries[i], h)) {
      ++a.feature_count;
      feature_sum += d.back();
      feature_max = (std::max)(feature_max, d.back());
    }
  }
  if(d.empty()) return a;
  for(const double x : d) a.mean += x;
  a.mean /= double(d.size());
  a.max = *std::max_element(d.begin(), d.end());
  const auto q = d.begin() + std::ptrdiff_t(0.99 * double(d.size() - 1));
  std::nth_element(d.begin(), q, d.end());
  a.p99 = *q;
  if(a.feature_count > 0) {
    a.feature_mean = feature_sum / double(a.feature_count);
    a.feature_max = feature_max;
  }
  return a;
}

double peak_rss_mb() {
  rusage usage{};
  if(getrusage(RUSAGE_SELF, &usage) != 0) return -1;
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

// User + system CPU time of the whole process (all threads), in seconds. Unlike wall time it
// hardly changes when other processes share the cores.
double process_cpu_seconds() {
  rusage usage{};
  if(getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  const auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return s(usage.ru_utime) + s(usage.ru_stime);
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One operator on one input: every input point (table 1) or a subset (table 2).
struct Row {
  std::string input;
  std::size_t n = 0;
  std::string method;
  std::size_t queries = 0;
  double build = -1, project = -1; // wall seconds; -1: not applicable
  double cpu = -1;                 // process CPU seconds of build + project
  double project_cpu = -1;         // process CPU seconds of project alone
  double jet = -1, jet_cpu = -1;   // the jet times of the same input, for the ratios
  double levin_cpu_per_query = -1, jet_cpu_per_query = -1; // table 2's references
  double cold_cpu_per_query = -1; // table 3: the same operator's table-2 CPU time per query
  Accuracy error;
  std::size_t failures = 0, not_converged = 0, on_feature = 0;
  bool has_status = false;
  double mean_neighbors = -1;
  double peak_rss = -1;
  std::vector<Point> outputs; // in query order (table 1: every input point)
};

std::string fixed(double x, int digits) {
  if(x < 0) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}
std::string scientific(double x) {
  if(x < 0) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

void print_cells(const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& cells,
                 std::size_t left_columns, bool markdown) {
  std::vector<std::size_t> width(head.size());
  for(std::size_t j = 0; j < head.size(); ++j) {
    width[j] = head[j].size();
    for(const auto& c : cells) width[j] = (std::max)(width[j], c[j].size());
  }
  const auto left = [&](std::size_t j) { return j < left_columns && j != 1; }; // column 1 is n
  const auto line = [&](const std::vector<std::string>& c) {
    std::ostringstream os;
    if(markdown) os << "| ";
    for(std::size_t j = 0; j < c.size(); ++j) {
      const std::string pad(width[j] - c[j].size(), ' ');
      os << (left(j) ? c[j] + pad : pad + c[j]) << (markdown ? " | " : "  ");
    }
    std::string s = os.str();
    while(!s.empty() && s.back() == ' ') s.pop_back();
    std::cout << s << "\n";
  };
  line(head);
  if(markdown) {
    std::vector<std::string> rule;
    for(std::size_t j = 0; j < head.size(); ++j) rule.push_back(std::string(width[j] - 1, '-') + (left(j) ? "-" : ":"));
    line(rule);
  }
  for(const auto& c : cells) line(c);
}

void print_full_table(const std::vector<Row>& rows, bool markdown) {
  const std::vector<std::string> head = {"input",     "n",        "method",    "build s",  "project s",
                                         "total s",   "total/jet", "cpu s",    "cpu/jet",  "mean dist",
                                         "p99 dist",  "max dist", "edge mean", "failed/not conv", "nbrs",
                                         "peak RSS MB"};
  std::vector<std::vector<std::string>> cells;
  for(const Row& r : rows) {
    const double total = r.build >= 0 ? r.build + r.project : r.project;
    std::string ratio = "-";
    if(total >= 0 && r.jet > 0) ratio = fixed(total / r.jet, 2);
    std::string cpu_ratio = "-";
    if(r.cpu >= 0 && r.jet_cpu > 0) cpu_ratio = fixed(r.cpu / r.jet_cpu, 2);
    cells.push_back({r.input, std::to_string(r.n), r.method, fixed(r.build, 3), fixed(r.project, 3), fixed(total, 3),
                     ratio, fixed(r.cpu, 2), cpu_ratio, scientific(r.error.mean), scientific(r.error.p99),
                     scientific(r.error.max), scientific(r.error.feature_mean),
                     r.has_status ? std::to_string(r.failures) + "/" + std::to_string(r.not_converged) : "-",
                     fixed(r.mean_neighbors, 1), fixed(r.peak_rss, 0)});
  }
  print_cells(head, cells, 3, markdown);
}

void print_subset_table(const std::vector<Row>& rows, bool markdown, bool warm = false) {
  std::vector<std::string> head = {"input",     "n",         "method",    "queries",   "build s",
                                   "cpu ms/q",  "wall ms/q", "cpu/P_L",   "cpu/jet",   "mean dist",
                                   "max dist",  "edge mean", "edge max",  "not conv",  "failed",
                                   "on feature"};
  if(warm) head.insert(head.begin() + 9, "cold/warm");
  std::vector<std::vector<std::string>> cells;
  for(const Row& r : rows) {
    const double q = double(r.queries);
    const double cpu_per_query = r.project_cpu / q;
    std::string to_levin = "-", to_jet = "-";
    if(r.levin_cpu_per_query > 0) to_levin = fixed(cpu_per_query / r.levin_cpu_per_query, 1);
    if(r.jet_cpu_per_query > 0) to_jet = fixed(cpu_per_query / r.jet_cpu_per_query, 1);
    cells.push_back({r.input, std::to_string(r.n), r.method, std::to_string(r.queries), fixed(r.build, 3),
                     fixed(1e3 * cpu_per_query, 3), fixed(1e3 * r.project / q, 3), to_levin, to_jet,
                     scientific(r.error.mean), scientific(r.error.max), scientific(r.error.feature_mean),
                     scientific(r.error.feature_max), r.has_status ? std::to_string(r.not_converged) : "-",
                     r.has_status ? std::to_string(r.failures) : "-",
                     r.has_status ? std::to_string(r.on_feature) : "-"});
    if(warm)
      cells.back().insert(cells.back().begin() + 9,
                          r.cold_cpu_per_query > 0 ? fixed(r.cold_cpu_per_query / cpu_per_query, 1) : std::string("-"));
  }
  print_cells(head, cells, 3, markdown);
}

// Projects `queries` with `projection` (built on `points` by `make`), timed.
template <class Make>
Row run_operator(const Input& input, const std::vector<Point>& queries, const char* method, double h, Make make) {
  Row row;
  row.input = input.name;
  row.n = input.points.size();
  row.method = method;
  row.queries = queries.size();
  row.has_status = true;

  const double cpu_start = process_cpu_seconds();
  auto start = Clock::now();
  const auto projection = make(); // sample set (copy + kd-tree) and bandwidth
  row.build = seconds_since(start);

  using Result = typename std::decay_t<decltype(*projection)>::Result;
  std::vector<Result> results;
  results.reserve(queries.size());
  const double project_cpu_start = process_cpu_seconds();
  start = Clock::now();
  CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(*projection, queries, std::back_inserter(results));
  row.project = seconds_since(start);
  const double cpu_end = process_cpu_seconds();
  row.cpu = cpu_end - cpu_start;
  row.project_cpu = cpu_end - project_cpu_start;

  double neighbors = 0;
  row.outputs.reserve(results.size());
  for(const auto& r : results) {
    if(!r.is_success()) ++row.failures;
    if(r.status == CGAL::MLS::Projection_status::NOT_CONVERGED || r.status == CGAL::MLS::Projection_status::LEVIN_FALLBACK)
      ++row.not_converged; // the table's column counts both
    if(r.is_on_feature) ++row.on_feature;
    neighbors += double(r.number_of_neighbors);
    row.outputs.push_back(r.point); // a failed projection keeps the query point: counted as it is
  }
  row.mean_neighbors = results.empty() ? 0 : neighbors / double(results.size());
  row.error = accuracy(input, queries, row.outputs, h);
  row.peak_rss = peak_rss_mb();
  return row;
}

template <class Projection>
std::function<std::unique_ptr<Projection>()> maker(const std::vector<Point>& points,
                                                   const CGAL::MLS::Projection_options& options = {}) {
  return [&points, options] { return std::make_unique<Projection>(points, options); };
}

Row run_jet(const Input& input, unsigned int k, double h) {
  Row row;
  row.input = input.name;
  row.n = input.points.size();
  row.queries = row.n;
  row.method = "jet k=" + std::to_string(k);
  row.outputs = input.points;
  const double cpu_start = process_cpu_seconds();
  const auto start = Clock::now();
  CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(row.outputs, k);
  row.project = seconds_since(start);
  row.cpu = row.project_cpu = process_cpu_seconds() - cpu_start;
  row.error = accuracy(input, input.points, row.outputs, h);
  row.mean_neighbors = k;
  row.peak_rss = peak_rss_mb();
  return row;
}

// `count` distinct indices of [0, n) drawn with a fixed seed, in increasing order.
std::vector<std::size_t> random_subset(std::size_t n, std::size_t count, std::uint64_t seed) {
  std::vector<std::size_t> all(n);
  for(std::size_t i = 0; i < n; ++i) all[i] = i;
  count = (std::min)(count, n);
  Random rng(seed);
  for(std::size_t i = 0; i < count; ++i) std::swap(all[i], all[i + std::size_t(rng.raw() % (n - i))]);
  all.resize(count);
  std::sort(all.begin(), all.end());
  return all;
}

// A table-1 row's result restricted to the subset, as a table-2 reference row.
Row restricted(const Row& full, const Input& input, const std::vector<std::size_t>& subset,
               const std::vector<Point>& queries, double h) {
  Row row = full;
  row.queries = subset.size();
  row.build = full.build >= 0 ? full.build : -1;
  // Its per-query cost is that of the whole input.
  row.project = full.project * double(subset.size()) / double(full.n);
  row.project_cpu = full.project_cpu * double(subset.size()) / double(full.n);
  std::vector<Point> outputs;
  for(const std::size_t i : subset) outputs.push_back(full.outputs[i]);
  row.error = accuracy(input, queries, outputs, h);
  row.has_status = false;
  row.method = full.method + " (all n)";
  return row;
}

const std::vector<std::string> all_operators = {"single", "enriched", "unified-quadratic", "unified-wedge", "mixed"};

[[noreturn]] void usage(const char* program, const std::string& error) {
  if(!error.empty()) std::cerr << "error: " << error << "\n";
  std::cerr
    << "usage: " << program << " [options]\n"
    << "  --sizes a,b,...     torus sizes (default 50000; 'none': no torus)\n"
    << "  --cube N            points of the sampled cube (default 20000; 0: no cube)\n"
    << "  --cube-noise F      noise of the noisy cube, in units of its h (default 0.02; < 0: no noisy cube)\n"
    << "  --solid S           mls_mesh's built-in solid (box, bore, rounded edge) sampled at spacing S\n"
    << "                      (default 0: none; 0.03 gives about 11800 points), noiseless and noisy\n"
    << "  --solid-noise F     noise of the noisy solid, in units of its h (default 0.02; < 0: none)\n"
    << "  --subset N          queries of the closest-point operators per input (default 300; 0: none)\n"
    << "  --operators a,b,... closest-point operators among single, enriched, unified-quadratic,\n"
    << "                      unified-wedge, mixed (default: all)\n"
    << "  --warm-operators .. the same for table 3, every input point with warm starts\n"
    << "                      (default: unified-wedge,mixed; 'none': no table 3)\n"
    << "  --threads N         threads (default: all cores)\n"
    << "  --jet-k K           neighbours of jet_smooth_point_set (default 18)\n"
    << "  --noise SIGMA       noise of the torus (default 0.005)\n"
    << "  --seed S            seed of the sampling and of the subsets (default 20260101)\n"
    << "  --markdown          Markdown tables\n";
  std::exit(error.empty() ? 0 : 2);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> items;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ',')) items.push_back(item);
  return items;
}

std::vector<std::size_t> parse_sizes(const std::string& s, const char* program) {
  std::vector<std::size_t> sizes;
  if(s == "none") return sizes;
  for(const std::string& item : split(s)) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(item.c_str(), &end, 10);
    if(item.empty() || *end != '\0' || v < 100) usage(program, "bad size '" + item + "' (an integer >= 100)");
    sizes.push_back(std::size_t(v));
  }
  if(sizes.empty()) usage(program, "no size given");
  return sizes;
}

std::size_t parse_count(const std::string& s, const char* program, const std::string& option) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if(s.empty() || *end != '\0' || s[0] == '-') usage(program, "bad value '" + s + "' of " + option);
  return std::size_t(v);
}

// The closest-point operator named `op` (see --operators) on `queries`, with `options`.
Row run_named_operator(const std::string& op, const Input& input, const std::vector<Point>& queries, double h,
                       const CGAL::MLS::Projection_options& options) {
  using namespace CGAL::MLS;
  const std::vector<Point>& points = input.points;
  if(op == "single")
    return run_operator(input, queries, "P_S quadratic", h,
                        maker<Single_phase_projection<Kernel, Paraboloid_function_space<3>>>(points, options));
  if(op == "enriched")
    return run_operator(input, queries, "P_E quadratic", h,
                        maker<Enriched_projection<Kernel, Paraboloid_function_space<3>>>(points, options));
  if(op == "unified-quadratic")
    return run_operator(input, queries, "P_U quadratic", h,
                        maker<Unified_projection<Kernel, Paraboloid_function_space<3>>>(points, options));
  if(op == "unified-wedge")
    return run_operator(input, queries, "P_U wedge", h,
                        maker<Unified_projection<Kernel, Wedge_fan_function_space<3>>>(points, options));
  return run_operator(input, queries, "mixed", h, maker<Mixed_projection<Kernel, 3>>(points, options));
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes = {50000};
  std::size_t cube_size = 20000, subset_size = 300;
  double cube_noise = 0.02; // in units of h
  double solid_spacing = 0, solid_noise = 0.02; // --solid: the built-in solid's sample spacing (0: none)
  std::vector<std::string> operators = all_operators, warm_operators = {"unified-wedge", "mixed"};
  int threads = 0; // 0: all cores
  unsigned int jet_k = 18;
  double noise = 0.005;
  std::uint64_t seed = 20260101;
  bool markdown = false;

  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if(i + 1 >= argc) usage(argv[0], arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--sizes") sizes = parse_sizes(value(), argv[0]);
    else if(arg == "--cube") cube_size = parse_count(value(), argv[0], arg);
    else if(arg == "--cube-noise") cube_noise = std::atof(value().c_str());
    else if(arg == "--solid") solid_spacing = std::atof(value().c_str());
    else if(arg == "--solid-noise") solid_noise = std::atof(value().c_str());
    else if(arg == "--subset") subset_size = parse_count(value(), argv[0], arg);
    else if(arg == "--operators") {
      operators = split(value());
      for(const std::string& o : operators)
        if(std::find(all_operators.begin(), all_operators.end(), o) == all_operators.end())
          usage(argv[0], "unknown operator '" + o + "'");
    }
    else if(arg == "--warm-operators") {
      const std::string v = value();
      warm_operators = v == "none" ? std::vector<std::string>() : split(v);
      for(const std::string& o : warm_operators)
        if(std::find(all_operators.begin(), all_operators.end(), o) == all_operators.end())
          usage(argv[0], "unknown operator '" + o + "'");
    }
    else if(arg == "--threads") threads = std::atoi(value().c_str());
    else if(arg == "--jet-k") jet_k = unsigned(std::atoi(value().c_str()));
    else if(arg == "--noise") noise = std::atof(value().c_str());
    else if(arg == "--seed") seed = std::strtoull(value().c_str(), nullptr, 10);
    else if(arg == "--markdown") markdown = true;
    else if(arg == "--help" || arg == "-h") usage(argv[0], "");
    else usage(argv[0], "unknown argument " + arg);
  }
  if(threads < 0) usage(argv[0], "--threads must be >= 0");
  if(jet_k < 6) usage(argv[0], "--jet-k must be at least 6 (a degree 2 jet needs 6 points)");
  if(!(noise >= 0)) usage(argv[0], "--noise must be >= 0");
  if(cube_size > 0 && cube_size < 100) usage(argv[0], "--cube must be 0 or at least 100");

#ifdef CGAL_LINKED_WITH_TBB
  if(threads == 0) threads = tbb::info::default_concurrency();
  // Caps every TBB algorithm of the process: project_points and jet_smooth_point_set alike.
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  const char* concurrency = "TBB";
#else
  if(threads > 1) std::cerr << "warning: built without TBB, running on 1 thread\n";
  threads = 1;
  const char* concurrency = "sequential (no TBB)";
#endif

  std::vector<Input> inputs;
  for(const std::size_t n : sizes) {
    Input torus;
    torus.name = "torus";
    torus.shape = Shape::TORUS;
    torus.points = sample_torus(n, noise, seed);
    torus.noise = noise;
    inputs.push_back(std::move(torus));
  }
  // A noiseless input, then (noise_in_h >= 0) its copy with Gaussian noise of noise_in_h times
  // the noiseless sample's bandwidth h; returns h.
  const auto add_with_noisy_copy = [&inputs](Input input, double noise_in_h, std::uint64_t noise_seed) {
    const double h = CGAL::MLS::Levin_projection<Kernel>(input.points).bandwidth();
    if(noise_in_h >= 0) {
      Input noisy = input;
      noisy.noise = noise_in_h * h;
      noisy.name += "+noise";
      noisy.points = add_noise(input.points, noisy.noise, noise_seed);
      inputs.push_back(std::move(input));
      inputs.push_back(std::move(noisy));
    } else {
      inputs.push_back(std::move(input));
    }
    return h;
  };
  double cube_h = 0;
  if(cube_size > 0) {
    Input cube;
    cube.name = "cube";
    cube.shape = Shape::CUBE;
    cube.points = sample_cube(cube_size, seed);
    cube_h = add_with_noisy_copy(std::move(cube), cube_noise, seed + 1);
  }
  double solid_h = 0;
  if(solid_spacing > 0) {
    Input solid;
    solid.name = "solid";
    solid.shape = Shape::SOLID;
    solid.solid = std::make_shared<const Solid>();
    for(const auto& p : mls_tools::builtin_solid_points(solid_spacing).points) solid.points.emplace_back(p[0], p[1], p[2]);
    solid_h = add_with_noisy_copy(std::move(solid), solid_noise, seed + 2);
  }

  std::cout << "MLS_projection benchmark: torus R=" << major_radius << " r=" << minor_radius
            << ", isotropic Gaussian noise sigma=" << noise << "; cube [-0.5,0.5]^3, " << cube_size
            << " points uniform on the faces, noiseless (h=" << cube_h << ") and noisy (sigma=" << cube_noise
            << " h=" << cube_noise * cube_h << "); seed " << seed << "\n"
            << "threads: " << threads << " (" << concurrency << "), hardware threads: "
            << std::thread::hardware_concurrency() << "\n"
            << "all operators: default Projection_options; jet: jet_smooth_point_set k=" << jet_k
            << ", degree_fitting=2, degree_monge=2\n"
            << "distances are to the exact surface; 'input' rows are the sample itself\n"
            << std::endl;

  std::vector<Row> full_rows, subset_rows, warm_rows;
  for(const Input& input : inputs) {
    const std::size_t n = input.points.size();
    // "edge mean" uses the noiseless sample's h
    const double h = input.shape == Shape::CUBE ? cube_h : input.shape == Shape::SOLID ? solid_h : 0;
    const std::string tag = input.name + " n=" + std::to_string(n);
    const std::vector<Point> all = input.points;
    Row sample;
    sample.input = input.name;
    sample.n = n;
    sample.method = "input";
    sample.error = accuracy(input, all, all, h);
    sample.peak_rss = peak_rss_mb();

    Row jet = run_jet(input, jet_k, h);
    std::cerr << tag << ": jet done in " << jet.project << " s" << std::endl;
    using Levin_quadratic = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Polynomial_function_space<3>>;
    using Levin_plane = CGAL::MLS::Levin_projection<Kernel, CGAL::MLS::Plane_function_space<3>>;
    Row quadratic = run_operator(input, all, "P_L quadratic", h, maker<Levin_quadratic>(input.points));
    std::cerr << tag << ": P_L quadratic done in " << quadratic.build + quadratic.project << " s" << std::endl;
    Row plane = run_operator(input, all, "P_L plane", h, maker<Levin_plane>(input.points));
    std::cerr << tag << ": P_L plane done in " << plane.build + plane.project << " s" << std::endl;

    jet.jet = quadratic.jet = plane.jet = jet.project;
    jet.jet_cpu = quadratic.jet_cpu = plane.jet_cpu = jet.cpu;
    full_rows.push_back(sample);
    full_rows.push_back(quadratic);
    full_rows.push_back(plane);
    full_rows.push_back(jet);

    if(subset_size == 0 || (operators.empty() && warm_operators.empty())) continue;
    const std::vector<std::size_t> subset = random_subset(n, subset_size, seed + 2);
    std::vector<Point> queries;
    for(const std::size_t i : subset) queries.push_back(input.points[i]);
    const double levin_per_query = quadratic.project_cpu / double(n);
    const double jet_per_query = jet.cpu / double(n);
    Row sample_subset = sample;
    sample_subset.queries = queries.size();
    sample_subset.error = accuracy(input, queries, queries, h);
    sample_subset.project_cpu = -1;
    std::vector<Row> rows = {sample_subset, restricted(quadratic, input, subset, queries, h),
                             restricted(jet, input, subset, queries, h)};
    CGAL::MLS::Projection_options cold;
    cold.warm_starts = false;
    for(const std::string& op : operators) {
      Row row = run_named_operator(op, input, queries, h, cold);
      std::cerr << tag << ": " << row.method << " done in " << row.build + row.project << " s ("
                << 1e3 * row.project_cpu / double(row.queries) << " CPU ms per query)" << std::endl;
      rows.push_back(std::move(row));
    }
    for(const std::string& op : warm_operators) {
      Row row = run_named_operator(op, input, all, h, CGAL::MLS::Projection_options());
      std::cerr << tag << ": " << row.method << " with warm starts done in " << row.build + row.project << " s ("
                << 1e3 * row.project_cpu / double(row.queries) << " CPU ms per query)" << std::endl;
      row.levin_cpu_per_query = levin_per_query;
      row.jet_cpu_per_query = jet_per_query;
      for(const Row& r : rows)
        if(r.method == row.method && r.project_cpu > 0) row.cold_cpu_per_query = r.project_cpu / double(r.queries);
      row.outputs.clear();
      warm_rows.push_back(std::move(row));
    }
    for(Row& r : rows) {
      r.levin_cpu_per_query = levin_per_query;
      r.jet_cpu_per_query = jet_per_query;
      r.outputs.clear();
      subset_rows.push_back(std::move(r));
    }
  }

  std::cout << "\nTable 1: every input point projected\n";
  print_full_table(full_rows, markdown);
  std::cout << "\ntotal = build + project (jet: its whole call, kd-tree included); total/jet = total / jet's total "
               "on the same input.\ncpu s = user + system CPU seconds of the process over the same span (all threads; "
               "robust to other load on the machine); cpu/jet likewise.\ndist = distance to the exact surface (p99: 99th "
               "percentile); edge mean: mean over the queries within 2h of a cube edge.\nfailed = no projection (point "
               "kept), not conv = optimiser hit its limit (point used).\nnbrs = mean number of points with non-zero "
               "weight in the final fit (jet: k).\npeak RSS = getrusage ru_maxrss after the row (the process peak so far, "
               "monotone)."
            << std::endl;
  if(!subset_rows.empty()) {
    std::cout << "\nTable 2: closest-point operators on " << subset_size
              << " random input points per input (P_L and jet: their table-1 outputs at the same points)\n";
    print_subset_table(subset_rows, markdown);
    std::cout << "\ncpu ms/q = CPU milliseconds per query (all threads; P_L and jet: their table-1 project CPU / n, "
                 "jet's kd-tree included); wall ms/q likewise.\ncpu/P_L, cpu/jet = cpu ms/q over that of P_L quadratic "
                 "and of jet on the same input, in the same run.\nedge mean/max: over the queries within 2h of a cube "
                 "edge. not conv: NOT_CONVERGED results (the closest-point operators' fall-back to P_L is counted "
                 "there too); on feature: results on a crease or apex."
              << std::endl;
  }
  if(!warm_rows.empty()) {
    std::cout << "\nTable 3: every input point projected with project_points and warm starts (default options)\n";
    print_subset_table(warm_rows, markdown, true);
    std::cout << "\ncpu/P_L, cpu/jet: as in table 2; cold/warm = table 2's cpu ms/q of the same operator on the same "
                 "input (cold, random queries) over this row's."
              << std::endl;
  }
  return 0;
}
