// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_project: projects points onto the MLS curve (2D) or surface (3D) of a point set.
// Run `mls_project --help` for the usage. The file reads top to bottom: the operator table, the
// command line, and main. The projection itself (a template over the operator class) and the
// classes behind each operator and function space are in <mls_tools/operator_rows.h>, compiled
// in one translation unit per operator (mls_project_<operator>.cpp).

#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Weight_function.h>

#include <mls_tools/arguments.h>
#include <mls_tools/errors.h>
#include <mls_tools/output_file.h>
#include <mls_tools/point_io.h>
#include <mls_tools/progress.h>
#include <mls_tools/projection_job.h>
#include <mls_tools/synthetic.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

using mls_tools::Input_error;
using mls_tools::Point_cloud;
using mls_tools::Usage_error;

const char* const tool_name = "mls_project";
const char* const default_output = "projected.xyz";
const char* const default_operator = "unified";
/// The function space when --space is not given (the operators that cannot use it, the graph
/// operators levin and single when it is wedge or mixed, use `fallback_space`).
const char* const default_space = "mixed";
const char* const fallback_space = "quadratic";

// ---------------------------------------------------------------------------------------------
// The operators. Adding an operator is one entry in `operators()` and its rows (which class per
// dimension and function space) in <mls_tools/operator_rows.h>, instantiated in its own
// translation unit; the function spaces are listed in mls_tools::function_spaces().

using mls_tools::Implementation;

struct Operator_entry {
  const char* name;
  const char* description;
  const char* restriction; // why the spaces without an implementation are not offered
  mls_tools::Operator_rows rows; // [dimension - 2][column of the space]
};

const std::vector<Operator_entry>& operators() {
  const char* const graph_only = "it fits a height function over its frame, which needs a graph function space";
  static const std::vector<Operator_entry> table = {
    {"levin", "Levin's two-phase projection P_L: frame, then a height function over it", graph_only,
     mls_tools::levin_rows()},
    {"single", "single-phase projection P_S (eq. 4): frame and height function fitted together", graph_only,
     mls_tools::single_phase_rows()},
    {"enriched", "enriched projection P_E (eq. 5): Levin's frame, then a closest-point fit", "",
     mls_tools::enriched_rows()},
    {"unified", "unified projection P_U (eq. 6): frame and function fitted together, closest-point distances", "",
     mls_tools::unified_rows()},
  };
  return table;
}

const Operator_entry& find_operator(const std::string& name) {
  for(const auto& e : operators())
    if(name == e.name) return e;
  throw std::logic_error(std::string("no operator named ") + name);
}

const std::vector<std::pair<std::string, int>>& spaces = mls_tools::function_spaces();

int space_index(const std::string& name) {
  for(const auto& s : spaces)
    if(s.first == name) return s.second;
  throw std::logic_error("no function space named " + name);
}

bool can_use(const Operator_entry& op, int space) { return op.rows[0][space].run && op.rows[1][space].run; }

/// The names of the function spaces `op` can use, `a|b|...`.
std::string usable_spaces(const Operator_entry& op) {
  std::string names;
  for(const auto& s : spaces)
    if(can_use(op, s.second)) names += (names.empty() ? "" : "|") + s.first;
  return names;
}

// ---------------------------------------------------------------------------------------------
// The command line.

