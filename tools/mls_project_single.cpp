// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mls_project: the rows of the single-phase projection P_S (own translation unit, see projection_job.h).

#include <mls_tools/operator_rows.h>

mls_tools::Operator_rows mls_tools::single_phase_rows() { return {single_phase_row<2>(), single_phase_row<3>()}; }
