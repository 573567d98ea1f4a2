// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_FROM_TAG_H
#define CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_FROM_TAG_H

#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/Operator_tags.h>
#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Sample_set.h>

#include <memory>
#include <utility>

namespace CGAL {
namespace MLS {
namespace internal {

/// The projection operator selected by a tag of <CGAL/MLS_projection/Operator_tags.h>.
template <class K, class Space>
Levin_projection<K, Space> make_operator(Levin_operator_tag<Space>, std::shared_ptr<const Sample_set<K, 3>> samples,
                                         const Projection_options& options) {
  static_assert(!has_sharp_features<Space>::value, "Levin_operator_tag: Levin's operator fits graphs (plane, polynomial)");
  return Levin_projection<K, Space>(std::move(samples), options);
}
template <class K, class Space>
Unified_projection<K, Space> make_operator(Unified_operator_tag<Space>, std::shared_ptr<const Sample_set<K, 3>> samples,
                                           const Projection_options& options) {
  return Unified_projection<K, Space>(std::move(samples), options);
}
template <class K>
Mixed_projection<K, 3> make_operator(Mixed_operator_tag, std::shared_ptr<const Sample_set<K, 3>> samples,
                                     const Projection_options& options) {
  return Mixed_projection<K, 3>(std::move(samples), options);
}

} // namespace internal
} // namespace MLS
} // namespace CGAL

#endif // CGAL_MLS_PROJECTION_INTERNAL_PROJECTION_OPERATOR_FROM_TAG_H
