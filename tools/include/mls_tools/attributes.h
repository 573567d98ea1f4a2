// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Per-point attributes of the tools' inputs and outputs: named scalar channels (PLY vertex
// properties such as red, green, blue, alpha, intensity, quality), stored as doubles and written
// back in their PLY type (integer types rounded and clamped to their range).

#ifndef MLS_TOOLS_ATTRIBUTES_H
#define MLS_TOOLS_ATTRIBUTES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace mls_tools {

/// One scalar channel: its PLY property name and type (char, uchar, short, ushort, int, uint,
/// float or double).
struct Attribute_channel {
  std::string name;
  std::string type;
};
using Attribute_channels = std::vector<Attribute_channel>;

/// The smallest and largest values of an integer PLY type (false for float and double).
inline bool integer_range(const std::string& type, double& low, double& high) {
  if(type == "char") { low = -128; high = 127; }
  else if(type == "uchar") { low = 0; high = 255; }
  else if(type == "short") { low = -32768; high = 32767; }
  else if(type == "ushort") { low = 0; high = 65535; }
  else if(type == "int") { low = -2147483648.; high = 2147483647.; }
  else if(type == "uint") { low = 0; high = 4294967295.; }
  else return false;
  return true;
}

/// Writes `value` as a value of `channel`'s type.
inline void write_attribute(std::ostream& os, const Attribute_channel& channel, double value) {
  double low = 0, high = 0;
  if(integer_range(channel.type, low, high))
    os << static_cast<long long>(std::clamp(std::round(value), low, high));
  else
    os << value;
}

/// The `property TYPE NAME` lines of a PLY header for the channels.
inline void write_ply_properties(std::ostream& os, const Attribute_channels& channels) {
  for(const auto& c : channels) os << "property " << c.type << ' ' << c.name << '\n';
}

/// Whether the channels are colours only: red, green, blue (and alpha), all uchar, in that order
/// (what an OFF file's COFF variant holds).
inline bool are_colours_only(const Attribute_channels& channels) {
  static const char* const names[] = {"red", "green", "blue", "alpha"};
  if(channels.size() != 3 && channels.size() != 4) return false;
  for(std::size_t i = 0; i < channels.size(); ++i)
    if(channels[i].name != names[i] || channels[i].type != "uchar") return false;
  return true;
}

} // namespace mls_tools

#endif // MLS_TOOLS_ATTRIBUTES_H
