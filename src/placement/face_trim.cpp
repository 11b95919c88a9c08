// A tool face's trimming curves: OpenCASCADE's face classifier on the face's own parameters
// (the placement surface's mapped back: reversal undone, analytic surfaces' parameters in
// closed form), and the edge a boundary point lies on.
#include "placement/face_trim.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <Extrema_ExtPC.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// Whether edge @p e's curve on @p face runs along one side of the face's box (9 places, to
/// 1e-7 of the box: curves projected onto a B-spline face stray by about that).
bool alongBoxSide(const TopoDS_Edge& e, const TopoDS_Face& face, const double box[4])
{
    double f, l;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(e, face, f, l);
    if (c.IsNull()) return false;
    const double du = 1e-7 * (box[1] - box[0]), dv = 1e-7 * (box[3] - box[2]);
    const double sides[4] = {box[0], box[1], box[2], box[3]};
    for (int side = 0; side < 4; ++side) {
        const double tol = side < 2 ? du : dv;
        bool all = true;
        for (int k = 0; k <= 8 && all; ++k) {
            const gp_Pnt2d p = c->Value(f + (l - f) * k / 8.0);
            all = std::abs((side < 2 ? p.X() : p.Y()) - sides[side]) <= tol;
        }
        if (all) return true;
    }
    return false;
}

/// Whether @p converted gives the points @p surface does at the same parameters (a B-spline,
/// Bezier or plane converted: 25 places in the box, to 1e-12 of @p size).
bool sameParameterisation(const Handle(Geom_BSplineSurface)& converted, const Handle(Geom_Surface)& surface, const double box[4], double size)
{
    double u0, u1, v0, v1;
    converted->Bounds(u0, u1, v0, v1);
    if (std::abs(u0 - box[0]) > 1e-12 * (box[1] - box[0]) + 1e-300 || std::abs(v0 - box[2]) > 1e-12 * (box[3] - box[2]) + 1e-300) return false;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double u = u0 + (u1 - u0) * i / 4.0, v = v0 + (v1 - v0) * j / 4.0;
            if (converted->Value(u, v).Distance(surface->Value(u, v)) > 1e-12 * size) return false;
        }
    return true;
}

/// @p x moved by whole periods @p period into [lo, hi] if a copy lies there (to 1e-9 of the
/// period), else nearest its middle.
double intoRange(double x, double period, double lo, double hi)
{
    const double slack = 1e-9 * period;
    double y = x - period * std::floor((x - lo + slack) / period);
    if (y <= hi + slack) return y;
    const double mid = 0.5 * (lo + hi);
    return x - period * std::round((x - mid) / period);
}

/// The face's own parameters of the placement point @p uv.
gp_Pnt2d faceParameters(const FaceTrim& t, const Handle(Geom_BSplineSurface)& s, UV uv)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    if (s->IsUPeriodic()) uv.u = intoRange(uv.u, s->UPeriod(), u0, u1);
    if (s->IsVPeriodic()) uv.v = intoRange(uv.v, s->VPeriod(), v0, v1);
    double u = t.reversedU ? t.uFirst + t.uLast - uv.u : uv.u, v = uv.v;
    if (!t.sameParameters) {
        const gp_Pnt p = s->Value(uv.u, uv.v);
        const GeomAdaptor_Surface a(t.surface);
        switch (a.GetType()) {
        case GeomAbs_Plane: ElSLib::Parameters(a.Plane(), p, u, v); break;
        case GeomAbs_Cylinder: ElSLib::Parameters(a.Cylinder(), p, u, v); break;
        case GeomAbs_Cone: ElSLib::Parameters(a.Cone(), p, u, v); break;
        case GeomAbs_Sphere: ElSLib::Parameters(a.Sphere(), p, u, v); break;
        case GeomAbs_Torus: ElSLib::Parameters(a.Torus(), p, u, v); break;
        default: {
            GeomAPI_ProjectPointOnSurf nearest(p, t.surface, t.box[0], t.box[1], t.box[2], t.box[3]);
            if (nearest.NbPoints() == 0) throw Error(ErrorCode::Internal, "a point of the tool surface has no place on its face");
            nearest.LowerDistanceParameters(u, v);
        }
        }
    }
    if (t.basis->IsUPeriodic()) u = intoRange(u, t.basis->UPeriod(), t.box[0], t.box[1]);
    if (t.basis->IsVPeriodic()) v = intoRange(v, t.basis->VPeriod(), t.box[2], t.box[3]);
    return {u, v};
}

}  // namespace

