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

/// The walk's largest step in each parameter, a fraction of its range (OCCT's UVMaxStep). OCCT
/// uses 0.001 for B-spline pairs; its points are then ~8 times denser than the chordal tolerance
/// keeps, and the walk was half of `detect`'s time on bench_resolve_scan's pressed weave. 0.002
/// gives the same 1606 loops there with half the walk's points; 0.004 (a quarter) does too, but
/// moves where a figure-8's lobes pass their singular point enough to cost the mesh there a
/// degree (test_resolve_scans). A closed walk that comes back enclosing no area is walked again
/// with kFineWalkStep before it is called a contact.
constexpr double kWalkStep = 0.002;
/// OCCT's own step for B-spline pairs (IntPatch_Intersection::DefineUVMaxStep away from singular
/// points).
constexpr double kFineWalkStep = 0.001;

/// One thread's OCCT adaptors over a pair of surfaces (adaptors cache spans: not shareable).
class SurfaceWalker {
public:
    /// @param tolerance the 3D tolerance of the walk (OCCT's TolArc and TolTang)
    /// @param maxStep the largest step in each parameter, a fraction of its range
    SurfaceWalker(const SurfacePair& surfaces, double tolerance, double maxStep = kWalkStep);

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
