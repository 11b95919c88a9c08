// OpenCASCADE's surface-surface intersection, walking from a start point: IntPatch's
// parametric marching (IntWalk_PWalking) as used by GeomInt_IntSS with a start point. Its cost
// does not grow with the number of knots of the surfaces, unlike the unseeded search.
#pragma once

#include <GeomAdaptor_Surface.hxx>
#include <Adaptor3d_TopolTool.hxx>

#include <vector>

#include "intersect/intersection_point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One thread's OCCT adaptors over a pair of surfaces (adaptors cache spans: not shareable).
class SurfaceWalker {
public:
    /// @param tolerance the 3D tolerance of the walk (OCCT's TolArc and TolTang)
    SurfaceWalker(const SurfacePair& surfaces, double tolerance);

    /// The walking line through @p start: the points OCCT marched along, each on both surfaces
    /// within the tolerance, in order. Empty when OCCT finds no line there. The line stops where
    /// it reaches a surface's boundary or a periodic seam, or returns to its first point.
    std::vector<PointOn2> walk(const PointOn2& start) const;

private:
    Handle(GeomAdaptor_Surface) a_, b_;
    Handle(Adaptor3d_TopolTool) domainA_, domainB_;
    double tolerance_;
    double uvMaxStep_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
