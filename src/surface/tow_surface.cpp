// TowSurface: construction and point queries.
#include <Bnd_Box.hxx>
#include <BndLib_AddSurface.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>

#include "surface/curve3_impl.hpp"
#include "surface/occt_convert.hpp"
#include "surface/occt_guard.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using detail::fromOcct;
using detail::toOcct;

TowSurface::TowSurface(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

namespace detail {

Handle(Geom_BSplineSurface) surfaceInFrame(const Handle(Geom_BSplineSurface)& surface, const Frame& frame)
{
    Handle(Geom_BSplineSurface) copy = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());
    copy->Transform(frame.trsf());
    return copy;
}

void setUnitFrame(TowSurface::Impl& tow)
{
    BoundingBox box;
    for (const auto& section : tow.sections)
        for (const Point3& p : section) box.add(p);
    tow.unitFrame = Frame::around(box, tow.towSize);
    tow.unit = surfaceInFrame(tow.surface, tow.unitFrame);
    tow.caps = capChartsOf(tow.surface);
}

TowSurface inFrame(const TowSurface& tow, const Frame& frame)
{
    const TowSurface::Impl& t = tow.impl();
    auto moved = std::make_shared<TowSurface::Impl>(t);
    for (auto& section : moved->sections)
        for (Point3& p : section) p = frame.toFrame(p);
    moved->towSize = frame.lengthToFrame(t.towSize);
    moved->surface = surfaceInFrame(t.surface, frame);
    moved->caps = capChartsOf(moved->surface);
    // The unit surface stays as it is; only the map to it changes (scales are powers of two).
    moved->unitFrame.origin = frame.toFrame(t.unitFrame.origin);
    moved->unitFrame.scale = t.unitFrame.scale / frame.scale;
    return TowSurfaceAccess::make(std::move(moved));
}

}  // namespace detail

Point3 TowSurface::pointOnClosed(double u, double v) const
{
    const detail::TowCaps& caps = impl_->caps;
    if (u >= caps.uMin && u <= caps.uMax) return point(u, v);
    const double eps = 1e-9 * (caps.uMax - caps.uMin);
    if (!std::isfinite(u) || !std::isfinite(v) || u < caps.uLow() - eps || u > caps.uHigh() + eps)
        throw Error(ErrorCode::InvalidArgument, "parameter u = " + std::to_string(u) + " lies beyond the tow's end caps",
                    "tow '" + impl_->name + "'");
    const GeomAdaptor_Surface tube(impl_->surface);
    return detail::chartPoint(tube, caps, std::clamp(u, caps.uLow(), caps.uHigh()), v);
}

TowSurface TowSurface::fit(const TowStack& stack, const FitOptions& options)
{
    if (options.mode == FitMode::Approximate &&
        !(options.tolerance > 0.0 || (options.tolerance == 0.0 && options.relativeTolerance > 0.0)))
        throw Error(ErrorCode::InvalidArgument, "the approximation tolerance must be positive", "tow '" + stack.name + "'");
    validateStack(stack);
    return TowSurface(detail::fitSurface(stack, options));
}

const std::string& TowSurface::name() const { return impl_->name; }
FitMode TowSurface::mode() const { return impl_->mode; }
std::size_t TowSurface::sectionCount() const { return impl_->sections.size(); }
std::size_t TowSurface::pointsPerSection() const { return impl_->sections.front().size(); }
bool TowSurface::inputReversed() const { return impl_->reversed; }
const std::vector<std::vector<Point3>>& TowSurface::sections() const { return impl_->sections; }
const std::vector<std::size_t>& TowSurface::startShifts() const { return impl_->startShifts; }
std::size_t TowSurface::inputPointIndex(std::size_t i, std::size_t j) const
{
    const std::size_t m = impl_->sections.size(), n = impl_->sections.front().size();
    if (i >= m || j >= n)
        throw Error(ErrorCode::InvalidArgument,
                    "no point " + std::to_string(j) + " of section " + std::to_string(i) + " in a tow of " +
                        std::to_string(m) + " x " + std::to_string(n) + " points",
                    "tow '" + impl_->name + "'");
    const std::size_t k = (j + impl_->startShifts[i]) % n;
    return impl_->reversed ? (n - k) % n : k;
}
const std::vector<double>& TowSurface::sectionParameters() const { return impl_->uParams; }
const std::vector<double>& TowSurface::pointParameters() const { return impl_->vParams; }
double TowSurface::towSize() const { return impl_->towSize; }
std::size_t TowSurface::controlPointCount(bool alongU) const
{
    return static_cast<std::size_t>(alongU ? impl_->surface->NbUPoles() : impl_->surface->NbVPoles());
}

ParameterRange TowSurface::parameterRange() const
{
    ParameterRange r;
    impl_->surface->Bounds(r.uMin, r.uMax, r.vMin, r.vMax);
    return r;
}

