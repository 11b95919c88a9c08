// The face courses are laid on: the tool surface as OpenCASCADE evaluates it (periodic where it
// closes smoothly) and, for a trimmed face, its trimming curves. Where a point is on the face,
// and which side of it a boundary point lies on.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <memory>
#include <string>

#include "placement/face_trim.hpp"
#include "towgeom/nurbs_offset.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A tool face: its surface (see toolSurface()) and its trimming (null: the box is the face).
struct ToolFace {
    Handle(Geom_BSplineSurface) surface;
    std::shared_ptr<const FaceTrim> trim;
};

/// @p surface as a tool face trimmed by @p trim (null: untrimmed).
ToolFace toolFace(const NurbsSurface& surface, std::shared_ptr<const FaceTrim> trim = nullptr);

/// Whether @p uv lies on the face: in the box (in each direction that is not periodic; outside
/// by at most @p slack of the box allowed) and inside its trimming curves.
bool onFace(const ToolFace& f, const UV& uv, double slack = 0.0);

/// The side of the face @p uv lies on, within @p tolerance (of the box's size for its sides, of
/// the face's size for its edges): a box side ("u_min", ...; see boundarySide()) where the face
/// is untrimmed, else "edge K" (K the edge's index among the face's edges) or, where no edge is
/// that near, a box side; empty if none.
std::string faceSide(const ToolFace& f, const UV& uv, double tolerance);

/// The side of the face nearest @p uv: a box side not periodic or, on a trimmed face, the edge
/// it lies on (within 1e-9 of the face), else the box side it lies on, else the nearest edge.
std::string nearestFaceSide(const ToolFace& f, const UV& uv);

/// @p uv put onto the side @p side: onto a box side exactly (see onSide()); a point near a
/// trimmed face's edge is kept as it is (found on it by bisection).
UV ontoSide(const ToolFace& f, const UV& uv, const std::string& side);

}  // namespace detail
TOWGEOM_END_NAMESPACE
