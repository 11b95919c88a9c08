/// @file towgeom.hpp
/// @brief The whole public API of towgeom in one include.
///
/// @mainpage towgeom
/// towgeom turns the interpenetrating tows exported by textile simulators into exact NURBS
/// surfaces and compatible finite-element meshes. Start with readStackFile() and
/// TowSurface::fit(); every failure is a towgeom::Error.
#pragma once

#include "towgeom/bezier_extraction.hpp"
#include "towgeom/cell.hpp"
#include "towgeom/collision.hpp"
#include "towgeom/cross_section.hpp"
#include "towgeom/curve3.hpp"
#include "towgeom/error.hpp"
#include "towgeom/fit_options.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/intersection_options.hpp"
#include "towgeom/intersection_report_json.hpp"
#include "towgeom/surface_mesher.hpp"
#include "towgeom/progress.hpp"
#include "towgeom/mesh_export.hpp"
#include "towgeom/mesh_options.hpp"
#include "towgeom/point.hpp"
#include "towgeom/report.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/knot_span_classification.hpp"
#include "towgeom/trimmed_brep.hpp"
#include "towgeom/nurbs_offset.hpp"
#include "towgeom/placement_surface.hpp"
#include "towgeom/tow_ribbon.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/mesh_tows.hpp"
#include "towgeom/method_comparison.hpp"
#include "towgeom/connect_regions.hpp"
#include "towgeom/shrink_tows.hpp"
#include "towgeom/stack_reader.hpp"
#include "towgeom/stl_writer.hpp"
#include "towgeom/textile_io.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/triangle_mesh.hpp"
#include "towgeom/version.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/vtk_writer.hpp"
#include "towgeom/weave.hpp"
#include "towgeom/yarn_path.hpp"
