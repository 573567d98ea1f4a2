// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_mesh: meshes the MLS surface of a 3D point set into a closed, manifold OFF triangle mesh (with
// --open, a mesh with a boundary where the data ends),
// with CGAL's Mesh_3 (sharp features protected) or Surface_mesher, through
// CGAL::MLS::mls_surface_reconstruction(). Run `mls_mesh --help` for the usage. Without --input it
// meshes a built-in point set sampled from an analytic solid with sharp edges, corners and a
// curved part (<mls_tools/builtin_solid.h>).

#include <CGAL/MLS_projection/Meshing_report.h>

#include <mls_tools/arguments.h>
#include <mls_tools/attributes.h>
#include <mls_tools/builtin_solid.h>
#include <mls_tools/errors.h>
#include <mls_tools/mesh_job.h>
#include <mls_tools/output_file.h>
#include <mls_tools/point_io.h>
#include <mls_tools/progress.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/OFF.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

using mls_tools::Input_error;
using mls_tools::Point_cloud;
using mls_tools::Usage_error;
using Mesher = CGAL::MLS::Mesher;
using K = mls_tools::Mesh_kernel;
using mls_tools::Mesh;

const char* const tool_name = "mls_mesh";
const char* const default_output = "mesh.off";
/// The fewest input points: a surface needs a few neighbourhoods of the local fits (the bad-input
/// suite's 1, 2 and 3 points are errors, as for mls_project).
constexpr std::size_t minimum_points = 10;

// ---------------------------------------------------------------------------------------------
// The command line. Defaults as mls_project's: the unified operator with the mixed space
// (quadratic for levin, which cannot use wedge or mixed).

enum class Operator { LEVIN, UNIFIED };
enum class Space { PLANE, QUADRATIC, WEDGE, MIXED };
const std::vector<std::pair<std::string, Operator>> operator_choices = {{"levin", Operator::LEVIN},
                                                                       {"unified", Operator::UNIFIED}};
const std::vector<std::pair<std::string, Space>> space_choices = {
  {"plane", Space::PLANE}, {"quadratic", Space::QUADRATIC}, {"wedge", Space::WEDGE}, {"mixed", Space::MIXED}};
const std::vector<std::pair<std::string, Mesher>> mesher_choices = {{"mesh3", Mesher::MESH_3},
                                                                   {"surface_mesher", Mesher::SURFACE_MESHER}};

template <class T>
std::string name_of(T value, const std::vector<std::pair<std::string, T>>& choices) {
  for(const auto& c : choices)
    if(c.second == value) return c.first;
  return "?";
}

struct Settings {
  std::string input, output = default_output;
  Operator op = Operator::UNIFIED;
  std::optional<Space> space; // unset: mixed, quadratic with levin
  Mesher mesher = Mesher::MESH_3;
  bool features = true; // auto
  bool remove_outliers = true;
  bool open = false;
  double size = 0, distance = 0, bandwidth = 0;
  double time_limit = 0; // 0: none
  int threads = 0; // 0: all
  bool parallel_mesher = false;
  bool quiet = false;
};

