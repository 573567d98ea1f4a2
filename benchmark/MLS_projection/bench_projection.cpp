// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Speed and accuracy of Levin's projection P_L next to CGAL's jet smoothing.
//
// For each size n: samples n points of a torus with Gaussian noise (fixed seed, so the same
// n gives the same points on every machine), then
//   - P_L quadratic: Levin_projection<Epick, Polynomial_function_space<3>> (default options),
//   - P_L plane:     Levin_projection<Epick, Plane_function_space<3>>      (default options),
//     each timed as "build" (sample set: copy + kd-tree, and the bandwidth) and "project"
//     (project_points<Parallel_if_available_tag> of all n input points),
//   - jet: CGAL::jet_smooth_point_set<Parallel_if_available_tag> on a copy of the same points
//     (k = 18 by default, degree 2 fit and 2 Monge; its own kd-tree is inside its time),
// and reports the distance of every output point to the exact torus. Wall times use
// std::chrono::steady_clock; the process CPU time (getrusage) is reported next to them.
//
// Usage: bench_projection [--sizes 50000,200000,1000000] [--threads N] [--jet-k K]
//                         [--noise SIGMA] [--seed S] [--markdown]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MLS_projection.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/tags.h>

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
#include <iostream>
#include <iterator>
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

double distance_to_torus(const Point& p) {
  const double rho = std::hypot(p.x(), p.y());
  return std::abs(std::hypot(rho - major_radius, p.z()) - minor_radius);
}

struct Accuracy {
  double mean = 0, p99 = 0, max = 0;
};

