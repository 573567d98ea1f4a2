// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The implicit function as the meshers evaluate it: counted, cancellable, its recent values
// cached per thread.

#ifndef CGAL_MLS_PROJECTION_INTERNAL_MESHING_EVALUATION_MONITOR_H
#define CGAL_MLS_PROJECTION_INTERNAL_MESHING_EVALUATION_MONITOR_H

#include <CGAL/number_utils.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace CGAL {
namespace MLS {
namespace internal {

struct Meshing_cancelled {};

// The state shared by the copies of a monitored function (meshers copy their function).
struct Evaluation_monitor {
  // tells apart the runs in the cache of recent values (a monitor may reuse another's address)
  const std::uint64_t run = next_run();
  std::atomic<std::size_t> count{0};
  std::atomic<bool> stop{false};
  std::thread::id caller = std::this_thread::get_id();
  const std::function<bool(double)>* callback = nullptr;
  double expected = 1e6;
  std::size_t limit = 0;             // 0: none
  std::atomic<bool> limit_hit{false};
  std::atomic<bool> time_hit{false};
  std::atomic<bool> stall_hit{false};
  bool throw_on_stop = false; // Surface_mesher has no stop flag: it is left by an exception

  static std::uint64_t next_run() {
    static std::atomic<std::uint64_t> runs{0};
    return ++runs;
  }
};

// The values of the function at points this thread evaluated in a run, in a direct-mapped table
// indexed by a hash of the coordinates: Mesh_3 evaluates the circumcentre of each new cell to label
// it, then again as an end of each of its facets' dual segments, and the ends of a segment to test
// it for an intersection, then again to construct it, often many thousands of evaluations later:
// 2^18 entries (10 MB) make a quarter fewer evaluations than 2^12 on a 50k-point scan, and more
// entries save little.
struct Recent_values {
  struct Entry {
    std::uint64_t run = 0;
    double x = 0, y = 0, z = 0, value = 0;
  };
  static constexpr int bits = 18;
  std::vector<Entry> entries = std::vector<Entry>(std::size_t(1) << bits);

  static std::size_t slot(double x, double y, double z) {
    std::uint64_t h = 0;
    for(double c : {x, y, z}) {
      std::uint64_t b;
      std::memcpy(&b, &c, sizeof b);
      h = (h ^ b) * 0x9E3779B97F4A7C15ull;
    }
    return std::size_t(h >> (64 - bits));
  }
  const double* find(std::uint64_t run, double x, double y, double z) const {
    const Entry& e = entries[slot(x, y, z)];
    return e.run == run && e.x == x && e.y == y && e.z == z ? &e.value : nullptr;
  }
  void add(std::uint64_t run, double x, double y, double z, double value) {
    entries[slot(x, y, z)] = Entry{run, x, y, z, value};
  }
};

// The function with an evaluation counter and the cancellation poll.
// Its copies share the function and the monitor.
template <class GeomTraits, class Point = typename GeomTraits::Point_3>
struct Monitored_function {
  using FT = typename GeomTraits::FT;
  std::shared_ptr<const std::function<double(const typename GeomTraits::Point_3&)>> function;
  std::shared_ptr<Evaluation_monitor> monitor;

  FT operator()(const Point& p) const { return FT(value(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()))); }

  double value(double x, double y, double z) const {
    thread_local Recent_values recent;
    if(const double* v = recent.find(monitor->run, x, y, z)) return *v;
    const std::size_t c = monitor->count.fetch_add(1, std::memory_order_relaxed) + 1;
    if(c == monitor->limit + 1 && monitor->limit > 0) { // exactly one call sees it
      monitor->limit_hit.store(true, std::memory_order_relaxed);
      monitor->stop.store(true, std::memory_order_release);
    }
    if((c & 1023) == 0 && monitor->callback && *monitor->callback && std::this_thread::get_id() == monitor->caller) {
      if(!(*monitor->callback)(1. - std::exp(-double(c) / monitor->expected)))
        monitor->stop.store(true, std::memory_order_release);
    }
    if(monitor->throw_on_stop && monitor->stop.load(std::memory_order_relaxed)) throw Meshing_cancelled();
    const double v = (*function)(typename GeomTraits::Point_3(x, y, z));
    const double out = std::isfinite(v) ? v : 1.; // a NaN would break the root finding: outside
    recent.add(monitor->run, x, y, z, out);
    return out;
  }
};

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_MESHING_EVALUATION_MONITOR_H