std::shared_ptr<const FaceTrim> faceTrim(const TopoDS_Face& face, const Handle(Geom_BSplineSurface)& converted, bool reversed)
{
    auto t = std::make_shared<FaceTrim>();
    t->face = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    t->surface = BRep_Tool::Surface(t->face);
    // A trimmed surface's periods are its basis's (a face on a cylinder trimmed to an angle range
    // still has the cylinder's angles, to be moved into the face's box).
    t->basis = t->surface;
    while (const auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(t->basis)) t->basis = trimmed->BasisSurface();
    BRepTools::UVBounds(t->face, t->box[0], t->box[1], t->box[2], t->box[3]);
    TopTools_IndexedMapOfShape all;
    TopExp::MapShapes(t->face, TopAbs_EDGE, all);
    bool natural = true;
    for (int k = 1; k <= all.Extent(); ++k) {
        const TopoDS_Edge& e = TopoDS::Edge(all(k));
        if (BRep_Tool::Degenerated(e) || BRep_Tool::IsClosed(e, t->face)) continue;  // a pole or a seam: not where the face ends
        t->edges.push_back(e);
        t->edgeIndex.push_back(static_cast<std::size_t>(k - 1));
        if (!alongBoxSide(e, t->face, t->box)) natural = false;
    }
    if (natural) return nullptr;
    Bnd_Box bounds;
    BRepBndLib::Add(t->face, bounds);
    t->size = std::sqrt(bounds.SquareExtent());
    t->sameParameters = sameParameterisation(converted, t->surface, t->box, t->size);
    t->reversedU = reversed;
    t->quick = std::make_shared<const BRepTopAdaptor_FClass2d>(t->face, 1e-7 * std::max(t->box[1] - t->box[0], t->box[3] - t->box[2]));
    double v0, v1;
    converted->Bounds(t->uFirst, t->uLast, v0, v1);
    return t;
}

bool insideTrim(const FaceTrim& trim, const Handle(Geom_BSplineSurface)& s, const UV& uv)
{
    const gp_Pnt2d q = faceParameters(trim, s, uv);
    const TopAbs_State quick = trim.quick->Perform(q, false);
    if (quick == TopAbs_IN) return true;
    if (quick == TopAbs_OUT) return false;
    const double tol = 1e-12 * std::max(trim.box[1] - trim.box[0], trim.box[3] - trim.box[2]);
    const BRepClass_FaceClassifier classifier(trim.face, q, tol);
    return classifier.State() == TopAbs_IN || classifier.State() == TopAbs_ON;
}

std::string trimSide(const FaceTrim& trim, const gp_Pnt& p, double tolerance)
{
    if (trim.edges.empty()) return {};
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < trim.edges.size(); ++k) {
        const BRepAdaptor_Curve c(trim.edges[k]);
        double d = std::min(p.Distance(c.Value(c.FirstParameter())), p.Distance(c.Value(c.LastParameter())));
        const Extrema_ExtPC extrema(p, c);
        if (extrema.IsDone())
            for (int i = 1; i <= extrema.NbExt(); ++i) d = std::min(d, std::sqrt(extrema.SquareDistance(i)));
        if (d < best) best = d, nearest = k;
    }
    // The edge's curve on the face (which classified the point) may stray from its 3D curve by
    // the edge's tolerance.
    if (!(best <= tolerance * trim.size + BRep_Tool::Tolerance(trim.edges[nearest]))) return {};
    nearest = trim.edgeIndex[nearest];
    return "edge " + std::to_string(nearest);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