namespace {
/// Checks (u,v) and returns u clamped onto the range (within 1e-9 of it).
double checkedU(const TowSurface::Impl& t, double u, double v)
{
    double u0, u1, v0, v1;
    t.surface->Bounds(u0, u1, v0, v1);
    const double slack = 1e-9 * (u1 - u0);
    if (!std::isfinite(u) || !std::isfinite(v) || u < u0 - slack || u > u1 + slack)
        throw Error(ErrorCode::InvalidArgument,
                    "parameter (" + std::to_string(u) + ", " + std::to_string(v) + ") is outside the surface's u range",
                    "tow '" + t.name + "'");
    return std::clamp(u, u0, u1);
}
}  // namespace

Point3 TowSurface::point(double u, double v) const
{
    return detail::guarded(impl_->name, "point", [&]() -> Point3 {
        return fromOcct(impl_->surface->Value(checkedU(*impl_, u, v), v));
    });
}

SurfaceDerivatives TowSurface::derivatives(double u, double v) const
{
    return detail::guarded(impl_->name, "derivatives", [&]() -> SurfaceDerivatives {
        gp_Pnt p;
        gp_Vec du, dv;
        impl_->surface->D1(checkedU(*impl_, u, v), v, p, du, dv);
        return {fromOcct(p), fromOcct(du), fromOcct(dv)};
    });
}

SurfaceSecondDerivatives TowSurface::secondDerivatives(double u, double v) const
{
    return detail::guarded(impl_->name, "secondDerivatives", [&]() -> SurfaceSecondDerivatives {
        gp_Pnt p;
        gp_Vec du, dv, duu, dvv, duv;
        impl_->surface->D2(checkedU(*impl_, u, v), v, p, du, dv, duu, dvv, duv);
        return {fromOcct(p), fromOcct(du), fromOcct(dv), fromOcct(duu), fromOcct(dvv), fromOcct(duv)};
    });
}

Vector3 TowSurface::normal(double u, double v) const
{
    const SurfaceDerivatives d = derivatives(u, v);
    const Vector3 n = cross(d.du, d.dv);
    const double len = norm(n);
    if (!(len > 1e-300))
        throw Error(ErrorCode::Internal, "the surface is singular at (" + std::to_string(u) + ", " + std::to_string(v) + ")",
                    "tow '" + impl_->name + "'");
    return (1.0 / len) * n;
}

UV TowSurface::closestParameters(const Point3& p) const
{
    try {
        GeomAPI_ProjectPointOnSurf projector(toOcct(impl_->unitFrame.toFrame(p)), impl_->unit);
        if (projector.NbPoints() > 0) {
            UV uv;
            projector.LowerDistanceParameters(uv.u, uv.v);
            return uv;
        }
    } catch (const Standard_Failure&) {
        // fall through to the sampled start below
    }
    // No interior extremum (e.g. the closest point is on an end): start from the nearest
    // input point and search locally.
    std::size_t bi = 0, bj = 0;
    double best = 1e300;
    for (std::size_t i = 0; i < impl_->sections.size(); ++i)
        for (std::size_t j = 0; j < impl_->sections[i].size(); ++j) {
            const double d = distance(p, impl_->sections[i][j]);
            if (d < best) {
                best = d;
                bi = i;
                bj = j;
            }
        }
    return closestParameters(p, {impl_->uParams[bi], impl_->vParams[bj]});
}

UV TowSurface::closestParameters(const Point3& p, UV start) const
{
    const ParameterRange r = parameterRange();
    start.u = std::clamp(start.u, r.uMin, r.uMax);
    // OCCT's local search does not wrap a start outside the period; unwrapped v is common.
    start.v -= r.vPeriod() * std::floor((start.v - r.vMin) / r.vPeriod());
    GeomAdaptor_Surface adaptor(impl_->unit);
    Extrema_GenLocateExtPS locate(adaptor);
    try {
        locate.Perform(toOcct(impl_->unitFrame.toFrame(p)), start.u, start.v, Standard_False);
    } catch (const Standard_Failure&) {
        return start;
    }
    if (!locate.IsDone()) return start;
    UV uv;
    locate.Point().Parameter(uv.u, uv.v);
    // Keep whichever is closer: the local search may stop at the u boundary.
    if (distance(p, point(uv.u, uv.v)) > distance(p, point(start.u, start.v))) return start;
    return uv;
}

BoundingBox TowSurface::boundingBox() const
{
    return detail::guarded(impl_->name, "boundingBox", [&]() -> BoundingBox {
        BoundingBox box;
        const TColgp_Array2OfPnt& poles = impl_->surface->Poles();
        for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
            for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) box.add(fromOcct(poles(i, j)));
        return box;
    });
}

