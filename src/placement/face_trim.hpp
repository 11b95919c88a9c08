// A tool face's trimming curves as read from its file (OpenCASCADE's face): whether a point of
// the placement surface's (u,v) lies on the face, and which of its edges a point lies on.
#pragma once

#include <BRepTopAdaptor_FClass2d.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include <memory>
#include <string>
#include <vector>

#include "towgeom/placement_surface.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A face whose boundary is not its parameter box: the face itself (its surface and curves as
/// the file gives them) and how PlacementSurface::surface's (u,v) map onto its parameters.
struct FaceTrim {
    TopoDS_Face face;                 ///< the face, FORWARD (its own parameters, unreversed)
    Handle(Geom_Surface) surface;     ///< its surface
    Handle(Geom_Surface) basis;       ///< that surface untrimmed (whose periods its parameters have)
    bool sameParameters = false;      ///< whether the converted surface's (u,v) are the face's (B-spline, Bezier, plane)
    bool reversedU = false;           ///< the placement surface's u runs the other way (u' = uFirst + uLast - u)
    double uFirst = 0.0, uLast = 0.0;  ///< the placement surface's u range (for the reversal)
    double box[4] = {0.0, 0.0, 0.0, 0.0};  ///< the face's (u,v) bounds: u0, u1, v0, v1
    std::vector<TopoDS_Edge> edges;   ///< the edges that bound it (no seams, no degenerate edges), by index
    std::vector<std::size_t> edgeIndex;  ///< each one's index among all the face's edges ("edge K")
    double size = 0.0;                ///< the face's size: its bounding box's diagonal
    /// OpenCASCADE's quick classifier (the face's curves as polygons; near them it asks the
    /// exact classifier itself, "on" within its tolerance, 1e-7 of the box), built once: its
    /// "in" and "out" are taken, its "on" is decided by the exact classifier at 1e-12.
    std::shared_ptr<const BRepTopAdaptor_FClass2d> quick;
};

/// The trimming of @p face, whose surface converted over the face's (u,v) box is
/// @p converted (before any reversal; reversed in u when @p reversed), or null when the face's
/// edges all run along the sides of its box (a natural face: the box is the face).
std::shared_ptr<const FaceTrim> faceTrim(const TopoDS_Face& face, const Handle(Geom_BSplineSurface)& converted, bool reversed);

/// Whether the point of placement parameters @p uv (on @p s, see toolSurface()) lies on the
/// face: OpenCASCADE's quick classifier where it is sure, else its exact face classifier (on the
/// boundary within 1e-12 of the face's (u,v) box counting as on it).
bool insideTrim(const FaceTrim& trim, const Handle(Geom_BSplineSurface)& s, const UV& uv);

/// "edge K" for the bounding edge nearest @p p if it lies within @p tolerance x the face's size
/// of it (beyond the edge's own tolerance, by which its curve on the face, which classified the
/// point, may stray from its 3D curve), else empty.
std::string trimSide(const FaceTrim& trim, const gp_Pnt& p, double tolerance);

}  // namespace detail
TOWGEOM_END_NAMESPACE