mls_tools::Argument_parser make_parser(Settings& s) {
  mls_tools::Argument_parser parser;
  parser.add("--input", "P", "input points: .xyz, .pwn, .ply or .off, 3D (default: the built-in solid)",
             [&s](const std::string& v) {
               (void)mls_tools::point_format(v); // an unknown extension is a usage error
               s.input = v;
             });
  parser.add("--output", "O", std::string("output mesh, .off or .ply (default: ") + default_output + ")",
             [&s](const std::string& v) {
               const std::string ext = mls_tools::lower_extension(v);
               if(ext != ".off" && ext != ".ply")
                 throw Usage_error("unknown extension '" + ext + "' of output '" + v + "' (expected .off or .ply)");
               s.output = v;
             });
  parser.add("--operator", "levin|unified", "projection operator (default: unified)",
             [&s](const std::string& v) { s.op = mls_tools::parse_choice("--operator", v, operator_choices); });
  parser.add("--space", "plane|quadratic|wedge|mixed",
             "function space of the local fit (default: mixed, quadratic with levin)",
             [&s](const std::string& v) { s.space = mls_tools::parse_choice("--space", v, space_choices); });
  parser.add("--mesher", "mesh3|surface_mesher", "CGAL mesher (default: mesh3)",
             [&s](const std::string& v) { s.mesher = mls_tools::parse_choice("--mesher", v, mesher_choices); });
  parser.add("--features", "auto|off", "protect sharp features (default: auto, see below)", [&s](const std::string& v) {
    s.features = mls_tools::parse_choice<bool>("--features", v, {{"auto", true}, {"off", false}});
  });
  parser.add("--outliers", "remove|keep", "remove the outliers first (default: remove, see below)",
             [&s](const std::string& v) {
               s.remove_outliers = mls_tools::parse_choice<bool>("--outliers", v, {{"remove", true}, {"keep", false}});
             });
  parser.add("--size", "S", "facet size bound, > 0, in input units (default: 2 x the average spacing)",
             [&s](const std::string& v) { s.size = mls_tools::parse_positive_double("--size", v); });
  parser.add("--distance", "D", "facet distance bound, > 0, in input units (default: 0.25 x the average spacing)",
             [&s](const std::string& v) { s.distance = mls_tools::parse_positive_double("--distance", v); });
  parser.add("--h", "H", "bandwidth h of the projection's weight, > 0 (default: from the data, as mls_project)",
             [&s](const std::string& v) { s.bandwidth = mls_tools::parse_positive_double("--h", v); });
  parser.add("--threads", "N", "use at most N threads, N >= 1 (default: all cores)",
             [&s](const std::string& v) { s.threads = mls_tools::parse_positive_int("--threads", v, 4096); });
  parser.add("--time-limit", "T", "stop meshing (and fail) after T seconds of the mesher, > 0 (default: no limit)",
             [&s](const std::string& v) { s.time_limit = mls_tools::parse_positive_double("--time-limit", v); });
  parser.add_flag("--open", "the input is an open scan: mesh only where there is data, with a boundary (see below)",
                  [&s] { s.open = true; });
  parser.add_flag("--parallel-mesher",
                  "mesh3 refines in parallel too: faster on large meshes, but the mesh then depends on the threads' scheduling",
                  [&s] { s.parallel_mesher = true; });
  parser.add_flag("--quiet", "no progress bar, only the final summary line", [&s] { s.quiet = true; });
  return parser;
}