Curve3 TowSurface::isoU(double u) const
{
    return detail::guarded(impl_->name, "isoU", [&]() -> Curve3 {
        auto impl = std::make_shared<Curve3::Impl>();
        impl->curve = impl_->surface->UIso(checkedU(*impl_, u, 0.0));
        return Curve3(impl);
    });
}

SeamJump TowSurface::seamJump(double u) const
{
    return detail::guarded(impl_->name, "seamJump", [&]() -> SeamJump {
        const Geom_BSplineSurface& s = *impl_->surface;
        u = checkedU(*impl_, u, 0.0);
        int uk = s.FirstUKnotIndex();
        while (uk + 1 < s.LastUKnotIndex() && s.UKnot(uk + 1) <= u) ++uk;
        const int vFirst = s.FirstVKnotIndex(), vLast = s.LastVKnotIndex();
        gp_Pnt pa, pb;
        gp_Vec a[5], b[5];
        s.LocalD2(u, s.VKnot(vLast), uk, uk + 1, vLast - 1, vLast, pa, a[0], a[1], a[2], a[3], a[4]);
        s.LocalD2(u, s.VKnot(vFirst), uk, uk + 1, vFirst, vFirst + 1, pb, b[0], b[1], b[2], b[3], b[4]);
        const auto rel = [](const gp_XYZ& x, const gp_XYZ& y) {
            return (x - y).Modulus() / std::max({x.Modulus(), y.Modulus(), 1e-300});
        };
        SeamJump j;
        j.position = rel(pa.XYZ(), pb.XYZ());
        j.first = std::max(rel(a[0].XYZ(), b[0].XYZ()), rel(a[1].XYZ(), b[1].XYZ()));
        j.second = std::max({rel(a[2].XYZ(), b[2].XYZ()), rel(a[3].XYZ(), b[3].XYZ()), rel(a[4].XYZ(), b[4].XYZ())});
        return j;
    });
}

Deviation TowSurface::deviation() const
{
    return detail::guarded(impl_->name, "deviation", [&]() -> Deviation {
        const Impl& t = *impl_;
        GeomAdaptor_Surface adaptor(t.surface);
        Extrema_GenLocateExtPS locate(adaptor);
        const double negligible = 1e-12 * t.towSize;
        Deviation dev;
        double sum = 0.0;
        std::size_t count = 0;
        for (std::size_t i = 0; i < t.sections.size(); ++i)
            for (std::size_t j = 0; j < t.sections[i].size(); ++j) {
                const gp_Pnt q = toOcct(t.sections[i][j]);
                double d = adaptor.Value(t.uParams[i], t.vParams[j]).Distance(q);
                if (d > negligible) {
                    try {
                        locate.Perform(q, t.uParams[i], t.vParams[j], Standard_False);
                        if (locate.IsDone()) d = std::min(d, std::sqrt(locate.SquareDistance()));
                    } catch (const Standard_Failure&) {
                        // keep the parametric distance, an upper bound
                    }
                }
                sum += d * d;
                ++count;
                if (d > dev.max) {
                    dev.max = d;
                    dev.worstSection = i;
                    dev.worstPoint = inputPointIndex(i, j);
                }
            }
        dev.rms = std::sqrt(sum / static_cast<double>(count));
        return dev;
    });
}

TriangleMesh TowSurface::tessellate(std::size_t nu, std::size_t nv) const
{
    return detail::guarded(impl_->name, "tessellate", [&]() -> TriangleMesh {
        if (nu < 2 || nv < 3)
            throw Error(ErrorCode::InvalidArgument, "tessellation needs at least 2 x 3 vertices", "tow '" + impl_->name + "'");
        const ParameterRange r = parameterRange();
        GeomAdaptor_Surface adaptor(impl_->surface);
        TriangleMesh mesh;
        mesh.vertices.reserve(nu * nv);
        mesh.normals.reserve(nu * nv);
        for (std::size_t i = 0; i < nu; ++i) {
            const double u = r.uMin + (r.uMax - r.uMin) * static_cast<double>(i) / static_cast<double>(nu - 1);
            for (std::size_t j = 0; j < nv; ++j) {
                const double v = r.vMin + r.vPeriod() * static_cast<double>(j) / static_cast<double>(nv);
                gp_Pnt p;
                gp_Vec du, dv;
                adaptor.D1(u, v, p, du, dv);
                gp_Vec n = du.Crossed(dv);
                const double len = n.Magnitude();
                mesh.vertices.push_back(fromOcct(p));
                mesh.normals.push_back(len > 0.0 ? fromOcct(n / len) : Vector3{});
            }
        }
        mesh.triangles.reserve(2 * (nu - 1) * nv);
        for (std::size_t i = 0; i + 1 < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                const std::size_t a = i * nv + j, b = (i + 1) * nv + j;
                const std::size_t c = (i + 1) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
                mesh.triangles.push_back({a, b, c});
                mesh.triangles.push_back({a, c, d});
            }
        return mesh;
    });
}

TOWGEOM_END_NAMESPACE
