// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_project: the rows of Levin's projection P_L (own translation unit, see projection_job.h).

#include <mls_tools/operator_rows.h>

mls_tools::Operator_rows mls_tools::levin_rows() { return {levin_row<2>(), levin_row<3>()}; }