void print_help(const mls_tools::Argument_parser& parser) {
  std::cout
    << "Usage: mls_mesh [--input P] [--output O] [--space plane|quadratic|wedge|mixed]\n"
       "                [--operator levin|unified] [--mesher mesh3|surface_mesher] [--features auto|off]\n"
       "                [--outliers remove|keep] [--open]\n"
       "                [--size S] [--distance D]\n"
       "                [--h H] [--threads N] [--time-limit T] [--parallel-mesher] [--quiet]\n"
       "\n"
       "Meshes the moving-least-squares (MLS) surface of a 3D point set into a closed, manifold\n"
       "triangle mesh (OFF), with CGAL's Mesh_3 or Surface_mesher; with --open, a manifold mesh with\n"
       "a boundary where the data ends.\n"
       "\n"
       "Options:\n";
  parser.print_options(std::cout);
  std::cout
    << "\n"
       "Operators and spaces: as mls_project's (see mls_project --help). levin (P_L) is fast and\n"
       "smooth and takes plane or quadratic; unified (P_U) takes every space, and with wedge or\n"
       "mixed reproduces sampled creases and corners. --operator levin --space wedge|mixed is a\n"
       "command-line error.\n"
       "\n"
       "Features (--features auto): with mesh3 and the wedge or mixed space, the creases and corners\n"
       "found by the projection are chained into polylines that Mesh_3 protects, so the mesh has\n"
       "edges along them and vertices at the corners. Otherwise (levin, plane, quadratic,\n"
       "surface_mesher) no feature is protected. --features off never protects any.\n"
       "\n"
       "Outliers (--outliers remove): a point whose 6 nearest neighbours are more than 3 times as far\n"
       "as theirs are (root mean square, median of the 6), or more than 4 times the median over all\n"
       "points, is removed before anything else; so is a region sampled more than 4 times as sparsely\n"
       "as the median, and a point off the plane of its 20 nearest neighbours by more than that median\n"
       "and 3 times the 90th percentile of their distances to the plane.\n"
       "\n"
       "Open scans (--open): the input is a part of a surface (scanned from one side, or with its\n"
       "border in view): the surface is meshed where there is data only, up to 2 average spacings\n"
       "beyond the last points, as a manifold mesh with a boundary along the scan's border (and along\n"
       "the holes wider than about 4 spacings). Coplanar points are then accepted. mesh3 only.\n"
       "Without --open the surface is closed, and an open scan fails (\"the surface is not closed\").\n"
       "\n"
       "Screening: with wedge or mixed, the seeds of the implicit function (and the feature\n"
       "detection's points) are projected with levin first, and only those whose quadratic fit\n"
       "leaves a residual above the noise go to the unified operator: the creases and corners.\n"
       "\n"
       "Threads: the normals, the seeds and the features are computed in parallel (--threads), and\n"
       "the mesh is the same, byte for byte, for any number of threads. Mesh_3's own refinement is\n"
       "sequential unless --parallel-mesher is given; its output then varies from run to run.\n"
       "\n"
       "Input: .xyz holds 3 (x y z) or 6 (x y z nx ny nz) numbers per line, .pwn 6 and then any\n"
       "attribute values, .ply and .off give their vertices (normals when present; a .ply file's\n"
       "other vertex properties, such as red green blue alpha intensity, are attributes).\n"
       "Without normals, normals are estimated and oriented (PCA, minimum spanning forest, votes\n"
       "of the free space around the points).\n"
       "A 2D input is an error.\n"
       "Without --input, the input is the built-in solid: the box [-1,1] x [-0.6,0.6] x [-0.4,0.4]\n"
       "with its edge at x = 1, z = 0.4 rounded (a quarter-cylinder fillet of radius 0.25) and a\n"
       "cylindrical bore of radius 0.25 along z at (x, y) = (-0.35, 0): 15 sharp edges (straight\n"
       "edges, the fillet's two end arcs, the bore's two rims), 6 corners, sampled noiselessly at\n"
       "spacing 0.03 (11810 points, fixed seed) with its exact normals.\n"
       "\n"
       "Output: a triangle mesh, .ply (ASCII, with the input's attributes per vertex) or .off (COFF\n"
       "with the vertex colours when the attributes are red green blue [alpha] only, otherwise\n"
       "geometry only). Each vertex's attributes are the weighted means of the input points' around\n"
       "it, on its own face of a crease (see the manual). Written to a temporary file renamed at\n"
       "the end (no file is left on an error). The output path is checked before any work.\n"
       "\n"
       "Progress bars on stderr (when it is a terminal and without --quiet) for the long stages; the\n"
       "last line of stderr is the summary: points, operator/space, mesher, seconds, vertices,\n"
       "facets, the feature polylines and corners protected, closed or not (open, with the number of\n"
       "boundary cycles, with --open), manifold or not.\n"
       "\n"
       "Exit status: 0 on success, 1 on a bad input or output file or a failed meshing, 2 on a bad\n"
       "command line.\n";
}

Space choose_space(const Settings& s) {
  const bool levin = s.op == Operator::LEVIN;
  if(!s.space) return levin ? Space::QUADRATIC : Space::MIXED;
  if(levin && (*s.space == Space::WEDGE || *s.space == Space::MIXED))
    throw Usage_error("--operator levin cannot use --space " + name_of(*s.space, space_choices) +
                      ": it fits a height function over its frame, which needs a graph function space (plane|quadratic)");
  return *s.space;
}

// ---------------------------------------------------------------------------------------------
// Writes `mesh` as PLY (with every attribute channel) or OFF (COFF when the channels are colours
// only, geometry only otherwise), with 17 digits. Returns what the summary line adds: which
// attributes were written or left out.
std::string write_mesh(std::ostream& os, const Mesh& mesh, const mls_tools::Attribute_channels& channels, bool ply) {
  const auto attributes = mesh.property_map<Mesh::Vertex_index, std::vector<double>>(mls_tools::vertex_attributes_property);
  const bool has = !channels.empty() && attributes.second;
  const bool colours = has && mls_tools::are_colours_only(channels);
  os << std::setprecision(17);
  if(ply) {
    os << "ply\nformat ascii 1.0\nelement vertex " << mesh.number_of_vertices()
       << "\nproperty double x\nproperty double y\nproperty double z\n";
    if(has) mls_tools::write_ply_properties(os, channels);
    os << "element face " << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
  } else {
    os << (colours ? "COFF\n" : "OFF\n") << mesh.number_of_vertices() << ' ' << mesh.number_of_faces() << " 0\n";
  }
  std::map<Mesh::Vertex_index, std::size_t> number; // the vertices' numbers in the file
  for(const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    number.emplace(v, number.size());
    os << p.x() << ' ' << p.y() << ' ' << p.z();
    if(has && (ply || colours)) {
      const auto& a = attributes.first[v];
      for(std::size_t k = 0; k < channels.size(); ++k) mls_tools::write_attribute(os << ' ', channels[k], a[k]);
      if(!ply && channels.size() == 3) os << " 255"; // COFF: alpha
    }
    os << '\n';
  }
  for(const auto f : mesh.faces()) {
    os << "3";
    for(const auto v : vertices_around_face(mesh.halfedge(f), mesh)) os << ' ' << number.at(v);
    os << '\n';
  }
  if(!has) return "";
  std::string names;
  for(const auto& c : channels) names += (names.empty() ? "" : " ") + c.name;
  if(ply || colours) return " (vertex attributes: " + names + ")";
  return " (vertex attributes " + names + " not written: OFF holds colours only, use a .ply output)";
}

