// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Checks of a PLY file made before CGAL 5.5's reader (CGAL::IO::read_PLY) reads it. That reader
// trusts the file: on malformed ones it crashes, hangs or allocates without bound (every case below
// was found by fuzz/fuzz_point_io.cpp). `check_ply_file` refuses such files with an `Input_error`
// that says what is wrong, and lets well-formed files through untouched.

#ifndef MLS_TOOLS_PLY_CHECK_H
#define MLS_TOOLS_PLY_CHECK_H

#include <mls_tools/errors.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mls_tools {
namespace internal {

/// The size in bytes of a PLY scalar type (0 if CGAL's reader does not know it).
inline std::size_t ply_type_size(const std::string& type) {
  if(type == "char" || type == "int8" || type == "uchar" || type == "uint8") return 1;
  if(type == "short" || type == "int16" || type == "ushort" || type == "uint16") return 2;
  if(type == "int" || type == "int32" || type == "uint" || type == "uint32" || type == "float" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

inline bool ply_is_float(const std::string& type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

inline bool ply_is_signed(const std::string& type) {
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
}

/// The largest value of a PLY integer type.
inline unsigned long long ply_max(const std::string& type) {
  const std::size_t bits = 8 * ply_type_size(type) - (ply_is_signed(type) ? 1 : 0);
  return (1ull << bits) - 1;
}

struct Ply_property {
  std::string name;
  std::string type;       ///< a scalar's type, or the type of a list's entries
  std::string count_type; ///< a list's count type; empty for a scalar
  /// whether CGAL's reader knows the types: it skips the others when it reads the items
  bool read() const {
    if(count_type.empty()) return ply_type_size(type) != 0;
    return ply_type_size(count_type) != 0 && !ply_is_float(count_type) && ply_type_size(type) != 0;
  }
};

struct Ply_element {
  std::string name;
  unsigned long long count = 0;
  std::vector<Ply_property> properties;

  bool has_list() const {
    return std::any_of(properties.begin(), properties.end(),
                       [](const Ply_property& p) { return p.read() && !p.count_type.empty(); });
  }
  /// The least number of bytes an item takes: 1 per property in ASCII, the sizes of the scalars
  /// and list counts in binary (the exact size of an item without lists). 0 without properties.
  std::size_t least_bytes(bool binary) const {
    std::size_t bytes = 0;
    for(const Ply_property& p : properties)
      if(p.read()) bytes += binary ? ply_type_size(p.count_type.empty() ? p.type : p.count_type) : 1;
    return bytes;
  }
  bool is_vertex() const { return name == "vertex" || name == "vertices"; }
};

/// Walks the items of the elements up to the last one with a list property, as CGAL's reader will
/// read them, and refuses a list count that the rest of the file cannot hold: CGAL's reader
/// resizes a buffer to the count before it reads the entries (a binary count of about 4e8 made it
/// allocate 3.4 GB, found by the fuzzer). In ASCII every number must be one whole token (CGAL
/// reads with operator>>, which may stop inside a token and so read a later count than this walk
/// checked). A file that ends at a list count is refused (CGAL's reader would take an
/// uninitialised count); one that ends elsewhere is left to CGAL's reader, which fails on it.
class Ply_list_walk {
public:
  Ply_list_walk(const std::string& path, std::istream& is, std::uintmax_t file_size, bool binary, bool big_endian)
      : path_(path), is_(is), file_size_(file_size), binary_(binary), big_endian_(big_endian) {}

  void run(const std::vector<Ply_element>& elements) {
    std::size_t last = elements.size();
    for(std::size_t i = 0; i < elements.size(); ++i)
      if(elements[i].has_list()) last = i;
    if(last == elements.size()) return;
    for(std::size_t i = 0; i <= last; ++i) {
      const Ply_element& e = elements[i];
      if(binary_ && !e.has_list()) { // fixed-size items: skip them at once
        is_.seekg(std::streamoff(e.count * e.least_bytes(true)), std::ios::cur);
        continue;
      }
      for(unsigned long long item = 0; item < e.count; ++item)
        for(const Ply_property& p : e.properties) {
          if(!p.read()) continue;
          if(!(p.count_type.empty() ? skip(p.type, e, item) : list(p, e, item))) return;
        }
    }
  }

private:
  std::string where(const Ply_element& e, unsigned long long item) const {
    return quote(path_) + ": item " + std::to_string(item) + " of the PLY element " + quote(e.name);
  }

  /// Reads one number of `type`; false at the end of the file.
  bool number(const std::string& type, const Ply_element& e, unsigned long long item, long long* value) {
    if(binary_) {
      unsigned char b[8];
      const std::size_t size = ply_type_size(type);
      if(!is_.read(reinterpret_cast<char*>(b), std::streamsize(size))) return false;
      if(value) {
        unsigned long long u = 0;
        for(std::size_t k = 0; k < size; ++k) u |= (unsigned long long)(b[big_endian_ ? k : size - 1 - k]) << (8 * (size - 1 - k));
        const bool negative = ply_is_signed(type) && (u >> (8 * size - 1)) != 0;
        *value = negative ? (long long)(u) - (long long)(1ull << (8 * size - 1)) * 2 : (long long)(u);
      }
      return true;
    }
    std::string token;
    if(!(is_ >> token)) return false;
    if(!is_whole_number(token, ply_is_float(type)))
      throw Input_error(where(e, item) + ": " + quote(token.substr(0, 40)) + " is not a " +
                        (ply_is_float(type) ? "number" : "whole number"));
    if(value) {
      errno = 0;
      const unsigned long long u = std::strtoull(token.c_str() + (token[0] == '+' ? 1 : 0), nullptr, 10);
      *value = (token[0] == '-') ? -1 : (errno == ERANGE || u > ply_max(type)) ? -2 : (long long)(u);
    }
    return true;
  }

  bool skip(const std::string& type, const Ply_element& e, unsigned long long item) {
    return number(type, e, item, nullptr);
  }

  bool list(const Ply_property& p, const Ply_element& e, unsigned long long item) {
    long long n = 0;
    // CGAL's reader would resize the list to an uninitialised count (4.7 GB, found by the fuzzer)
    if(!number(p.count_type, e, item, &n))
      throw Input_error(where(e, item) + ": the file ends before the count of the list " + quote(p.name) + " (truncated file?)");
    if(n < 0)
      throw Input_error(where(e, item) + ": the count of the list " + quote(p.name) + " is " +
                        (n == -2 ? "too large for its type " + p.count_type : "negative"));
    // the least bytes the entries take; in ASCII a separator and a digit each
    const unsigned long long bytes = (unsigned long long)(n) * (binary_ ? ply_type_size(p.type) : 2);
    const auto position = bytes > 4096 ? is_.tellg() : std::streampos(0); // small lists: no tellg
    const std::uintmax_t rest = position < 0 ? 0 : file_size_ - std::uintmax_t(position);
    if(bytes > 4096 && bytes > rest)
      throw Input_error(where(e, item) + ": the list " + quote(p.name) + " declares " + std::to_string(n) +
                        " entries, more than the " + std::to_string(rest) + " bytes left in the file can hold");
    if(binary_) {
      is_.seekg(std::streamoff(bytes), std::ios::cur);
      return bool(is_);
    }
    for(long long k = 0; k < n; ++k)
      if(!skip(p.type, e, item)) return false;
    return true;
  }

  /// Whether operator>> reads all of `token` as one number: [+-]digits, or for a floating-point
  /// type [+-](digits[.digits]|.digits)([eE][+-]digits).
  static bool is_whole_number(const std::string& token, bool floating) {
    std::size_t i = (token[0] == '+' || token[0] == '-') ? 1 : 0;
    const auto digits = [&token, &i]() {
      const std::size_t start = i;
      while(i < token.size() && std::isdigit(static_cast<unsigned char>(token[i]))) ++i;
      return i - start;
    };
    std::size_t mantissa = digits();
    if(!floating) return mantissa > 0 && i == token.size();
    if(i < token.size() && token[i] == '.') {
      ++i;
      mantissa += digits();
    }
    if(mantissa == 0) return false;
    if(i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
      ++i;
      if(i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
      if(digits() == 0) return false;
    }
    return i == token.size();
  }

  const std::string& path_;
  std::istream& is_;
  std::uintmax_t file_size_;
  bool binary_, big_endian_;
};

/// Checks what CGAL 5.5's PLY reader does not, before it reads `path`:
///  - a `property` line before any `element` line makes it call back() on an empty vector
///    (a segmentation fault);
///  - a property name repeated in an element with another type, or vertex coordinates and normals
///    that are not all float or all double, make it dereference a null pointer: both are refused;
///  - it accepts a header without `end_header` (and returns its vertices at the origin);
///  - several vertex elements trip one of its assertions;
///  - it reserves memory for every declared item before reading any: an element count that the
///    rest of the file cannot hold (`Ply_element::least_bytes`, at least 1) is refused;
///  - it resizes a buffer to each list count it reads: see `Ply_list_walk`.
/// A file whose first line is not `ply` is left to CGAL's reader, which says it is not PLY.
inline void check_ply_file(const std::string& path) {
  std::ifstream is(path, std::ios::in | std::ios::binary);
  std::vector<Ply_element> elements;
  bool binary = false, big_endian = false, has_end = false;
  std::string line;
  for(std::size_t line_number = 1; std::getline(is, line); ++line_number) {
    std::istringstream iss(line);
    std::string keyword;
    iss >> keyword;
    if(line_number == 1) {
      if(keyword != "ply") return;
      continue;
    }
    if(line_number == 2) { // "format <ascii|binary_*> 1.0", checked by CGAL's reader
      std::string format;
      iss >> format;
      binary = format.rfind("binary", 0) == 0;
      big_endian = format == "binary_big_endian";
      continue;
    }
    const std::string where = quote(path) + ", line " + std::to_string(line_number) + " of the PLY header: ";
    if(keyword == "end_header") {
      has_end = true;
      break;
    } else if(keyword == "element") {
      Ply_element e;
      if(iss >> e.name >> e.count) elements.push_back(e);
    } else if(keyword == "property") {
      if(elements.empty()) throw Input_error(where + "a property before any element");
      Ply_property p;
      iss >> p.type;
      if(p.type == "list") iss >> p.count_type >> p.type;
      iss >> p.name;
      if(p.type == "float32") p.type = "float";
      if(p.type == "float64") p.type = "double";
      auto& properties = elements.back().properties;
      if(std::any_of(properties.begin(), properties.end(), [&p](const Ply_property& q) { return q.name == p.name; }))
        throw Input_error(where + "property " + quote(p.name) + " appears twice in element " + quote(elements.back().name));
      properties.push_back(p);
    }
  }
  if(!has_end) throw Input_error(quote(path) + ": the PLY header has no end_header line (truncated file?)");
  if(std::count_if(elements.begin(), elements.end(), [](const Ply_element& e) { return e.is_vertex(); }) > 1)
    throw Input_error(quote(path) + ": the PLY header declares more than one vertex element");
  for(const Ply_element& e : elements) {
    if(!e.is_vertex()) continue;
    // CGAL reads x, y, z (and nx, ny, nz when all three exist) all as float if one of x, y, z is
    // a float, else all as double, and dereferences a null pointer when one has another type
    const auto type_of = [&e](const char* name) -> std::string {
      for(const Ply_property& p : e.properties)
        if(p.name == name) return p.count_type.empty() ? p.type : "list";
      return std::string();
    };
    std::vector<const char*> names = {"x", "y", "z"};
    if(!type_of("nx").empty() && !type_of("ny").empty() && !type_of("nz").empty())
      names.insert(names.end(), {"nx", "ny", "nz"});
    bool has_float = false;
    for(const char* n : {"x", "y", "z"}) has_float = has_float || type_of(n) == "float";
    const std::string expected = has_float ? "float" : "double";
    for(const char* n : names) {
      const std::string t = type_of(n);
      if(!t.empty() && t != expected)
        throw Input_error(quote(path) + ": the PLY vertex property " + quote(n) + " is a " + t + ", but x, y, z" +
                          (names.size() > 3 ? ", nx, ny, nz" : "") + " must all be float or all double");
    }
  }
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if(ec) return;
  // a file that ends with "end_header" without a newline has no data (CGAL's reader then takes
  // an uninitialised list count, found by the fuzzer); tellg() would fail at the end of the file
  const std::streamoff header_end = is.eof() ? std::streamoff(file_size) : std::streamoff(is.tellg());
  if(header_end < 0) return;
  is.clear();
  is.seekg(header_end);
  const long double available = (long double)(file_size) - (long double)(header_end);
  long double needed = 0;
  for(const Ply_element& e : elements) {
    // at least 1 byte per item: CGAL's reader loops over the items of an element without
    // properties too (a count of -7, read as 2^64 - 7, made it hang)
    needed += (long double)(e.count) * (long double)(std::max<std::size_t>(1, e.least_bytes(binary)));
    if(needed > available)
      throw Input_error(quote(path) + ": the PLY header declares " + std::to_string(e.count) + " '" + e.name +
                        "' items, more than the " + std::to_string((long long)(available)) +
                        " bytes after the header can hold (truncated file?)");
  }
  Ply_list_walk(path, is, file_size, binary, big_endian).run(elements);
}

} // namespace internal
} // namespace mls_tools

#endif // MLS_TOOLS_PLY_CHECK_H
