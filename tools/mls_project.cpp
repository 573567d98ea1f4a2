// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_project: projects points onto the MLS curve (2D) or surface (3D) of a point set.
// Run `mls_project --help` for the usage. The file reads top to bottom: the operator table,
// the projection of one operator (a template over the dimension and the function space),
// the command line, and main.

#include <CGAL/MLS_projection.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <mls_tools/arguments.h>
#include <mls_tools/errors.h>
#include <mls_tools/output_file.h>
#include <mls_tools/point_io.h>
#include <mls_tools/progress.h>
#include <mls_tools/synthetic.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using mls_tools::Input_error;
using mls_tools::Point_cloud;
using mls_tools::Usage_error;

const char* const tool_name = "mls_project";
const char* const default_output = "projected.xyz";

// ---------------------------------------------------------------------------------------------
// What one projection run needs and gives back, whatever the operator.

struct Job {
  const Point_cloud& input;
  const Point_cloud& queries;
  const CGAL::MLS::Projection_options& options;
  bool show_progress;
  std::ostream& out;
};

struct Outcome {
  std::size_t failed = 0;
  double bandwidth = 0;
};

template <int D> struct Point_types;
template <> struct Point_types<2> {
  using Point = Kernel::Point_2;
  using Vector = Kernel::Vector_2;
  static Point point(const std::array<double, 3>& c) { return Point(c[0], c[1]); }
  static Vector vector(const std::array<double, 3>& c) { return Vector(c[0], c[1]); }
};
template <> struct Point_types<3> {
  using Point = Kernel::Point_3;
  using Vector = Kernel::Vector_3;
  static Point point(const std::array<double, 3>& c) { return Point(c[0], c[1], c[2]); }
  static Vector vector(const std::array<double, 3>& c) { return Vector(c[0], c[1], c[2]); }
};

/// The fewest input points `Operator` accepts here: its own minimum, and at least D+1.
template <class Operator>
std::size_t minimum_points() {
  return (std::max)(std::size_t(Operator::minimum_points()), std::size_t(Operator::dimension + 1));
}

/// Projects the queries with `Operator` (any operator of the package, constructible from a
/// shared sample set and the options) and writes `x y [z] nx ny [nz]` per query, in order.
template <class Operator>
Outcome run_operator(const Job& job) {
  constexpr int D = Operator::dimension;
  using T = Point_types<D>;
  using Sample = std::pair<typename T::Point, typename T::Vector>;
  using Samples = typename Operator::Samples;
  using Point_map = CGAL::First_of_pair_property_map<Sample>;
  using Normal_map = CGAL::Second_of_pair_property_map<Sample>;

  std::vector<Sample> samples;
  samples.reserve(job.input.size());
  for(std::size_t i = 0; i < job.input.size(); ++i)
    samples.emplace_back(T::point(job.input.points[i]),
                         job.input.has_normals ? T::vector(job.input.normals[i]) : typename T::Vector(CGAL::NULL_VECTOR));
  // The normals only orient the results; the sample set's type does not depend on them.
  const auto shared = job.input.has_normals
    ? std::make_shared<const Samples>(samples, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))
    : std::make_shared<const Samples>(samples, CGAL::parameters::point_map(Point_map()));
  const Operator op(shared, job.options);

  std::vector<typename T::Point> queries;
  queries.reserve(job.queries.size());
  for(const auto& q : job.queries.points) queries.push_back(T::point(q));

  Outcome outcome;
  outcome.bandwidth = op.bandwidth();
  std::ostream& out = job.out;
  out << std::setprecision(17);
  // A std::function, because the output iterator must be assignable (a capturing lambda is not).
  const std::function<void(const typename Operator::Result&)> write = [&](const typename Operator::Result& r) {
    if(!r.is_success()) ++outcome.failed; // the result keeps the query and has a null normal
    for(int k = 0; k < D; ++k) out << r.point[k] << ' ';
    for(int k = 0; k < D; ++k) out << r.normal[k] << (k + 1 < D ? ' ' : '\n');
  };
  mls_tools::Progress_bar bar("mls_project: projecting", job.show_progress);
  CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(op, queries, boost::make_function_output_iterator(write),
                                                             CGAL::parameters::callback(bar.callback()));
  bar.finish();
  return outcome;
}

// ---------------------------------------------------------------------------------------------
// The operators and function spaces. Adding an operator is one entry in `operators`.

using Run_function = Outcome (*)(const Job&);
using Minimum_function = std::size_t (*)();

