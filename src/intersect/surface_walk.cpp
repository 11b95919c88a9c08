#include "intersect/surface_walk.hpp"

#include <IntPatch_Intersection.hxx>
#include <IntPatch_WLine.hxx>
#include <IntSurf_PntOn2S.hxx>
#include <Standard_Failure.hxx>

#include <cmath>

#include "surface/occt_convert.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

SurfaceWalker::SurfaceWalker(const SurfacePair& surfaces, double tolerance, double maxStep)
    : a_(new GeomAdaptor_Surface(surfaces.a)),
      b_(new GeomAdaptor_Surface(surfaces.b)),
      domainA_(new Adaptor3d_TopolTool(a_)),
      domainB_(new Adaptor3d_TopolTool(b_)),
      tolerance_(tolerance),
      // OCCT's choice (kFineWalkStep, or ten times finer near a surface's singular point), scaled.
      uvMaxStep_(maxStep * (IntPatch_Intersection::DefineUVMaxStep(a_, domainA_, b_, domainB_) / kFineWalkStep))
{
}

std::vector<PointOn2> SurfaceWalker::walk(const PointOn2& start) const
{
    std::vector<PointOn2> line;
    IntPatch_Intersection intersector;
    // The deflection OCCT itself uses for B-spline pairs (IntTools_FaceFace).
    constexpr double kDeflection = 0.01;
    intersector.SetTolerances(tolerance_, tolerance_, uvMaxStep_, kDeflection);
    // OCCT expects v inside [first, first + period]; both ends are kept as they are, since at
    // a seam they say on which side to walk.
    const auto wrap = [](double v, const Handle(GeomAdaptor_Surface)& s) {
        const double first = s->FirstVParameter(), period = s->VPeriod();
        return v >= first && v <= first + period ? v : v - period * std::floor((v - first) / period);
    };
    intersector.Perform(a_, domainA_, b_, domainB_, start.ua, wrap(start.va, a_), start.ub, wrap(start.vb, b_),
                        tolerance_, tolerance_);
    if (!intersector.IsDone()) return line;
    for (int i = 1; i <= intersector.NbLines(); ++i) {
        const Handle(IntPatch_WLine) w = Handle(IntPatch_WLine)::DownCast(intersector.Line(i));
        if (w.IsNull() || w->NbPnts() < 2) continue;
        // A start-point walk gives one line; should OCCT ever give more, keep the longest.
        if (static_cast<std::size_t>(w->NbPnts()) <= line.size()) continue;
        line.clear();
        for (int k = 1; k <= w->NbPnts(); ++k) {
            const IntSurf_PntOn2S& p = w->Point(k);
            PointOn2 q;
            p.Parameters(q.ua, q.va, q.ub, q.vb);
            q.point = fromOcct(p.Value());
            line.push_back(q);
        }
    }
    return line;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
