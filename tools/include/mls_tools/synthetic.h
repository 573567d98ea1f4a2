// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Built-in inputs of the command-line tools, sampled deterministically: the same points on every
// platform and compiler (own uniform and Gaussian variates from std::mt19937_64, whose output is
// specified by the standard, unlike the std distributions).

#ifndef MLS_TOOLS_SYNTHETIC_H
#define MLS_TOOLS_SYNTHETIC_H

#include <mls_tools/point_io.h>

#include <CGAL/number_type_config.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace mls_tools {

/// A reproducible random source.
class Random {
public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  /// Standard normal variate (Box-Muller; the second variate is dropped for simplicity).
  double gaussian() {
    const double u = 1. - uniform(); // in (0, 1]
    const double v = uniform();
    return std::sqrt(-2. * std::log(u)) * std::cos(2. * CGAL_PI * v);
  }

private:
  std::mt19937_64 engine_;
};

/// `n` points uniformly distributed (by area) on the torus of axis z with radii `R` (centre of
/// the tube) and `r` (tube), each moved by isotropic Gaussian noise of standard deviation
/// `sigma`, with the exact unit normals of their unperturbed positions (pointing outwards).
inline Point_cloud noisy_torus(std::size_t n = 20000, double R = 1., double r = 0.4, double sigma = 0.005,
                               std::uint64_t seed = 20260101) {
  Random random(seed);
  Point_cloud cloud;
  cloud.dimension = 3;
  cloud.has_normals = true;
  cloud.points.reserve(n);
  cloud.normals.reserve(n);
  while(cloud.points.size() < n) {
    const double u = 2. * CGAL_PI * random.uniform(); // around the axis
    const double v = 2. * CGAL_PI * random.uniform(); // around the tube
    // The area element is proportional to R + r cos v: rejection sampling.
    if(random.uniform() * (R + r) > R + r * std::cos(v)) continue;
    const double nx = std::cos(v) * std::cos(u), ny = std::cos(v) * std::sin(u), nz = std::sin(v);
    const double x = R * std::cos(u) + r * nx + sigma * random.gaussian();
    const double y = R * std::sin(u) + r * ny + sigma * random.gaussian();
    const double z = r * nz + sigma * random.gaussian();
    cloud.points.push_back({x, y, z});
    cloud.normals.push_back({nx, ny, nz});
  }
  return cloud;
}

} // namespace mls_tools

#endif // MLS_TOOLS_SYNTHETIC_H
