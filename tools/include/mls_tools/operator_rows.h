// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The projection run of mls_project (a template over the operator) and the operator classes
// behind each row of its operator table: which class implements which function space. Included
// by the operator translation units only (tools/mls_project_<operator>.cpp), each instantiating
// one row template, so that the compilation is spread over several units.

#ifndef MLS_TOOLS_OPERATOR_ROWS_H
#define MLS_TOOLS_OPERATOR_ROWS_H

#include <mls_tools/progress.h>
#include <mls_tools/projection_job.h>

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/interpolate_attributes.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

namespace mls_tools {

using Kernel = CGAL::Simple_cartesian<double>;

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
/// shared sample set and the options) and writes `x y [z] nx ny [nz]` per query, in order,
/// followed by the attributes interpolated at the projection (`interpolate_attributes()`) when
/// the input has some, and `x y [z] dx dy [dz]` to `job.features` per projection on a crease or apex.
template <class Operator>
Projection_outcome run_operator(const Projection_job& job) {
  constexpr int D = Operator::dimension;
  using T = Point_types<D>;
  using Samples = typename Operator::Samples;

  // The sample set reads the input by index.
  std::vector<std::size_t> indices(job.points.size());
  for(std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  const std::size_t channels = job.channels.size();
  const auto point_map = boost::make_function_property_map<std::size_t>([&](std::size_t i) { return T::point(job.points[i]); });
  const auto attribute_map = boost::make_function_property_map<std::size_t>([&](std::size_t i) {
    const auto first = job.attributes.begin() + std::ptrdiff_t(i * channels);
    return std::vector<double>(first, first + std::ptrdiff_t(channels));
  });
  const auto np = CGAL::MLS::parameters::attribute_map(attribute_map).point_map(point_map);
  // The normals only orient the results; the sample set's type does not depend on them.
  const auto shared =
    job.normals ? std::make_shared<const Samples>(indices, np.normal_map(boost::make_function_property_map<std::size_t>(
                                                             [&](std::size_t i) { return T::vector((*job.normals)[i]); })))
                : std::make_shared<const Samples>(indices, np);
  const Operator op(shared, job.options);

  std::vector<typename T::Point> queries;
  queries.reserve(job.queries.size());
  for(const auto& q : job.queries) queries.push_back(T::point(q));

  Projection_outcome outcome;
  outcome.bandwidth = op.bandwidth();
  std::ostream& out = job.out;
  out << std::setprecision(17);
  if(job.features) *job.features << std::setprecision(17);
  const auto write_result = [&](const typename Operator::Result& r, const double* attributes) {
    if(!r.is_success()) ++outcome.failed; // the result keeps the query and has a null normal
    for(int k = 0; k < D; ++k) out << r.point[k] << ' ';
    for(int k = 0; k < D; ++k) out << r.normal[k] << (k + 1 < D ? " " : "");
    for(std::size_t k = 0; attributes && k < channels; ++k) write_attribute(out << ' ', job.channels[k], attributes[k]);
    out << '\n';
    if(r.is_on_feature) {
      ++outcome.on_feature;
      if(job.features) { // the direction is null at an apex (+ 0. writes a -0 as 0)
        for(int k = 0; k < D; ++k) *job.features << r.point[k] << ' ';
        for(int k = 0; k < D; ++k) *job.features << r.feature_direction[k] + 0. << (k + 1 < D ? ' ' : '\n');
      }
    }
  };
  Progress_bar bar("mls_project: projecting", job.show_progress);
  if(channels == 0) {
    // A std::function, because the output iterator must be assignable (a capturing lambda is not).
    const std::function<void(const typename Operator::Result&)> write = [&](const typename Operator::Result& r) {
      write_result(r, nullptr);
    };
    CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(op, queries, boost::make_function_output_iterator(write),
                                                               CGAL::parameters::callback(bar.callback()));
    bar.finish();
    return outcome;
  }
  std::vector<typename Operator::Result> results;
  results.reserve(queries.size());
  CGAL::MLS::project_points<CGAL::Parallel_if_available_tag>(op, queries, std::back_inserter(results),
                                                             CGAL::parameters::callback(bar.callback()));
  bar.finish();
  std::vector<double> values(results.size() * channels);
  CGAL::MLS::internal::for_each_index<CGAL::Parallel_if_available_tag>(0, results.size(), 64, [&](std::size_t i) {
    CGAL::MLS::interpolate_attributes(op, results[i], values.begin() + std::ptrdiff_t(i * channels));
  });
  for(std::size_t i = 0; i < results.size(); ++i) write_result(results[i], values.data() + i * channels);
  return outcome;
}

template <class Operator>
Implementation implementation() {
  return {&run_operator<Operator>, &minimum_points<Operator>};
}

// The rows: one class per function space, in the columns of function_spaces() (plane,
// quadratic, wedge, mixed), empty where the operator cannot use the space. Levin's projection
// and P_S fit a height function over their frame (P_S projects along the frame normal): graph
// spaces only. "quadratic" is Polynomial_function_space (total degree 2) for Levin's projection
// and Paraboloid_function_space (the paper's quadratic space) for the closest-point operators; "mixed" fits both the
// quadratic and the wedge fan and keeps the better (Mixed_projection).

template <int D>
Row levin_row() {
  using namespace CGAL::MLS;
  return {implementation<Levin_projection<Kernel, Plane_function_space<D>>>(),
          implementation<Levin_projection<Kernel, Polynomial_function_space<D>>>(), Implementation(), Implementation()};
}

template <int D>
Row single_phase_row() {
  using namespace CGAL::MLS;
  return {implementation<Single_phase_projection<Kernel, Plane_function_space<D>>>(),
          implementation<Single_phase_projection<Kernel, Paraboloid_function_space<D>>>(), Implementation(),
          Implementation()};
}

/// P_E or P_U, by `kind`.
template <int D, CGAL::MLS::Operator_kind kind>
Row closest_point_row() {
  using namespace CGAL::MLS;
  return {implementation<Closest_point_projection<Kernel, Plane_function_space<D>, kind>>(),
          implementation<Closest_point_projection<Kernel, Paraboloid_function_space<D>, kind>>(),
          implementation<Closest_point_projection<Kernel, Wedge_fan_function_space<D>, kind>>(),
          implementation<Mixed_projection<Kernel, D, kind>>()};
}

} // namespace mls_tools

#endif // MLS_TOOLS_OPERATOR_ROWS_H