// Checks of the output mesh.

/// Rejects a planar set: it bounds no volume, and the meshers would refine the plane's patch
/// inside the bounding sphere (measured: no end within 300 s on 400 points with levin).
/// Judged as check_point_cloud judges collinearity: the largest distance to the PCA plane is
/// negligible against the spread in it.
void check_not_coplanar(const Point_cloud& cloud, const std::string& what) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for(const auto& p : cloud.points) c += Eigen::Vector3d(p[0], p[1], p[2]);
  c /= double(cloud.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for(const auto& p : cloud.points) {
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - c;
    C.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  const Eigen::Vector3d normal = eig.eigenvectors().col(0); // eigenvalues are ascending
  double along = 0, across = 0;
  for(const auto& p : cloud.points) {
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - c;
    const double t = d.dot(normal);
    across = (std::max)(across, std::abs(t));
    along = (std::max)(along, (d - t * normal).norm());
  }
  if(!(across > 1e-10 * along))
    throw Input_error(what + ": all points are coplanar; a closed surface needs points spanning a volume");
}

bool is_manifold(const Mesh& mesh) {
  std::vector<Mesh::Halfedge_index> non_manifold;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(non_manifold));
  return non_manifold.empty() && CGAL::is_valid_polygon_mesh(mesh);
}

// ---------------------------------------------------------------------------------------------

/// One progress bar per stage of the meshing function (`CGAL::MLS::meshing_stage()`), from the
/// fraction of the whole job that it reports.
class Stage_progress {
public:
  explicit Stage_progress(bool enabled) : enabled_(enabled) {}
  void operator()(double fraction) {
    if(!enabled_) return;
    const CGAL::MLS::Meshing_stage stage = CGAL::MLS::meshing_stage(fraction);
    if(!bar_ || stage_ != stage.name) {
      if(bar_) bar_->finish();
      stage_ = stage.name;
      bar_ = std::make_unique<mls_tools::Progress_bar>(std::string(tool_name) + ": " + stage.name, true);
    }
    bar_->update((fraction - stage.begin) / (stage.end - stage.begin));
  }
  void finish() {
    if(bar_) bar_->finish();
  }

private:
  bool enabled_;
  std::string stage_;
  std::unique_ptr<mls_tools::Progress_bar> bar_;
};

