// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_PROJECT_POINTS_H
#define CGAL_MLS_PROJECTION_PROJECT_POINTS_H

#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <thread>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MLS {

/// \ingroup PkgMLSProjectionFunctions
/// The number of consecutive queries along the Hilbert curve that `project_points()` projects
/// with warm starts, the first one cold.
constexpr std::size_t warm_start_block = 256;

namespace internal {

template <class P, class = void> struct has_warm_start : std::false_type {};
template <class P> struct has_warm_start<P, std::void_t<typename P::Warm_start>> : std::true_type {};

// f(i) for i in [begin, end), in parallel (chunks of `grain`) when the tag asks for it.
template <class ConcurrencyTag, class F>
void for_each_index(std::size_t begin, std::size_t end, std::size_t grain, const F& f) {
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_convertible<ConcurrencyTag, Parallel_tag>::value) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, grain), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i) f(i);
    });
    return;
  }
#endif
  for(std::size_t i = begin; i < end; ++i) f(i);
}

// project_points() for operators with warm starts (see there): `out[i]` is the result of
// `points[i]`. False when the callback cancelled.
template <class ConcurrencyTag, class Projection, class Point>
bool project_warm(const Projection& projection, const std::vector<Point>& points, std::vector<typename Projection::Result>& out,
                  const std::function<bool(double)>& callback) {
  if(points.empty()) return true;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  using Map = Pointer_property_map<Point>;
  using Traits = std::conditional_t<Ambient_dimension<Point>::value == 2, Spatial_sort_traits_adapter_2<Kernel, typename Map::const_type>,
                                    Spatial_sort_traits_adapter_3<Kernel, typename Map::const_type>>;
  // the finite queries along a Hilbert curve (the others fail at once: they go last)
  std::vector<std::size_t> order, invalid;
  order.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    bool finite = true;
    for(int j = 0; j < Ambient_dimension<Point>::value; ++j) finite = finite && std::isfinite(CGAL::to_double(points[i][j]));
    (finite ? order : invalid).push_back(i);
  }
  hilbert_sort(order.begin(), order.end(), Traits(make_property_map(points)));
  order.insert(order.end(), invalid.begin(), invalid.end());

  // One parallel loop over all blocks: a block near creases costs tens of times a smooth one, so
  // a barrier every few blocks would leave threads idle. The callback runs on the calling thread
  // after each block it projected; a cancellation skips the blocks not yet started.
  const std::size_t n = order.size();
  const std::size_t blocks = (n + warm_start_block - 1) / warm_start_block;
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<std::size_t> done{0};
  std::atomic<bool> cancelled{false};
  for_each_index<ConcurrencyTag>(0, blocks, 1, [&](std::size_t b) {
    if(cancelled.load(std::memory_order_relaxed)) return;
    typename Projection::Warm_start warm;
    const std::size_t first = b * warm_start_block, last = (std::min)(n, first + warm_start_block);
    for(std::size_t k = first; k < last; ++k) out[order[k]] = projection.project(points[order[k]], warm);
    const std::size_t finished = done.fetch_add(last - first) + (last - first);
    if(callback && std::this_thread::get_id() == caller && finished < n && !callback(double(finished) / double(n)))
      cancelled.store(true, std::memory_order_relaxed);
  });
  if(cancelled.load()) return false;
  if(callback) callback(1.);
  return true;
}

} // namespace internal

/// \ingroup PkgMLSProjectionFunctions
/// Projects every point of `queries` with `projection` and writes one result per query,
/// in query order, to `results`.
///
/// Operators with warm starts (those with a `Warm_start` type: `Closest_point_projection`,
/// `Mixed_projection`), unless their options' `warm_starts` is `false`, visit the queries along a
/// Hilbert curve in blocks of `warm_start_block` consecutive queries: the first query of a block
/// is projected cold, each next one continues from the fit of the one before (see
/// `Closest_point_projection::project()`). The blocks depend only on the queries, so the results
/// are bit-identical whatever the concurrency tag and the number of threads; a query's result
/// can depend on the other queries (a continued fit can be another local minimum than the cold
/// one, see the manual). Other operators project each query independently.
///
/// The `callback` is called from the calling thread with the fraction done: after each batch of
/// queries, or with warm starts after each block that thread projected.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
/// \param projection any projection operator of this package (e.g. `Levin_projection`)
/// \param queries a range of query points
/// \param results an output iterator accepting `Projection::Result`
/// \param np optional named parameters: `point_map` (the queries' point map, default identity)
///        and `callback` (a `std::function<bool(double)>`; returning `false` cancels)
/// \return `true` when every query was projected, `false` when the callback cancelled (then
///         only the results of the completed batches were written; with warm starts, none)
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
  if constexpr(internal::has_warm_start<Projection>::value) {
    if(projection.options().warm_starts) {
      std::vector<Result> out(n);
      if(!internal::project_warm<ConcurrencyTag>(projection, points, out, callback)) return false;
      std::move(out.begin(), out.end(), results);
      return true;
    }
  }
  const std::size_t batch = 4096;
  std::vector<Result> out;
  for(std::size_t begin = 0; begin < n; begin += batch) {
    const std::size_t end = (std::min)(n, begin + batch);
    out.resize(end - begin);
    internal::for_each_index<ConcurrencyTag>(begin, end, 8, [&](std::size_t i) { out[i - begin] = projection.project(points[i]); });
    results = std::move(out.begin(), out.end(), results);
    if(callback && !callback(double(end) / double(n)) && end < n) return false;
  }
  return true;
}

} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_PROJECT_POINTS_H
