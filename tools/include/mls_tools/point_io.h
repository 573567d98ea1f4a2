// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Reading point files for the command-line tools, in 2D or 3D, with optional normals:
//  - .xyz: 2, 3, 4 (2D + normal) or 6 (3D + normal) numbers per line; .pwn: 6 (3D + normal).
//    Blank lines and lines starting with '#' are skipped. These are read by our own strict
//    parser, because CGAL's XYZ reader knows no 2D points and silently skips lines it cannot
//    parse: here every malformed line is an error that names its line number.
//  - .ply and .off: vertices only (faces are ignored), always 3D, with CGAL's readers
//    (CGAL::IO::read_PLY, CGAL::IO::read_OFF into a CGAL::Point_set_3); normals when present.
//  - attributes: a .ply file's other scalar vertex properties (red, green, blue, alpha,
//    intensity, ...), and a .pwn file's columns after the sixth (named value1, value2, ...;
//    an .xyz file's columns are not: 6 numbers are a point and its normal).
//    A .ply file is checked first (ply_check.h): CGAL's reader trusts malformed files.
// Every error is an `Input_error` (or a `Usage_error` for an unknown extension) with a one-line
// message. `check_point_cloud` rejects sets no MLS operator can work on.

#ifndef MLS_TOOLS_POINT_IO_H
#define MLS_TOOLS_POINT_IO_H

#include <mls_tools/arguments.h>
#include <mls_tools/attributes.h>
#include <mls_tools/errors.h>
#include <mls_tools/ply_check.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mls_tools {

/// Points (and optional normals) read from a file. In 2D the third coordinates are 0.
struct Point_cloud {
  int dimension = 0; ///< 2 or 3
  bool has_normals = false;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<double, 3>> normals; ///< empty, or one per point
  Attribute_channels channels;                 ///< the attribute channels (often none)
  std::vector<double> attributes;              ///< `channels.size()` values per point
  std::size_t size() const { return points.size(); }
};

enum class Point_format { XYZ, PWN, PLY, OFF };

/// The extension of `path` in lower case, with its dot ("" if none).
inline std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// The format of a point file from its extension. \throws Usage_error for an unknown one.
inline Point_format point_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if(ext == ".xyz") return Point_format::XYZ;
  if(ext == ".pwn") return Point_format::PWN;
  if(ext == ".ply") return Point_format::PLY;
  if(ext == ".off") return Point_format::OFF;
  throw Usage_error("unknown extension '" + ext + "' of '" + path + "' (expected .xyz, .pwn, .ply or .off)");
}

namespace internal {

/// Opens `path` for reading; refuses directories, missing and empty files.
inline std::ifstream open_point_file(const std::string& path, std::ios::openmode mode = std::ios::in) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if(!fs::exists(status)) throw Input_error("cannot open " + quote(path) + ": no such file");
  if(fs::is_directory(status)) throw Input_error("cannot read " + quote(path) + ": it is a directory");
  std::ifstream is(path, mode);
  if(!is) throw Input_error("cannot open " + quote(path) + ": " + std::strerror(errno));
  if(fs::is_regular_file(status) && fs::file_size(path, ec) == 0) throw Input_error(quote(path) + " is empty");
  return is;
}

/// Our strict .xyz/.pwn parser (see the top of this file for why not CGAL's).
inline Point_cloud read_xyz(const std::string& path, bool is_pwn) {
  std::ifstream is = open_point_file(path);
  Point_cloud cloud;
  std::size_t columns = 0, line_number = 0;
  std::string line;
  std::vector<double> values;
  while(std::getline(is, line)) {
    ++line_number;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    std::size_t i = 0;
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while(i < line.size() && is_space(line[i])) ++i;
    if(i == line.size() || line[i] == '#') continue;
    values.clear();
    while(i < line.size()) {
      std::size_t j = i;
      while(j < line.size() && !is_space(line[j])) ++j;
      const std::string token = line.substr(i, j - i);
      double v = 0;
      const Number_parse parsed = parse_number(token, v);
      if(parsed == Number_parse::NOT_FINITE) throw Input_error(where + "non-finite number " + quote(token));
      if(parsed != Number_parse::OK) throw Input_error(where + "cannot parse " + quote(token) + " as a number");
      values.push_back(v);
      i = j;
      while(i < line.size() && is_space(line[i])) ++i;
    }
    if(columns == 0) {
      columns = values.size();
      if(is_pwn ? columns < 6 : (columns != 2 && columns != 3 && columns != 4 && columns != 6))
        throw Input_error(where + "found " + std::to_string(columns) + " numbers, expected " +
                          (is_pwn ? "at least 6 (x y z nx ny nz, then attributes)"
                                  : "2 (x y), 3 (x y z), 4 (x y nx ny) or 6 (x y z nx ny nz)"));
      for(std::size_t k = 6; is_pwn && k < columns; ++k) cloud.channels.push_back({"value" + std::to_string(k - 5), "double"});
      cloud.dimension = (columns == 2 || columns == 4) ? 2 : 3;
      cloud.has_normals = (columns == 4 || columns == 6);
    } else if(values.size() != columns) {
      throw Input_error(where + "found " + std::to_string(values.size()) + " numbers, but the first point has " +
                        std::to_string(columns));
    }
    const int D = cloud.dimension;
    std::array<double, 3> p{0., 0., 0.}, n{0., 0., 0.};
    for(int k = 0; k < D; ++k) p[k] = values[k];
    cloud.points.push_back(p);
    if(cloud.has_normals) {
      for(int k = 0; k < D; ++k) n[k] = values[D + k];
      cloud.normals.push_back(n);
    }
    cloud.attributes.insert(cloud.attributes.end(), values.begin() + std::min<std::size_t>(values.size(), 2 * D), values.end());
  }
  if(is.bad()) throw Input_error("error while reading " + quote(path));
  if(cloud.points.empty()) throw Input_error(quote(path) + " contains no points");
  return cloud;
}