/// The function spaces, in the order of the second index of `Operator_entry::run`.
const std::vector<std::pair<std::string, int>> spaces = {{"plane", 0}, {"quadratic", 1}};

struct Operator_entry {
  const char* name;
  const char* description;
  Run_function run[2][2];          // [dimension - 2][space]
  Minimum_function minimum[2][2];  // [dimension - 2][space]
};

/// The entry of an operator templated by its function space, like Levin_projection.
template <template <class> class Operator>
Operator_entry function_space_operator(const char* name, const char* description) {
  using namespace CGAL::MLS;
  return {name,
          description,
          {{&run_operator<Operator<Plane_function_space<2>>>, &run_operator<Operator<Polynomial_function_space<2>>>},
           {&run_operator<Operator<Plane_function_space<3>>>, &run_operator<Operator<Polynomial_function_space<3>>>}},
          {{&minimum_points<Operator<Plane_function_space<2>>>, &minimum_points<Operator<Polynomial_function_space<2>>>},
           {&minimum_points<Operator<Plane_function_space<3>>>, &minimum_points<Operator<Polynomial_function_space<3>>>}}};
}

template <class Space> using Levin = CGAL::MLS::Levin_projection<Kernel, Space>;

const std::vector<Operator_entry>& operators() {
  static const std::vector<Operator_entry> table = {
    function_space_operator<Levin>("levin", "Levin's two-phase projection P_L"),
  };
  return table;
}

// ---------------------------------------------------------------------------------------------
// The command line.

struct Settings {
  std::string input, output, queries;
  const Operator_entry* op = &operators().front();
  int space = 1; // quadratic
  CGAL::MLS::Projection_options options;
  int threads = 0; // 0: all
  bool quiet = false;
};

mls_tools::Argument_parser make_parser(Settings& s) {
  mls_tools::Argument_parser parser;
  parser.add("--input", "P", "input points: .xyz, .pwn, .ply or .off (default: the built-in noisy torus)",
             [&s](const std::string& v) {
               (void)mls_tools::point_format(v); // an unknown extension is a usage error
               s.input = v;
             });
  parser.add("--output", "O", "output file, .xyz (or .pwn in 3D) (default with the built-in input: projected.xyz)",
             [&s](const std::string& v) {
               const std::string ext = mls_tools::lower_extension(v);
               if(ext != ".xyz" && ext != ".pwn")
                 throw Usage_error("unknown extension '" + ext + "' of output '" + v + "' (expected .xyz or .pwn)");
               s.output = v;
             });
  parser.add("--queries", "Q", "points to project, same dimension as the input (default: the input points)",
             [&s](const std::string& v) {
               (void)mls_tools::point_format(v);
               s.queries = v;
             });
  std::string op_names;
  std::vector<std::pair<std::string, const Operator_entry*>> op_choices;
  for(const auto& e : operators()) {
    op_names += (op_names.empty() ? "" : "|") + std::string(e.name);
    op_choices.emplace_back(e.name, &e);
  }
  parser.add("--operator", op_names, "projection operator (default: levin)", [&s, op_choices](const std::string& v) {
    s.op = mls_tools::parse_choice("--operator", v, op_choices);
  });
  parser.add("--space", "plane|quadratic", "function space of the local fit (default: quadratic)",
             [&s](const std::string& v) { s.space = mls_tools::parse_choice("--space", v, spaces); });
  parser.add("--h", "H", "bandwidth h of the weight, > 0 (default: from the data, see --k)",
             [&s](const std::string& v) { s.options.bandwidth = mls_tools::parse_positive_double("--h", v); });
  parser.add("--k", "K", "neighbours of the initial PCA and of the default h (default: 6 in 2D, 16 in 3D)",
             [&s](const std::string& v) { s.options.k = mls_tools::parse_positive_int("--k", v); });
  parser.add("--threads", "N", "use at most N threads, N >= 1 (default: all cores)",
             [&s](const std::string& v) { s.threads = mls_tools::parse_positive_int("--threads", v, 4096); });
  parser.add("--weight", "gaussian|wendland", "weight function (default: gaussian)", [&s](const std::string& v) {
    s.options.weight = mls_tools::parse_choice<CGAL::MLS::Weight_kind>(
      "--weight", v, {{"gaussian", CGAL::MLS::Weight_kind::GAUSSIAN}, {"wendland", CGAL::MLS::Weight_kind::WENDLAND}});
  });
  parser.add_flag("--quiet", "no progress bar, only the final summary line", [&s] { s.quiet = true; });
  return parser;
}