struct Settings {
  std::string input, output, queries, features;
  const Operator_entry* op = &find_operator(default_operator);
  std::optional<int> space; // unset: the default of the operator, see `choose_space`
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
  parser.add("--output", "O", "output file, .xyz (or .pwn or .ply in 3D) (default with the built-in input: projected.xyz)",
             [&s](const std::string& v) {
               const std::string ext = mls_tools::lower_extension(v);
               if(ext != ".xyz" && ext != ".pwn" && ext != ".ply")
                 throw Usage_error("unknown extension '" + ext + "' of output '" + v + "' (expected .xyz, .pwn or .ply)");
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
  parser.add("--operator", op_names, std::string("projection operator (default: ") + default_operator + ")",
             [&s, op_choices](const std::string& v) { s.op = mls_tools::parse_choice("--operator", v, op_choices); });
  std::string space_names;
  for(const auto& sp : spaces) space_names += (space_names.empty() ? "" : "|") + sp.first;
  parser.add("--space", space_names,
             std::string("function space of the local fit (default: ") + default_space + ", " + fallback_space +
               " for the operators that cannot use it)",
             [&s](const std::string& v) { s.space = mls_tools::parse_choice("--space", v, spaces); });
  parser.add("--features", "F", "also write the projections on a crease or apex to F: x y [z] dx dy [dz]",
             [&s](const std::string& v) { s.features = v; });
  parser.add("--h", "H", "bandwidth h of the weight, > 0 (default: from the data, see --k)",
             [&s](const std::string& v) { s.options.bandwidth = mls_tools::parse_positive_double("--h", v); });
  parser.add("--k", "K", "neighbours of the initial PCA and of the default h (default: 6 in 2D, 16 in 3D)",
             [&s](const std::string& v) { s.options.k = mls_tools::parse_positive_int("--k", v); });
  parser.add("--threads", "N", "use at most N threads, N >= 1 (default: all cores)",
             [&s](const std::string& v) { s.threads = mls_tools::parse_positive_int("--threads", v, 4096); });
  parser.add("--weight", "polynomial|gaussian|wendland", "weight function (default: polynomial)", [&s](const std::string& v) {
    s.options.weight = mls_tools::parse_choice<CGAL::MLS::Weight_kind>(
      "--weight", v,
      {{"polynomial", CGAL::MLS::Weight_kind::POLYNOMIAL}, {"gaussian", CGAL::MLS::Weight_kind::GAUSSIAN},
       {"wendland", CGAL::MLS::Weight_kind::WENDLAND}});
  });
  parser.add_flag("--no-warm-starts",
                  "project each query independently (default: continue from the fit of a nearby query, see the manual)",
                  [&s] { s.options.warm_starts = false; });
  parser.add_flag("--quiet", "no progress bar, only the final summary line", [&s] { s.quiet = true; });
  return parser;
}

void print_help(const mls_tools::Argument_parser& parser) {
  std::cout
    << "Usage: mls_project --input P --output O [--queries Q] [--operator levin|single|enriched|unified]\n"
       "                   [--space plane|quadratic|wedge|mixed] [--features F] [--h H] [--k K]\n"
       "                   [--threads N] [--weight polynomial|gaussian|wendland] [--quiet]\n"
       "\n"
       "Projects points onto the moving-least-squares (MLS) curve (2D input) or surface (3D input)\n"
       "defined by the input points.\n"
       "\n"
       "Options:\n";
  parser.print_options(std::cout);
  std::cout
    << "\n"
       "Operators:\n";
  for(const auto& e : operators())
    std::cout << "  " << e.name << ": " << e.description << "; spaces " << usable_spaces(e) << '\n';
  std::cout
    << "\n"
       "Function spaces (the local fit):\n"
       "  plane: a hyperplane; biased on curved data by O(h^2) towards the inside.\n"
       "  quadratic: with levin, the full degree-2 polynomial over the frame (Polynomial_function_space);\n"
       "    with the other operators, the paper's quadratic space, paraboloids with principal curvatures\n"
       "    (k x^2 in 2D, a x^2 + b y^2 in 3D: Paraboloid_function_space).\n"
       "  wedge: a wedge fan (two rays in 2D, 4 infinite triangles around an apex in 3D): reproduces\n"
       "    creases and corners exactly. Not a graph: enriched and unified only.\n"
       "  mixed: levin's full quadratic for every query, and a wedge fit (with the operator) only where\n"
       "    the quadratic's RMS residual is more than twice the noise of the data (or 0.01 h); the\n"
       "    wedge is kept when its energy is below 0.5 x the quadratic's, so that smooth parts keep the\n"
       "    quadratic's accuracy and cost, and creases the wedge's. Enriched and unified only.\n";
  std::string cannot; // the operators that cannot use the default space
  for(const auto& e : operators())
    if(!can_use(e, space_index(default_space))) cannot += (cannot.empty() ? "" : ", ") + std::string(e.name);
  std::cout << "Without --space: " << default_space;
  if(!cannot.empty()) std::cout << ", or " << fallback_space << " with the operators that cannot use it (" << cannot << ")";
  std::cout
    << ".\n"
       "A --space that the operator cannot use is a command-line error.\n"
       "Cost per query in 3D, one thread: levin some 20 microseconds; the closest-point operators\n"
       "(single, enriched, unified) 0.15 to 0.3 ms continuing from the previous query's fit, 1 ms alone\n"
       "(--no-warm-starts); mixed costs levin's on smooth parts and the wedge fit's near creases.\n"
       "\n"
       "Features (--features F): one line per projected point that lies on a crease or an apex of its\n"
       "local fit, in query order: x y [z] dx dy [dz], d the unit crease direction (its sign is\n"
       "arbitrary); at an apex (a corner in 3D, every apex in 2D) d is written as zeros. Only the\n"
       "wedge and mixed spaces find features (with enriched, whose frame is Levin's, they need not lie\n"
       "on the data's creases; with unified they do): with the other spaces F is written empty.\n"
       "F is written like the output (temporary file, renamed at the end).\n"
       "\n"
       "Input: .xyz holds 2 (x y), 3 (x y z), 4 (x y nx ny) or 6 (x y z nx ny nz) numbers per line,\n"
       "blank lines and lines starting with # are skipped; .pwn holds 6 (x y z nx ny nz) and then any\n"
       "attribute values; .ply and .off give their vertices (3D, normals when present; a .ply file's\n"
       "other vertex properties, such as red green blue alpha intensity, are attributes). The input\n"
       "decides the dimension; the queries must have the same. Input normals only orient the\n"
       "output normals.\n"
       "Without --input, the input is a built-in noisy torus (R = 1, r = 0.4, 20000 points uniform by\n"
       "area, Gaussian noise sigma = 0.005, fixed seed: the same points on every run, with their exact\n"
       "normals) and the output defaults to projected.xyz.\n"
       "\n"
       "Output: one line per query, in query order: x y [z] nx ny [nz], 17 significant digits, then\n"
       "the input's attributes at the projected point (weighted means of the input points' around it,\n"
       "on its own face of a crease; see the manual), in the input's types; .ply is ASCII PLY with\n"
       "the same vertex lines (properties x y z nx ny nz and the attributes' names). A query\n"
       "whose projection fails keeps its position with a null normal, and is counted as failed in the\n"
       "summary line printed on stderr. The output is written to a temporary file renamed at the end.\n"
       "\n"
       "The summary line names the operator and the function space used.\n"
       "\n"
       "Exit status: 0 on success, 1 on a bad input or output file, 2 on a bad command line.\n";
}

/// The function space of the run: --space when given (an error when the operator cannot use
/// it), else the default, or the fall-back for the operators that cannot use the default.
int choose_space(const Settings& s) {
  if(!s.space) return can_use(*s.op, space_index(default_space)) ? space_index(default_space) : space_index(fallback_space);
  if(!can_use(*s.op, *s.space))
    throw Usage_error("--operator " + std::string(s.op->name) + " cannot use --space " + spaces[*s.space].first + ": " +
                      s.op->restriction + " (" + usable_spaces(*s.op) + ")");
  return *s.space;
}

/// Whether two paths name the same file (existing or not).
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec1, ec2;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ec1), cb = fs::weakly_canonical(fs::absolute(b), ec2);
  return ec1 || ec2 ? a == b : ca == cb;
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
  const int space = choose_space(s);
  if(!s.features.empty() && same_file(s.features, s.output))
    throw Usage_error("--features and --output name the same file '" + s.features + "'");