/// Silences std::cerr (CGAL's readers print their diagnostics there) and keeps its text.
class Capture_cerr {
public:
  Capture_cerr() : old_(std::cerr.rdbuf(buffer_.rdbuf())) {}
  ~Capture_cerr() { std::cerr.rdbuf(old_); }
  /// The first non-empty line printed, or "".
  std::string first_line() const {
    std::istringstream is(buffer_.str());
    std::string line;
    while(std::getline(is, line))
      if(!line.empty()) return line;
    return std::string();
  }

private:
  std::ostringstream buffer_;
  std::streambuf* old_;
};

/// The number of vertices declared by the header of an OFF file (-1 if it cannot be read).
inline long declared_off_vertices(const std::string& path) {
  std::ifstream is(path);
  std::string line, word;
  int significant = 0;
  while(std::getline(is, line)) {
    if(line.empty() || line[0] == '#') continue; // as CGAL's reader does
    std::istringstream iss(line);
    if(++significant == 1) {
      iss >> word; // the signature
      long n;
      if(iss >> n) return n; // "OFF n f e" on one line
    } else {
      long n;
      return (iss >> n) ? n : -1;
    }
  }
  return -1;
}

/// The PLY type name of a property of a `Point_set_3` read from PLY ("" when not a number).
template <class T> const char* ply_type_name();
template <> inline const char* ply_type_name<std::int8_t>() { return "char"; }
template <> inline const char* ply_type_name<std::uint8_t>() { return "uchar"; }
template <> inline const char* ply_type_name<std::int16_t>() { return "short"; }
template <> inline const char* ply_type_name<std::uint16_t>() { return "ushort"; }
template <> inline const char* ply_type_name<std::int32_t>() { return "int"; }
template <> inline const char* ply_type_name<std::uint32_t>() { return "uint"; }
template <> inline const char* ply_type_name<float>() { return "float"; }
template <> inline const char* ply_type_name<double>() { return "double"; }

/// Appends the property `name` of `set` to the cloud's channels and its values to `values` (one
/// vector per channel) when its type is `T`; true when it is.
template <class T, class Set>
bool read_channel(const Set& set, const std::string& name, Point_cloud& cloud, std::vector<std::vector<double>>& values) {
  const auto found = set.template property_map<T>(name);
  if(!found.second) return false;
  cloud.channels.push_back({name, ply_type_name<T>()});
  values.emplace_back();
  for(auto it = set.begin(); it != set.end(); ++it) values.back().push_back(static_cast<double>(get(found.first, *it)));
  return true;
}

/// The scalar properties of a point set read from PLY, other than the point and its normal.
template <class Set>
void read_channels(const Set& set, Point_cloud& cloud) {
  std::vector<std::vector<double>> values;
  for(const std::string& name : set.properties()) {
    if(name == "index" || name == "point" || name == "normal") continue;
    read_channel<std::int8_t>(set, name, cloud, values) || read_channel<std::uint8_t>(set, name, cloud, values) ||
      read_channel<std::int16_t>(set, name, cloud, values) || read_channel<std::uint16_t>(set, name, cloud, values) ||
      read_channel<std::int32_t>(set, name, cloud, values) || read_channel<std::uint32_t>(set, name, cloud, values) ||
      read_channel<float>(set, name, cloud, values) || read_channel<double>(set, name, cloud, values);
  }
  cloud.attributes.reserve(values.size() * set.size());
  for(std::size_t i = 0; i < set.size(); ++i)
    for(const auto& channel : values) cloud.attributes.push_back(channel[i]);
}

