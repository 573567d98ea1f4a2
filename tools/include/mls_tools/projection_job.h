// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The interface between the command line of mls_project (tools/mls_project.cpp) and its
// operator translation units (tools/mls_project_<operator>.cpp: one per operator family, so that
// their many template instantiations compile in parallel): what one projection run needs and
// gives back, and, per operator, its implementations per dimension and function space.
// A light header: the operators themselves are in <mls_tools/operator_rows.h>.

#ifndef MLS_TOOLS_PROJECTION_JOB_H
#define MLS_TOOLS_PROJECTION_JOB_H

#include <CGAL/MLS_projection/Projection_options.h>
#include <mls_tools/attributes.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mls_tools {

using Coordinates = std::vector<std::array<double, 3>>; // x y [z], one per point

/// What one projection run needs, whatever the operator.
struct Projection_job {
  const Coordinates& points;
  const Coordinates* normals; // one per point, or null: they only orient the results
  const Attribute_channels& channels;     // the input's attribute channels (often none)
  const std::vector<double>& attributes;  // channels.size() per point
  const Coordinates& queries;
  const CGAL::MLS::Projection_options& options;
  bool show_progress;
  std::ostream& out;       // x y [z] nx ny [nz] [attributes] per query, in order
  std::ostream* features;  // x y [z] dx dy [dz] per projection on a crease or apex, or null
};

struct Projection_outcome {
  std::size_t failed = 0;
  std::size_t on_feature = 0;
  double bandwidth = 0;
};

/// The function spaces of the tool, named as on the command line, with their column in `Row`.
inline const std::vector<std::pair<std::string, int>>& function_spaces() {
  static const std::vector<std::pair<std::string, int>> spaces = {
    {"plane", 0}, {"quadratic", 1}, {"wedge", 2}, {"mixed", 3}};
  return spaces;
}
constexpr std::size_t number_of_spaces = 4;

/// One operator with one function space in one dimension; null members when it cannot use it.
struct Implementation {
  Projection_outcome (*run)(const Projection_job&) = nullptr;
  std::size_t (*minimum_points)() = nullptr; // the fewest input points it accepts
};
using Row = std::array<Implementation, number_of_spaces>; // [column of the space]
using Operator_rows = std::array<Row, 2>;                 // [dimension - 2]

// The rows of each operator, each defined in its own translation unit.
Operator_rows levin_rows();        // tools/mls_project_levin.cpp
Operator_rows single_phase_rows(); // tools/mls_project_single.cpp
Operator_rows enriched_rows();     // tools/mls_project_enriched.cpp
Operator_rows unified_rows();      // tools/mls_project_unified.cpp

} // namespace mls_tools

#endif // MLS_TOOLS_PROJECTION_JOB_H