void print_help(const mls_tools::Argument_parser& parser) {
  std::cout
    << "Usage: mls_project --input P --output O [--queries Q] [--operator levin] [--space plane|quadratic]\n"
       "                   [--h H] [--k K] [--threads N] [--weight gaussian|wendland] [--quiet]\n"
       "\n"
       "Projects points onto the moving-least-squares (MLS) curve (2D input) or surface (3D input)\n"
       "defined by the input points.\n"
       "\n"
       "Options:\n";
  parser.print_options(std::cout);
  std::cout
    << "\n"
       "Operators:\n";
  for(const auto& e : operators()) std::cout << "  " << e.name << ": " << e.description << '\n';
  std::cout
    << "\n"
       "Input: .xyz holds 2 (x y), 3 (x y z), 4 (x y nx ny) or 6 (x y z nx ny nz) numbers per line,\n"
       "blank lines and lines starting with # are skipped; .pwn holds 6 (x y z nx ny nz); .ply and .off\n"
       "give their vertices (3D, normals when present). The input decides the dimension; the queries\n"
       "must have the same. Input normals only orient the output normals.\n"
       "Without --input, the input is a built-in noisy torus (R = 1, r = 0.4, 20000 points uniform by\n"
       "area, Gaussian noise sigma = 0.005, fixed seed: the same points on every run, with their exact\n"
       "normals) and the output defaults to projected.xyz.\n"
       "\n"
       "Output: one line per query, in query order: x y [z] nx ny [nz], 17 significant digits. A query\n"
       "whose projection fails keeps its position with a null normal, and is counted as failed in the\n"
       "summary line printed on stderr. The output is written to a temporary file renamed at the end.\n"
       "\n"
       "Exit status: 0 on success, 1 on a bad input or output file, 2 on a bad command line.\n";
}

/// Reads a point file, or the built-in torus when `path` is empty.
Point_cloud read_input(const std::string& path) {
  return path.empty() ? mls_tools::noisy_torus() : mls_tools::read_point_file(path);
}

int run(int argc, char** argv) {
  const auto start = std::chrono::steady_clock::now();
  Settings s;
  const auto parser = make_parser(s);
  if(!parser.parse(argc, argv)) {
    print_help(parser);
    return 0;
  }
  if(s.input.empty() && s.output.empty()) s.output = default_output;
  if(s.output.empty()) throw Usage_error("missing --output (see --help)");

  // Check that the output can be written before doing any work.
  mls_tools::Atomic_output_file output(s.output);

  const Point_cloud input = read_input(s.input);
  const std::string input_name = s.input.empty() ? "the built-in torus" : "'" + s.input + "'";
  const int D = input.dimension;
  if(D == 2 && mls_tools::lower_extension(s.output) == ".pwn")
    throw Usage_error("a .pwn output holds 3D points, but the input is 2D: use .xyz");
  mls_tools::check_point_cloud(input, s.op->minimum[D - 2][s.space](), input_name);

  Point_cloud queries_file;
  if(!s.queries.empty()) {
    queries_file = mls_tools::read_point_file(s.queries);
    if(queries_file.dimension != D)
      throw Input_error("the queries '" + s.queries + "' are " + std::to_string(queries_file.dimension) +
                        "D but the input is " + std::to_string(D) + "D: the dimensions must agree");
  }
  const Point_cloud& queries = s.queries.empty() ? input : queries_file;

#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> thread_limit;
  if(s.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(s.threads));
#endif

  const Job job{input, queries, s.options, !s.quiet && mls_tools::stderr_is_terminal(), output.stream()};
  const Outcome outcome = s.op->run[D - 2][s.space](job);
  output.commit();

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "%s: %zu points (%dD), %zu queries, %zu failed, h=%.3g, %.2f s, output %s\n", tool_name,
               input.size(), D, queries.size(), outcome.failed, outcome.bandwidth, seconds, s.output.c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch(const Usage_error& e) {
    std::cerr << tool_name << ": error: " << e.what() << std::endl;
    return Usage_error::exit_code;
  } catch(const Input_error& e) {
    std::cerr << tool_name << ": error: " << e.what() << std::endl;
    return Input_error::exit_code;
  } catch(const std::bad_alloc&) {
    std::cerr << tool_name << ": error: out of memory" << std::endl;
    return 1;
  } catch(const std::exception& e) {
    std::cerr << tool_name << ": error: " << e.what() << std::endl;
    return 1;
  }
}