template <class Range, class PointOf>
Accuracy accuracy(const Range& range, PointOf point_of) {
  Accuracy a;
  std::vector<double> d;
  for(const auto& v : range) d.push_back(distance_to_torus(point_of(v)));
  if(d.empty()) return a;
  for(const double x : d) a.mean += x;
  a.mean /= double(d.size());
  a.max = *std::max_element(d.begin(), d.end());
  const auto q = d.begin() + std::ptrdiff_t(0.99 * double(d.size() - 1));
  std::nth_element(d.begin(), q, d.end());
  a.p99 = *q;
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

struct Row {
  std::size_t n = 0;
  std::string method;
  double build = -1, project = -1; // -1: not applicable
  double cpu = -1;                 // process CPU seconds of build + project
  double jet = -1, jet_cpu = -1;   // the jet times of the same n, for the ratios
  Accuracy error;
  std::size_t failures = 0, not_converged = 0;
  double mean_neighbors = -1;
  double peak_rss = -1;
};

std::string fixed(double x, int digits) {
  if(x < 0) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}
std::string scientific(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

void print_table(const std::vector<Row>& rows, bool markdown) {
  const std::vector<std::string> head = {"n",        "method",    "build s",  "project s", "total s",
                                         "total/jet", "cpu s",     "cpu/jet",  "mean dist", "p99 dist",
                                         "max dist",  "failed/not conv", "nbrs", "peak RSS MB"};
  std::vector<std::vector<std::string>> cells;
  for(const Row& r : rows) {
    const double total = r.build >= 0 ? r.build + r.project : r.project;
    std::string ratio = "-";
    if(total >= 0 && r.jet > 0) ratio = fixed(total / r.jet, 2);
    std::string cpu_ratio = "-";
    if(r.cpu >= 0 && r.jet_cpu > 0) cpu_ratio = fixed(r.cpu / r.jet_cpu, 2);
    cells.push_back({std::to_string(r.n), r.method, fixed(r.build, 3), fixed(r.project, 3), fixed(total, 3), ratio,
                     fixed(r.cpu, 2), cpu_ratio, scientific(r.error.mean), scientific(r.error.p99),
                     scientific(r.error.max),
                     r.build >= 0 ? std::to_string(r.failures) + "/" + std::to_string(r.not_converged) : "-", fixed(r.mean_neighbors, 1),
                     fixed(r.peak_rss, 0)});
  }
  std::vector<std::size_t> width(head.size());
  for(std::size_t j = 0; j < head.size(); ++j) {
    width[j] = head[j].size();
    for(const auto& c : cells) width[j] = (std::max)(width[j], c[j].size());
  }
  const auto line = [&](const std::vector<std::string>& c) {
    std::ostringstream os;
    if(markdown) os << "| ";
    for(std::size_t j = 0; j < c.size(); ++j) {
      const std::string pad(width[j] - c[j].size(), ' ');
      os << (j == 1 ? c[j] + pad : pad + c[j]) << (markdown ? " | " : "  ");
    }
    std::string s = os.str();
    while(!s.empty() && s.back() == ' ') s.pop_back();
    std::cout << s << "\n";
  };
  line(head);
  if(markdown) {
    std::vector<std::string> rule;
    for(std::size_t j = 0; j < head.size(); ++j) rule.push_back(std::string(width[j] - 1, '-') + (j == 1 ? "-" : ":"));
    line(rule);
  }
  for(const auto& c : cells) line(c);
}

template <class FunctionSpace>
Row run_levin(const std::vector<Point>& points, const char* method) {
  using Projection = CGAL::MLS::Levin_projection<Kernel, FunctionSpace>;
  Row row;
  row.n = points.size();
  row.method = method;

  const double cpu_start = process_cpu_seconds();
  auto start = Clock::now();
  const Projection projection(points); // sample set (copy + kd-tree) and bandwidth
  row.build = seconds_since(start);

  std::vector<typename Projection::Result> results;
  results.reserve(points.size());
  start = Clock::now();
  CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(projection, points, std::back_inserter(results));
  row.project = seconds_since(start);
  row.cpu = process_cpu_seconds() - cpu_start;

  double neighbors = 0;
  for(const auto& r : results) {
    if(!r.is_success()) ++row.failures;
    if(r.status == CGAL::MLS::Projection_status::NOT_CONVERGED) ++row.not_converged;
    neighbors += double(r.number_of_neighbors);
  }
  row.mean_neighbors = results.empty() ? 0 : neighbors / double(results.size());
  // A failed projection keeps the query point: it is counted as it is.
  row.error = accuracy(results, [](const auto& r) { return r.point; });
  row.peak_rss = peak_rss_mb();
  return row;
}

Row run_jet(const std::vector<Point>& points, unsigned int k) {
  Row row;
  row.n = points.size();
  row.method = "jet k=" + std::to_string(k);
  std::vector<Point> smoothed = points;
  const double cpu_start = process_cpu_seconds();
  const auto start = Clock::now();
  CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(smoothed, k);
  row.project = seconds_since(start);
  row.cpu = process_cpu_seconds() - cpu_start;
  row.error = accuracy(smoothed, [](const Point& p) { return p; });
  row.mean_neighbors = k;
  row.peak_rss = peak_rss_mb();
  return row;
}

[[noreturn]] void usage(const char* program, const std::string& error) {
  if(!error.empty()) std::cerr << "error: " << error << "\n";
  std::cerr << "usage: " << program
            << " [--sizes 50000,200000,1000000] [--threads N] [--jet-k K] [--noise SIGMA] [--seed S] [--markdown]\n";
  std::exit(error.empty() ? 0 : 2);
}

std::vector<std::size_t> parse_sizes(const std::string& s, const char* program) {
  std::vector<std::size_t> sizes;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ',')) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(item.c_str(), &end, 10);
    if(item.empty() || *end != '\0' || v < 100) usage(program, "bad size '" + item + "' (an integer >= 100)");
    sizes.push_back(std::size_t(v));
  }
  if(sizes.empty()) usage(program, "no size given");
  return sizes;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes = {50000, 200000, 1000000};
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

  std::cout << "MLS_projection benchmark: torus R=" << major_radius << " r=" << minor_radius
            << ", isotropic Gaussian noise sigma=" << noise << ", seed " << seed << "\n"
            << "threads: " << threads << " (" << concurrency << "), hardware threads: "
            << std::thread::hardware_concurrency() << "\n"
            << "P_L: default Projection_options; jet: jet_smooth_point_set k=" << jet_k
            << ", degree_fitting=2, degree_monge=2\n"
            << "distances are to the exact torus; 'input' is the noisy sample itself\n"
            << std::endl;

  std::vector<Row> rows;
  for(const std::size_t n : sizes) {
    const std::vector<Point> points = sample_torus(n, noise, seed);
    Row input;
    input.n = n;
    input.method = "input (noisy)";
    input.error = accuracy(points, [](const Point& p) { return p; });
    input.peak_rss = peak_rss_mb();

    Row jet = run_jet(points, jet_k);
    std::cerr << "n=" << n << ": jet done in " << jet.project << " s" << std::endl;
    Row quadratic = run_levin<CGAL::MLS::Polynomial_function_space<3>>(points, "P_L quadratic");
    std::cerr << "n=" << n << ": P_L quadratic done in " << quadratic.build + quadratic.project << " s" << std::endl;
    Row plane = run_levin<CGAL::MLS::Plane_function_space<3>>(points, "P_L plane");
    std::cerr << "n=" << n << ": P_L plane done in " << plane.build + plane.project << " s" << std::endl;

    jet.jet = quadratic.jet = plane.jet = jet.project;
    jet.jet_cpu = quadratic.jet_cpu = plane.jet_cpu = jet.cpu;
    rows.push_back(input);
    rows.push_back(quadratic);
    rows.push_back(plane);
    rows.push_back(jet);
  }

  std::cout << "\n";
  print_table(rows, markdown);
  std::cout << "\ntotal = build + project (jet: its whole call, kd-tree included); total/jet = total / jet's total "
               "at the same n.\ncpu s = user + system CPU seconds of the process over the same span (all threads; "
               "robust to other load on the machine); cpu/jet likewise.\ndist = distance to the exact torus (p99: 99th "
               "percentile); failed = no projection (point kept), not conv = optimiser hit its limit (point used).\nnbrs = mean number of points with non-zero weight in the final fit of P_L "
               "(jet: k).\npeak RSS = getrusage ru_maxrss after the row (the process peak so far, monotone)."
            << std::endl;
  return 0;
}
