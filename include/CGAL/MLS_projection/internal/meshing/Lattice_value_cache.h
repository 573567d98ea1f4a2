// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Values at the nodes of a regular lattice, computed once and shared by the threads: a value
// depends only on its node, whichever thread computes it first, so that results do not depend
// on the threads. Mutex-guarded shards rather than TBB's concurrent_hash_map: TBB is optional.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_LATTICE_VALUE_CACHE_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_LATTICE_VALUE_CACHE_H

#include <CGAL/MLS_projection/internal/projection/Dimension.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <unordered_map>

namespace CGAL {
namespace MLS {
namespace internal {

class Lattice_value_cache {
public:
  /// Nodes at the integer multiples of `spacing` (positive), at most 2^20 from the origin on each
  /// axis.
  explicit Lattice_value_cache(double spacing) : spacing_(spacing) {}

  double spacing() const { return spacing_; }
  static constexpr double max_index = double(1 << 20);

  /// The value at the node `spacing()` times `i`: `compute(node)` the first time it is asked for.
  /// \pre each |i[j]| < `max_index`
  template <class Compute>
  double value(const std::array<double, 3>& i, Compute&& compute) {
    std::uint64_t key = 0;
    for(int j = 0; j < 3; ++j) key = (key << 21) | std::uint64_t(std::int64_t(i[j]) + (1 << 20));
    Shard& shard = shards_[(key * 0x9E3779B97F4A7C15ull) >> 58];
    {
      std::lock_guard<std::mutex> lock(shard.mutex);
      const auto it = shard.values.find(key);
      if(it != shard.values.end()) return it->second;
    }
    const double v = compute(Vec<3>(spacing_ * i[0], spacing_ * i[1], spacing_ * i[2])); // unlocked: another thread may compute it too
    std::lock_guard<std::mutex> lock(shard.mutex);
    shard.values.emplace(key, v);
    return v;
  }

private:
  struct Shard {
    std::mutex mutex;
    std::unordered_map<std::uint64_t, double> values;
  };
  double spacing_;
  std::array<Shard, 64> shards_;
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_LATTICE_VALUE_CACHE_H
