// Offset curves cut at, or carried to, the tool surface's boundary (bisection on the base
// curve's parameter; geodesics along the curve's end direction).
#include "placement/trimmed_offset.hpp"

#include <Adaptor3d_CurveOnSurface.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>

#include <cmath>
#include <limits>
#include <optional>

#include "placement/curve_derivatives.hpp"
#include "placement/geodesics.hpp"
#include "placement/offset_point.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/tool_face.hpp"
#include "placement/uv_interpolation.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr double kNaNOffset = std::numeric_limits<double>::quiet_NaN();

/// The cubic B-spline in (u,v) through @p c's points at their (u,v) chord lengths, and those.
struct UVCurve {
    Handle(Geom2d_BSplineCurve) curve;
    std::vector<double> params;
};

UVCurve uvCurve(const CurveOnSurface& c)
{
    UVCurve out;
    out.params = chordParameters(c.uv);
    out.curve = interpolateUV(c.uv, out.params);
    return out;
}

/// A point of a curve with its 3D direction.
struct PointAlong {
    UV uv;
    gp_Vec tangent;
};

PointAlong pointAlong(const Handle(Geom_BSplineSurface)& s, const UVCurve& c, double t)
{
    gp_Pnt2d p;
    gp_Vec2d d;
    c.curve->D1(t, p, d);
    gp_Pnt q;
    gp_Vec su, sv;
    s->D1(p.X(), p.Y(), q, su, sv);
    return {{p.X(), p.Y()}, su * d.X() + sv * d.Y()};
}

/// The offset of @p at, or nothing when it leaves the surface.
std::optional<OffsetPoint> tryOffset(const Handle(Geom_BSplineSurface)& s, const PointAlong& at, double d, const SurfaceOffsetOptions& o,
                                     bool measure = true)
{
    if (d == 0.0) return OffsetPoint{at.uv, at.uv, 0.0, 0.0};  // the curve itself, trimmed to the face
    try {
        return offsetPoint(s, at.uv, at.tangent, d, o, measure);
    } catch (const OffSurface&) {
        return std::nullopt;  // off the surface; anything else (a singular point, no convergence) is the caller's
    }
}

/// The offset of the base point between parameters @p inside (offset on the surface) and
/// @p outside (offset off it) whose offset lands on the boundary, put onto that side.
std::pair<OffsetPoint, std::string> cutAtBoundary(const ToolFace& f, const UVCurve& base, double inside, double outside, double d,
                                                  const SurfaceOffsetOptions& o)
{
    const Handle(Geom_BSplineSurface)& s = f.surface;
    const double span = std::abs(outside - inside);
    for (int it = 0; it < 200 && std::abs(outside - inside) > 1e-15 * span; ++it) {
        const double mid = 0.5 * (inside + outside);
        const std::optional<OffsetPoint> p = tryOffset(s, pointAlong(s, base, mid), d, o, false);  // where it lands only
        if (p && onFace(f, p->raw)) inside = mid;
        else outside = mid;
    }
    // The kept point, measured (if that fails so near the boundary: only where it lands).
    std::optional<OffsetPoint> kept;
    try {
        kept = tryOffset(s, pointAlong(s, base, inside), d, o);
    } catch (const Error&) {
        // Measuring so near the boundary failed (shooting did not converge): where it lands will do.
    }
    if (!kept) kept = tryOffset(s, pointAlong(s, base, inside), d, o, false);
    if (!kept) throw Error(ErrorCode::Internal, "an offset cut at the surface's boundary was lost");
    OffsetPoint end = *kept;
    // The bisection ends on the boundary; anywhere else something other than the face's end
    // stopped the offsets.
    const std::string side = faceSide(f, end.raw, 1e-6);
    if (side.empty())
        throw Error(ErrorCode::InvalidArgument, "an offset stops inside the face at (" + std::to_string(end.raw.u) + ", " + std::to_string(end.raw.v) + ")");
    end.uv = ontoSide(f, end.raw, side);  // within the bisection's 1e-15 of it: its distance stands
    return {end, side};
}

