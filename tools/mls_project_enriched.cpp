// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_project: the rows of the enriched projection P_E (own translation unit, see projection_job.h).

#include <mls_tools/operator_rows.h>

mls_tools::Operator_rows mls_tools::enriched_rows() {
  using CGAL::MLS::Operator_kind;
  return {closest_point_row<2, Operator_kind::ENRICHED>(), closest_point_row<3, Operator_kind::ENRICHED>()};
}
