// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PROJECT_POINTS_H
#define CGAL_MLS_PROJECTION_PROJECT_POINTS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctions
/// Projects every point of `queries` with `projection` and writes one result per query,
/// in query order, to `results`.
///
/// Each projection is independent and deterministic, so the results are bit-identical whatever
/// the concurrency tag and the number of threads. The queries are processed in batches; after
/// each batch, the `callback` is called from the calling thread with the fraction done.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
/// \param projection any projection operator of this package (e.g. `Levin_projection`)
/// \param queries a range of query points
/// \param results an output iterator accepting `Projection::Result`
/// \param np optional named parameters: `point_map` (the queries' point map, default identity)
///        and `callback` (a `std::function<bool(double)>`; returning `false` cancels)
/// \return `true` when every query was projected, `false` when the callback cancelled
///         (then only the results of the completed batches were written)
template <class ConcurrencyTag, class Projection, class QueryRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
bool project_points(const Projection& projection, const QueryRange& queries, OutputIterator results,
                    const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Value = typename std::iterator_traits<typename QueryRange::const_iterator>::value_type;
  using Result = typename Projection::Result;
  using Point = typename Projection::Point;
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  const auto point_map = choose_parameter(get_parameter(np, internal_np::point_map), Identity_property_map<Value>());
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  std::vector<Point> points;
  points.reserve(std::distance(queries.begin(), queries.end()));
  for(const auto& v : queries) points.push_back(Point(get(point_map, v)));

  const std::size_t n = points.size();
  const std::size_t batch = 4096;
  std::vector<Result> out;
  for(std::size_t begin = 0; begin < n; begin += batch) {
    const std::size_t end = (std::min)(n, begin + batch);
    out.resize(end - begin);
#ifdef CGAL_LINKED_WITH_TBB
    if constexpr(std::is_convertible<ConcurrencyTag, Parallel_tag>::value) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 8), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i) out[i - begin] = projection.project(points[i]);
      });
    } else
#endif
    {
      for(std::size_t i = begin; i < end; ++i) out[i - begin] = projection.project(points[i]);
    }
    results = std::move(out.begin(), out.end(), results);
    if(callback && !callback(double(end) / double(n)) && end < n) return false;
  }
  return true;
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PROJECT_POINTS_H