/// Where a geodesic carried on from a curve's end meets the boundary.
struct Carried {
    UV uv;             ///< the boundary point
    std::string side;  ///< its side of the box
    double length = 0.0;  ///< the geodesic's length to it
};

/// The boundary point reached from @p from along the 3D direction @p t by a geodesic, or nothing
/// if it does not leave the surface within @p longest.
std::optional<Carried> carryToBoundary(const ToolFace& f, const UV& from, const gp_Vec& t, double step, double longest,
                                                          int steps)
{
    const auto reach = [&](double length) -> std::optional<UV> {
        try {
            const UV end = shootGeodesic(f.surface, from, t, length, steps);
            if (onFace(f, end)) return end;
        } catch (const OffSurface&) {
        }
        return std::nullopt;
    };
    // Doubling the length on a box; on a trimmed face in eighths of the step, so as not to jump a
    // hole or notch.
    double inside = 0.0, outside = f.trim ? step / 8.0 : step;
    UV kept = from;
    while (const std::optional<UV> end = reach(outside)) {
        kept = *end, inside = outside, outside = f.trim ? outside + step / 8.0 : 2.0 * outside;
        if (inside > longest) return std::nullopt;
    }
    for (int it = 0; it < 200 && outside - inside > 1e-15 * outside; ++it) {
        const double mid = 0.5 * (inside + outside);
        if (const std::optional<UV> end = reach(mid)) kept = *end, inside = mid;
        else outside = mid;
    }
    const std::string side = nearestFaceSide(f, kept);
    return Carried{ontoSide(f, kept, side), side, inside};
}

/// The longest run [first, last] of consecutive true entries of @p on (last < first: none).
std::pair<std::size_t, std::size_t> longestRun(const std::vector<bool>& on)
{
    std::size_t bestFirst = 1, bestLast = 0;
    for (std::size_t i = 0; i < on.size();) {
        if (!on[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < on.size() && on[j + 1]) ++j;
        if (bestLast < bestFirst || j - i > bestLast - bestFirst) bestFirst = i, bestLast = j;
        i = j + 1;
    }
    return {bestFirst, bestLast};
}

void append(TrimmedOffset& out, const Handle(Geom_BSplineSurface)& s, const UV& uv, double geodesic, double estimate, bool front)
{
    const Point3 p = fromOcct(s->Value(uv.u, uv.v));
    const auto at = [front](auto& v) { return front ? v.begin() : v.end(); };
    out.curve.uv.insert(at(out.curve.uv), uv);
    out.curve.points.insert(at(out.curve.points), p);
    out.geodesicDistance.insert(at(out.geodesicDistance), geodesic);
    out.estimatedError.insert(at(out.estimatedError), estimate);
}

/// The curve's first (@p front) or last point replaced by @p end, with its step's record.
void replaceEnd(TrimmedOffset& out, const Handle(Geom_BSplineSurface)& s, const OffsetPoint& end, bool front)
{
    const std::size_t k = front ? 0 : out.curve.uv.size() - 1;
    out.curve.uv[k] = end.uv;
    out.curve.points[k] = fromOcct(s->Value(end.uv.u, end.uv.v));
    out.geodesicDistance[k] = end.geodesicDistance;
    out.estimatedError[k] = end.estimatedError;
}

/// Whether a point at @p uv added next to the curve's end point @p end is a new point (not the
/// same one to 1e-9 of the box).
bool distinct(const Handle(Geom_BSplineSurface)& s, const UV& uv, const UV& end)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    return std::abs(uv.u - end.u) > 1e-9 * (u1 - u0) || std::abs(uv.v - end.v) > 1e-9 * (v1 - v0);
}

}  // namespace

namespace {

TrimmedOffset offsetWithin(const ToolFace& f, const CurveOnSurface& base, double d, const SurfaceOffsetOptions& options, bool mayClose,
                           bool probed = false);

}  // namespace

TrimmedOffset offsetWithinSurface(const ToolFace& f, const CurveOnSurface& base, double d, const SurfaceOffsetOptions& options)
{
    return offsetWithin(f, base, d, options, true);
}

