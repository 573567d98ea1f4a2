// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The baseline of the benchmark: PCL's moving least squares (pcl::MovingLeastSquares, the MLS
// that most users of point clouds run), as a user runs it: polynomial order 2, the default
// Gaussian weight (its parameter the squared search radius), normals computed, on the points
// of an .xyz file. Used by the benchmark only, never by the package.
//
//   pcl_mls IN.xyz OUT.xyz RADIUS [THREADS]
//
// Writes "x y z nx ny nz" per output point and prints the seconds of the library call.

#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/mls.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
  if(argc < 4) {
    std::cerr << "usage: pcl_mls IN.xyz OUT.xyz RADIUS [THREADS]\n";
    return 2;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  std::ifstream in(argv[1]);
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream s(line);
    double x, y, z;
    if(s >> x >> y >> z) cloud->push_back(pcl::PointXYZ(float(x), float(y), float(z)));
  }
  if(cloud->empty()) {
    std::cerr << "pcl_mls: no point in " << argv[1] << "\n";
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::MovingLeastSquares<pcl::PointXYZ, pcl::PointNormal> mls;
  mls.setComputeNormals(true);
  mls.setInputCloud(cloud);
  mls.setPolynomialOrder(2);
  mls.setSearchMethod(tree);
  mls.setSearchRadius(std::atof(argv[3]));
  mls.setNumberOfThreads(argc > 4 ? unsigned(std::atoi(argv[4])) : 1u);
  pcl::PointCloud<pcl::PointNormal> out;
  mls.process(out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream o(argv[2]);
  o.precision(9);
  for(const auto& p : out) o << p.x << ' ' << p.y << ' ' << p.z << ' ' << p.normal_x << ' ' << p.normal_y << ' ' << p.normal_z << '\n';
  std::printf("pcl_mls: %zu points, %zu projected, %.4f s\n", cloud->size(), out.size(), seconds);
  return o ? 0 : 1;
}
