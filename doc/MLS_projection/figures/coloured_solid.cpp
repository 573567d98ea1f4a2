// Writes mls_mesh's built-in solid (11810 points, without normals: both methods of the figure
// estimate them) as an ASCII PLY file with a colour per point, the "normal map" colouring of CAD viewers, 255 (1 + n) / 2: each
// planar face has its own colour, which changes abruptly at the sharp edges and smoothly over the
// fillet and the bore. The input of the manual's colour figure (scripts/figures).
//
//   coloured_solid OUT.ply

#include <mls_tools/builtin_solid.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

int main(int argc, char** argv) {
  if(argc != 2) {
    std::cerr << "usage: coloured_solid OUT.ply" << std::endl;
    return 2;
  }
  const mls_tools::Point_cloud solid = mls_tools::builtin_solid_points();
  std::ofstream os(argv[1]);
  os << "ply\nformat ascii 1.0\nelement vertex " << solid.size() << "\n";
  for(const char* p : {"x", "y", "z"}) os << "property double " << p << "\n";
  for(const char* p : {"red", "green", "blue"}) os << "property uchar " << p << "\n";
  os << "end_header\n" << std::setprecision(17);
  for(std::size_t i = 0; i < solid.size(); ++i) {
    const auto& p = solid.points[i];
    const auto& n = solid.normals[i];
    os << p[0] << ' ' << p[1] << ' ' << p[2];
    for(int k = 0; k < 3; ++k) os << ' ' << std::lround(127.5 * (1. + n[k]));
    os << '\n';
  }
  return os ? 0 : 1;
}