namespace {

/// @p base with a point added between each two whose offsets (@p at, on the face where @p on)
/// lie on the trimmed face @p f but the chord between them in (u,v) does not (7 places probed),
/// where the offset of the base point there is off the face too: a hole or notch the offsets
/// passed over.
CurveOnSurface withHolesSampled(const ToolFace& f, const CurveOnSurface& base, const std::vector<std::optional<OffsetPoint>>& at,
                                const std::vector<bool>& on, double d, const SurfaceOffsetOptions& o)
{
    const std::size_t n = base.uv.size();
    const UVCurve curve = uvCurve(base);
    if (curve.curve.IsNull()) return base;
    CurveOnSurface out;
    for (std::size_t i = 0; i < n; ++i) {
        out.uv.push_back(base.uv[i]);
        out.points.push_back(base.points[i]);
        if (i + 1 == n || !on[i] || !on[i + 1]) continue;
        for (int k = 1; k < 8; ++k) {
            const double x = k / 8.0;
            const UV& a = at[i]->raw;
            const UV& b = at[i + 1]->raw;
            if (onFace(f, {a.u + x * (b.u - a.u), a.v + x * (b.v - a.v)})) continue;
            const PointAlong p = pointAlong(f.surface, curve, curve.params[i] + x * (curve.params[i + 1] - curve.params[i]));
            const std::optional<OffsetPoint> q = tryOffset(f.surface, p, d, o, false);
            if (q && onFace(f, q->raw)) continue;  // the chord strays off the face, the curve does not
            out.uv.push_back(p.uv);
            out.points.push_back(fromOcct(f.surface->Value(p.uv.u, p.uv.v)));
            break;
        }
    }
    return out;
}

/// offsetWithinSurface(); with @p mayClose false a closed base is laid as an open curve (its run
/// on the face neither wraps nor closes).
TrimmedOffset offsetWithin(const ToolFace& f, const CurveOnSurface& base, double d, const SurfaceOffsetOptions& options, bool mayClose, bool probed)
{
    const Handle(Geom_BSplineSurface)& s = f.surface;
    const std::size_t n = base.uv.size();
    std::vector<std::optional<OffsetPoint>> at(n);
    std::vector<bool> on(n, false);
    const std::vector<gp_Vec> tangents = curveTangents(s, base);
    for (std::size_t i = 0; i < n; ++i) {
        at[i] = tryOffset(s, {base.uv[i], tangents[i]}, d, options);
        on[i] = at[i] && onFace(f, at[i]->raw, 1e-9);  // rounding along an edge allowed
    }
    // A trimmed face's hole or notch between two offsets on it: laid again with a base point
    // there (once: its offset is off the face, so the run ends before it).
    if (f.trim && !probed) {
        const CurveOnSurface denser = withHolesSampled(f, base, at, on, d, options);
        if (denser.uv.size() > n) return offsetWithin(f, denser, d, options, mayClose, true);
    }
    // A closed base whose offsets leave the face somewhere: the run on the face may pass its
    // joint. Laid again from an offset that left round to it (both crossings next to it inside
    // the sequence), as an open curve, so that the run does not.
    if (mayClose && isClosed(base) && n >= 4) {
        std::size_t off = n;
        for (std::size_t k = 0; k + 1 < n && off == n; ++k)
            if (!on[k]) off = k;
        if (off < n) {
            const UV period{base.uv.back().u - base.uv.front().u, base.uv.back().v - base.uv.front().v};
            CurveOnSurface open;
            for (std::size_t k = off; k < n; ++k) open.uv.push_back(base.uv[k]), open.points.push_back(base.points[k]);
            for (std::size_t k = 1; k <= off; ++k) open.uv.push_back({base.uv[k].u + period.u, base.uv[k].v + period.v}), open.points.push_back(base.points[k]);
            return offsetWithin(f, open, d, options, false);
        }
    }
    TrimmedOffset out;
    const auto [first, last] = longestRun(on);
    if (last < first) return out;
    for (std::size_t i = first; i <= last; ++i) append(out, s, at[i]->uv, at[i]->geodesicDistance, at[i]->estimatedError, false);
    if (mayClose && isClosed(base)) return out;  // all on the face (else laid open above)
    const UVCurve curve = uvCurve(base);
    if (curve.curve.IsNull()) throw Error(ErrorCode::InvalidArgument, "a curve's points repeat (its (u,v) cannot be interpolated)");
    // Cut where the surface ends the offsets.
    if (first > 0) {
        const auto [end, side] = cutAtBoundary(f, curve, curve.params[first], curve.params[first - 1], d, options);
        if (distinct(s, end.uv, out.curve.uv.front())) append(out, s, end.uv, end.geodesicDistance, end.estimatedError, true);
        else replaceEnd(out, s, end, true);
        out.startSide = side;
    }
    if (last + 1 < n) {
        const auto [end, side] = cutAtBoundary(f, curve, curve.params[last], curve.params[last + 1], d, options);
        if (distinct(s, end.uv, out.curve.uv.back())) append(out, s, end.uv, end.geodesicDistance, end.estimatedError, false);
        else replaceEnd(out, s, end, false);
        out.endSide = side;
    }
    // Carried on where the base runs to the boundary and the offset stops short of it.
    if (out.curve.uv.size() < 2) return out;
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const double longest = 4.0 * std::abs(d) + 1e-3 * lengthOnSurface(s, base) + std::abs(d);
    const UVCurve offset = uvCurve(out.curve);
    if (offset.curve.IsNull()) return out;
    for (const bool atStart : {true, false}) {
        const std::string baseSide = faceSide(f, atStart ? base.uv.front() : base.uv.back(), 1e-9);
        if (baseSide.empty() || !(atStart ? out.startSide : out.endSide).empty()) continue;
        const UV end = atStart ? out.curve.uv.front() : out.curve.uv.back();
        if (!faceSide(f, end, 1e-9).empty()) continue;  // on the boundary already
        const PointAlong e = pointAlong(s, offset, atStart ? offset.params.front() : offset.params.back());
        const gp_Vec direction = atStart ? e.tangent.Reversed() : e.tangent;
        const std::optional<Carried> reached = carryToBoundary(f, end, direction, std::abs(d), longest, options.geodesicSteps);
        if (!reached) continue;
        (atStart ? out.startSide : out.endSide) = reached->side;
        if (!distinct(s, reached->uv, end)) {  // a rounding short of the side: put onto it
            (atStart ? out.curve.uv.front() : out.curve.uv.back()) = reached->uv;
            (atStart ? out.curve.points.front() : out.curve.points.back()) = fromOcct(s->Value(reached->uv.u, reached->uv.v));
            continue;
        }
        // Points along the carried geodesic at about the curve's spacing, then the boundary's.
        const double spacing = lengthOnSurface(s, out.curve) / static_cast<double>(out.curve.uv.size() - 1);
        const int pieces = spacing > 0.0 ? static_cast<int>(std::min(1000.0, std::ceil(reached->length / spacing))) : 1;
        for (int k = 1; k < pieces; ++k)
            append(out, s, shootGeodesic(s, end, direction, reached->length * k / pieces, options.geodesicSteps), kNaNOffset, kNaNOffset, atStart);
        append(out, s, reached->uv, kNaNOffset, kNaNOffset, atStart);
    }
    return out;
}

}  // namespace

CurveOnSurface trimToFace(const ToolFace& f, const CurveOnSurface& c)
{
    if (!f.trim) return c;
    return offsetWithin(f, c, 0.0, SurfaceOffsetOptions(), true).curve;  // probed for holes between its points too
}

double lengthOnSurface(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c)
{
    if (c.uv.size() < 2) return 0.0;
    const UVCurve curve = uvCurve(c);
    if (curve.curve.IsNull()) return 0.0;
    const Adaptor3d_CurveOnSurface adaptor(new Geom2dAdaptor_Curve(curve.curve), new GeomAdaptor_Surface(s));
    return GCPnts_AbscissaPoint::Length(adaptor, 1e-12);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