  // Check that the outputs can be written before doing any work.
  mls_tools::Atomic_output_file output(s.output);
  std::optional<mls_tools::Atomic_output_file> features;
  if(!s.features.empty()) features.emplace(s.features);

  const Point_cloud input = read_input(s.input);
  const std::string input_name = s.input.empty() ? "the built-in torus" : "'" + s.input + "'";
  const int D = input.dimension;
  const std::string output_format = mls_tools::lower_extension(s.output);
  if(D == 2 && output_format != ".xyz")
    throw Usage_error("a " + output_format + " output holds 3D points, but the input is 2D: use .xyz");
  const Implementation& implementation = s.op->rows[D - 2][space];
  mls_tools::check_point_cloud(input, implementation.minimum_points(), input_name);

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

  if(output_format == ".ply") {
    output.stream() << "ply\nformat ascii 1.0\nelement vertex " << queries.size()
                    << "\nproperty double x\nproperty double y\nproperty double z\n"
                       "property double nx\nproperty double ny\nproperty double nz\n";
    mls_tools::write_ply_properties(output.stream(), input.channels);
    output.stream() << "end_header\n";
  }
  const mls_tools::Projection_job job{input.points,
                                     input.has_normals ? &input.normals : nullptr,
                                     input.channels,
                                     input.attributes,
                                     queries.points,
                                     s.options,
                                     !s.quiet && mls_tools::stderr_is_terminal(),
                                     output.stream(),
                                     features ? &features->stream() : nullptr};
  const mls_tools::Projection_outcome outcome = implementation.run(job);
  if(features) features->commit();
  output.commit();

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "%s: %zu points (%dD), %zu queries, %zu failed, %zu on features, %s/%s, h=%.3g, %.2f s, output %s%s%s\n",
               tool_name, input.size(), D, queries.size(), outcome.failed, outcome.on_feature, s.op->name,
               spaces[space].first.c_str(), outcome.bandwidth, seconds, s.output.c_str(), features ? ", features " : "",
               features ? s.features.c_str() : "");
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