int run(int argc, char** argv) {
  const auto start = std::chrono::steady_clock::now();
  Settings s;
  const auto parser = make_parser(s);
  if(!parser.parse(argc, argv)) {
    print_help(parser);
    return 0;
  }
  const Space space = choose_space(s);
  using Choice = mls_tools::Operator_choice;
  mls_tools::Mesh_settings settings;
  if(s.op == Operator::LEVIN) settings.projection_operator = space == Space::PLANE ? Choice::LEVIN_PLANE : Choice::LEVIN_QUADRATIC;
  else
    settings.projection_operator = space == Space::PLANE       ? Choice::UNIFIED_PLANE
                                   : space == Space::QUADRATIC ? Choice::UNIFIED_QUADRATIC
                                   : space == Space::WEDGE     ? Choice::UNIFIED_WEDGE
                                                               : Choice::MIXED;
  settings.mesher = s.mesher;
  settings.features = s.features;
  settings.remove_outliers = s.remove_outliers;
  settings.open_surface = s.open;
  if(s.open && s.mesher != Mesher::MESH_3) throw Usage_error("--open meshes with --mesher mesh3 only");
  settings.parallel_mesher = s.parallel_mesher;
  settings.facet_size = s.size;
  settings.facet_distance = s.distance;
  settings.bandwidth = s.bandwidth;
  settings.time_limit = s.time_limit;

  // Check that the output can be written before doing any work.
  mls_tools::Atomic_output_file output(s.output);

  const Point_cloud input = s.input.empty() ? mls_tools::builtin_solid_points() : mls_tools::read_point_file(s.input);
  const std::string input_name = s.input.empty() ? "the built-in solid" : "'" + s.input + "'";
  if(input.dimension != 3)
    throw Input_error(input_name + " holds 2D points: mls_mesh meshes surfaces of 3D point sets");
  mls_tools::check_point_cloud(input, minimum_points, input_name);
  if(!s.open) check_not_coplanar(input, input_name);

#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> thread_limit;
  if(s.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(s.threads));
#endif

  Stage_progress progress(!s.quiet && mls_tools::stderr_is_terminal());
  settings.callback = [&progress](double fraction) {
    progress(fraction);
    return true;
  };

  mls_tools::Mesh_input job;
  job.points.reserve(input.size());
  for(std::size_t i = 0; i < input.size(); ++i) {
    const auto& p = input.points[i];
    const auto n = input.has_normals ? input.normals[i] : std::array<double, 3>{0., 0., 0.};
    job.points.emplace_back(K::Point_3(p[0], p[1], p[2]), K::Vector_3(n[0], n[1], n[2]));
  }
  job.channels = input.channels.size();
  job.attributes = input.attributes;
  CGAL::MLS::Meshing_report report;
  Mesh mesh;
  const bool ok = input.has_normals ? mls_tools::reconstruct_with_normals(job, mesh, settings, report)
                                    : mls_tools::reconstruct_without_normals(job, mesh, settings, report);
  progress.finish();
  if(!ok || mesh.number_of_faces() == 0)
    throw Input_error("meshing " + input_name + " failed: " + (*report.failure ? report.failure : "no facet"));

  const bool closed = CGAL::is_closed(mesh);
  const bool manifold = is_manifold(mesh);

  const auto written = write_mesh(output.stream(), mesh, input.channels, mls_tools::lower_extension(s.output) == ".ply");
  if(!output.stream()) throw Input_error("error while writing '" + s.output + "'");
  output.commit();

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string removed = (report.off_surface_polylines == 0 ? std::string()
                               : ", " + std::to_string(report.off_surface_polylines) + " polylines off the surface dropped") +
                              (report.removed_components == 0 ? std::string()
                              : ", " + std::to_string(report.removed_components) + " unsupported component(s) removed (away from the data or smaller than a facet)");
  const std::string closure = closed ? "closed"
                              : s.open ? "open (" + std::to_string(report.boundary_cycles) + " boundary cycle" +
                                           (report.boundary_cycles == 1 ? ")" : "s)")
                                       : "not closed";
  const std::string input_notes =
    (report.outliers == 0 ? std::string() : " (" + std::to_string(report.outliers) + " outliers removed)") +
    (report.normals_as_one_tree ? " (normals oriented again as one tree: the first orientation left the surface open)"
                                : "");
  const std::string gaps = report.gap_seeds == 0 ? std::string() : ", " + std::to_string(report.gap_seeds) + " in gaps";
  std::fprintf(stderr,
               "%s: %zu points%s, %s/%s, %s, %.2f s (normals %.1f s, seeds %.1f s: %zu of %zu by the operator%s, features "
               "%.1f s: %zu queries, meshing %.1f s), %zu vertices, %zu facets, %zu feature polylines, %zu corners%s%s, %s, %s, "
               "output %s%s\n",
               tool_name, input.size(),
               input_notes.c_str(), name_of(s.op, operator_choices).c_str(),
               name_of(space, space_choices).c_str(), name_of(s.mesher, mesher_choices).c_str(), seconds,
               report.seconds_normals, report.seconds_seeds, report.operator_seeds, report.seeds + report.unblended_seeds + report.failed_seeds, gaps.c_str(),
               report.seconds_features, report.feature_queries, report.seconds_meshing, std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()), report.feature_polylines, report.corners,
               report.features_dropped ? (report.feature_budget_exceeded ? " (not protected: Mesh_3 did not finish with them)" : " (not protected: Mesh_3 failed with them)") : "", removed.c_str(), closure.c_str(), manifold ? "manifold" : "not manifold", s.output.c_str(), written.c_str());
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
  } catch(const std::exception& e) { // e.g. a CGAL precondition: its message spans several lines
    std::string message = e.what();
    for(char& c : message)
      if(c == '\n' || c == '\r') c = ' ';
    std::cerr << tool_name << ": error: " << message << std::endl;
    return 1;
  }
}
