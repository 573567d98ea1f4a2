// Copyright (c) 2026 The CGAL MLS_projection authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Umbrella header of the MLS_projection package: every class and function, the meshing too
// (mls_surface_reconstruction.h, with CGAL's Mesh_3 and Surface_mesher). A unit that only
// projects compiles about a third faster with the headers of the classes it uses.

#ifndef CGAL_MLS_PROJECTION_H
#define CGAL_MLS_PROJECTION_H

#include <CGAL/MLS_projection/Weight_function.h>
#include <CGAL/MLS_projection/Projection_options.h>
#include <CGAL/MLS_projection/Projection_status.h>
#include <CGAL/MLS_projection/Projection_result.h>
#include <CGAL/MLS_projection/parameters.h>
#include <CGAL/MLS_projection/Sample_set.h>
#include <CGAL/MLS_projection/Plane_function_space.h>
#include <CGAL/MLS_projection/Polynomial_function_space.h>
#include <CGAL/MLS_projection/Closest_point.h>
#include <CGAL/MLS_projection/Paraboloid_function_space.h>
#include <CGAL/MLS_projection/Wedge_fan_function_space.h>
#include <CGAL/MLS_projection/Levin_projection.h>
#include <CGAL/MLS_projection/Closest_point_projection.h>
#include <CGAL/MLS_projection/Mixed_projection.h>
#include <CGAL/MLS_projection/project_points.h>
#include <CGAL/MLS_projection/interpolate_attributes.h>
#include <CGAL/MLS_projection/mls_project_point_set.h>
#include <CGAL/MLS_projection/mls_surface_reconstruction.h>

#endif // CGAL_MLS_PROJECTION_H