/// .ply and .off, with CGAL's readers.
inline Point_cloud read_with_cgal(const std::string& path, Point_format format) {
  using Kernel = CGAL::Simple_cartesian<double>;
  std::ifstream is = open_point_file(path, std::ios::in | std::ios::binary);
  if(format == Point_format::PLY) check_ply_file(path);
  CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> set;
  bool ok = false;
  std::string diagnostic;
  {
    Capture_cerr capture;
    try {
      ok = (format == Point_format::PLY) ? CGAL::IO::read_PLY(is, set) : CGAL::IO::read_OFF(is, set);
    } catch(const std::exception& e) {
      ok = false;
      diagnostic = e.what(); // CGAL's assertion messages span lines: keep the messages one line
      std::replace(diagnostic.begin(), diagnostic.end(), '\n', ' ');
    }
    if(diagnostic.empty()) diagnostic = capture.first_line();
  }
  const std::string name = format == Point_format::PLY ? "PLY" : "OFF";
  if(!ok) throw Input_error("cannot read " + quote(path) + " as " + name + (diagnostic.empty() ? "" : " (" + diagnostic + ")"));
  if(format == Point_format::OFF) {
    // CGAL's OFF reader skips vertex lines it cannot parse: compare with the declared count.
    const long declared = declared_off_vertices(path);
    if(declared >= 0 && std::size_t(declared) != set.size())
      throw Input_error(quote(path) + ": the OFF header declares " + std::to_string(declared) + " vertices, but " +
                        std::to_string(set.size()) + " could be read");
  }
  if(set.empty()) throw Input_error(quote(path) + " contains no points");
  Point_cloud cloud;
  cloud.dimension = 3;
  cloud.has_normals = set.has_normal_map();
  for(auto it = set.begin(); it != set.end(); ++it) {
    const auto& p = set.point(*it);
    cloud.points.push_back({p.x(), p.y(), p.z()});
    if(cloud.has_normals) {
      const auto& n = set.normal(*it);
      cloud.normals.push_back({n.x(), n.y(), n.z()});
    }
  }
  for(std::size_t i = 0; i < cloud.size(); ++i)
    for(int k = 0; k < 3; ++k)
      if(!std::isfinite(cloud.points[i][k]) || (cloud.has_normals && !std::isfinite(cloud.normals[i][k])))
        throw Input_error(quote(path) + ": vertex " + std::to_string(i + 1) + " has a non-finite coordinate");
  if(format == Point_format::PLY) read_channels(set, cloud);
  for(std::size_t i = 0; i < cloud.attributes.size(); ++i)
    if(!std::isfinite(cloud.attributes[i]))
      throw Input_error(quote(path) + ": vertex " + std::to_string(i / cloud.channels.size() + 1) + " has a non-finite " +
                        cloud.channels[i % cloud.channels.size()].name);
  return cloud;
}

} // namespace internal

/// Reads the points (and normals, when the file has some) of `path`; see the top of this file.
inline Point_cloud read_point_file(const std::string& path) {
  const Point_format format = point_format(path);
  switch(format) {
  case Point_format::XYZ: return internal::read_xyz(path, false);
  case Point_format::PWN: return internal::read_xyz(path, true);
  default: return internal::read_with_cgal(path, format);
  }
}

/// Rejects a set that no MLS operator can work on: fewer than `minimum_points`, all points
/// identical, or (in 3D) all points on one line, judged from a PCA of the whole set.
/// `what` names the set in messages (e.g. the file name).
inline void check_point_cloud(const Point_cloud& cloud, std::size_t minimum_points, const std::string& what) {
  if(cloud.size() < minimum_points)
    throw Input_error(what + " has " + std::to_string(cloud.size()) + " points, too few: the operator needs at least " +
                      std::to_string(minimum_points));
  const int D = cloud.dimension;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for(const auto& p : cloud.points) c += Eigen::Vector3d(p[0], p[1], p[2]);
  c /= double(cloud.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  bool all_equal = true;
  for(const auto& p : cloud.points) {
    all_equal = all_equal && p == cloud.points.front();
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - c;
    C.noalias() += d * d.transpose();
  }
  if(all_equal) throw Input_error(what + ": all points are identical");
  if(D == 3) {
    // The main axis of the PCA; the set is collinear when the largest distance to the line
    // along it is negligible against the spread along it. (Comparing eigenvalues instead fails:
    // the solver's error on the middle one is about eps times the largest.)
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
    const Eigen::Vector3d axis = eig.eigenvectors().col(2); // eigenvalues are ascending
    double along = 0, across = 0;
    for(const auto& p : cloud.points) {
      const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - c;
      const double t = d.dot(axis);
      along = (std::max)(along, std::abs(t));
      across = (std::max)(across, (d - t * axis).norm());
    }
    if(!(across > 1e-10 * along))
      throw Input_error(what + ": all points are collinear; a surface needs points spanning a plane");
  }
}

} // namespace mls_tools

#endif // MLS_TOOLS_POINT_IO_H
