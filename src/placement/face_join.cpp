// Faces of a tool shell joined side to side: sides matched by their points, the two surfaces
// made compatible along the shared side (OpenCASCADE's degree elevation and knot insertion) and
// their poles put together, a crease (a knot of multiplicity the degree) between them.
#include "placement/face_join.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "placement/periodic_surface.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

enum class Side { UMin, UMax, VMin, VMax };
constexpr std::array<Side, 4> kSides{Side::UMin, Side::UMax, Side::VMin, Side::VMax};

/// The point at fraction @p t of side @p side of @p s, in its parameter's direction.
gp_Pnt sidePoint(const Handle(Geom_BSplineSurface)& s, Side side, double t)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const double u = u0 + t * (u1 - u0), v = v0 + t * (v1 - v0);
    switch (side) {
    case Side::UMin: return s->Value(u0, v);
    case Side::UMax: return s->Value(u1, v);
    case Side::VMin: return s->Value(u, v0);
    default: return s->Value(u, v1);
    }
}

/// +1 if side @p a of @p A and side @p b of @p B coincide (9 places at the same fractions of their
/// parameters, within @p tol), -1 if they do the other way round, 0 if not or if either is a point.
int coincide(const Handle(Geom_BSplineSurface)& A, Side a, const Handle(Geom_BSplineSurface)& B, Side b, double tol)
{
    if (sidePoint(A, a, 0.0).Distance(sidePoint(A, a, 0.5)) + sidePoint(A, a, 0.5).Distance(sidePoint(A, a, 1.0)) <= tol) return 0;  // a pole
    bool same = true, reversed = true;
    for (int k = 0; k <= 8 && (same || reversed); ++k) {
        const gp_Pnt p = sidePoint(A, a, k / 8.0);
        same = same && p.Distance(sidePoint(B, b, k / 8.0)) <= tol;
        reversed = reversed && p.Distance(sidePoint(B, b, 1.0 - k / 8.0)) <= tol;
    }
    return same ? 1 : reversed ? -1 : 0;
}

/// @p s turned (its normal kept: an even number of reversals and exchanges) so that side @p side
/// is its v end (@p toEnd) or its v start.
void turnSide(const Handle(Geom_BSplineSurface)& s, Side side, bool toEnd)
{
    const Side want = toEnd ? Side::VMax : Side::VMin;
    if (side == want) return;
    if (side == Side::VMin || side == Side::VMax) {  // the other v side
        s->UReverse();
        s->VReverse();
        return;
    }
    s->ExchangeUV();  // u sides become the v sides of the same end
    const bool atEnd = side == Side::UMax;
    if (atEnd == toEnd) s->UReverse();  // the normal back
    else s->VReverse();
}

/// @p s rebuilt with its u knots mapped affinely onto [@p a, @p b] and its weights times @p scale.
Handle(Geom_BSplineSurface) remapped(const Handle(Geom_BSplineSurface)& s, double a, double b, double scale)
{
    TColStd_Array1OfReal uk(1, s->NbUKnots()), vk(1, s->NbVKnots());
    TColStd_Array1OfInteger um(1, s->NbUKnots()), vm(1, s->NbVKnots());
    s->UKnots(uk), s->VKnots(vk), s->UMultiplicities(um), s->VMultiplicities(vm);
    const double u0 = uk(1), u1 = uk(uk.Upper());
    for (int i = 1; i <= uk.Upper(); ++i) uk(i) = i == uk.Upper() ? b : a + (uk(i) - u0) * (b - a) / (u1 - u0);
    TColgp_Array2OfPnt poles(1, s->NbUPoles(), 1, s->NbVPoles());
    TColStd_Array2OfReal weights(1, s->NbUPoles(), 1, s->NbVPoles());
    s->Poles(poles);
    s->Weights(weights);
    for (int i = 1; i <= s->NbUPoles(); ++i)
        for (int j = 1; j <= s->NbVPoles(); ++j) weights(i, j) *= scale;
    return new Geom_BSplineSurface(poles, weights, uk, vk, um, vm, s->UDegree(), s->VDegree());
}

/// Each interior u knot of @p from inserted into @p into (multiplicity at least @p from's).
void insertUKnotsOf(const Handle(Geom_BSplineSurface)& from, const Handle(Geom_BSplineSurface)& into)
{
    for (int i = 2; i < from->NbUKnots(); ++i) into->InsertUKnot(from->UKnot(i), from->UMultiplicity(i), 1e-12 * (from->UKnot(from->NbUKnots()) - from->UKnot(1)), false);
}

/// The mean of |dS/dv| along @p s's v side at @p v.
double rateAcross(const Handle(Geom_BSplineSurface)& s, double v)
{
    double u0, u1, v0, v1, sum = 0.0;
    s->Bounds(u0, u1, v0, v1);
    for (int k = 0; k <= 8; ++k) {
        gp_Pnt p;
        gp_Vec du, dv;
        s->D1(u0 + (u1 - u0) * k / 8.0, v, p, du, dv);
        sum += dv.Magnitude();
    }
    return sum / 9.0;
}

/// @p A (its v end) and @p B (its v start) along the same side, joined; @p what names B.
Handle(Geom_BSplineSurface) joinAlongV(const Handle(Geom_BSplineSurface)& A0, const Handle(Geom_BSplineSurface)& B0, double tol, const std::string& what)
{
    const Handle(Geom_BSplineSurface) A = Handle(Geom_BSplineSurface)::DownCast(A0->Copy());
    Handle(Geom_BSplineSurface) B = Handle(Geom_BSplineSurface)::DownCast(B0->Copy());
    const int p = std::max(A->UDegree(), B->UDegree()), q = std::max(A->VDegree(), B->VDegree());
    A->IncreaseDegree(p, q);
    B->IncreaseDegree(p, q);
    double a0, a1, av0, av1;
    A->Bounds(a0, a1, av0, av1);
    B = remapped(B, a0, a1, 1.0);
    insertUKnotsOf(A, B);
    insertUKnotsOf(B, A);
    if (A->NbUPoles() != B->NbUPoles()) throw Error(ErrorCode::InvalidArgument, what + ": its knots along the shared side do not match the rest's");
    const int nu = A->NbUPoles(), na = A->NbVPoles(), nb = B->NbVPoles();
    // The weights along the side: B's a constant times A's, scaled to agree.
    const double scale = A->Weight(1, na) / B->Weight(1, 1);
    for (int i = 1; i <= nu; ++i) {
        if (std::abs(B->Weight(i, 1) * scale - A->Weight(i, na)) > 1e-10 * A->Weight(i, na))
            throw Error(ErrorCode::InvalidArgument, what + ": its weights along the shared side are not the rest's (a different rational form)");
        if (B->Pole(i, 1).Distance(A->Pole(i, na)) > tol)
            throw Error(ErrorCode::InvalidArgument, what + ": it is parametrised otherwise along the shared side (its poles there differ)");
    }
    double b0, b1, bv0, bv1;
    B->Bounds(b0, b1, bv0, bv1);
    // B's v scaled so that the rate across the side matches A's on average.
    const double ra = rateAcross(A, av1), rb = rateAcross(B, bv0);
    const double length = ra > 0.0 && rb > 0.0 ? (bv1 - bv0) * rb / ra : bv1 - bv0;
    TColgp_Array2OfPnt poles(1, nu, 1, na + nb - 1);
    TColStd_Array2OfReal weights(1, nu, 1, na + nb - 1);
    for (int i = 1; i <= nu; ++i) {
        for (int j = 1; j <= na; ++j) poles(i, j) = A->Pole(i, j), weights(i, j) = A->Weight(i, j);
        for (int j = 2; j <= nb; ++j) poles(i, na + j - 1) = B->Pole(i, j), weights(i, na + j - 1) = B->Weight(i, j) * scale;
    }
    const int ka = A->NbVKnots(), kb = B->NbVKnots();
    TColStd_Array1OfReal vk(1, ka + kb - 1);
    TColStd_Array1OfInteger vm(1, ka + kb - 1);
    for (int k = 1; k <= ka; ++k) vk(k) = A->VKnot(k), vm(k) = A->VMultiplicity(k);
    vm(ka) = q;  // the crease
    for (int k = 2; k <= kb; ++k) vk(ka + k - 1) = av1 + (B->VKnot(k) - bv0) * length / (bv1 - bv0), vm(ka + k - 1) = B->VMultiplicity(k);
    TColStd_Array1OfReal uk(1, A->NbUKnots());
    TColStd_Array1OfInteger um(1, A->NbUKnots());
    A->UKnots(uk);
    A->UMultiplicities(um);
    return new Geom_BSplineSurface(poles, weights, uk, vk, um, vm, p, q);
}

}  // namespace

Handle(Geom_BSplineSurface) joinFaces(const std::vector<Handle(Geom_BSplineSurface)>& faces, const std::vector<std::string>& names)
{
    if (faces.empty()) throw Error(ErrorCode::InvalidArgument, "no faces to join");
    Handle(Geom_BSplineSurface) joined = Handle(Geom_BSplineSurface)::DownCast(faces.front()->Copy());
    std::vector<bool> used(faces.size(), false);
    used[0] = true;
    for (std::size_t round = 1; round < faces.size(); ++round) {
        const double tol = 1e-7 * poleBoxSize(joined);
        bool found = false;
        for (std::size_t k = 0; k < faces.size() && !found; ++k) {
            if (used[k]) continue;
            for (const Side a : kSides) {
                for (const Side b : kSides) {
                    const int how = coincide(joined, a, faces[k], b, tol);
                    if (how == 0) continue;
                    Handle(Geom_BSplineSurface) face = Handle(Geom_BSplineSurface)::DownCast(faces[k]->Copy());
                    turnSide(joined, a, true);
                    turnSide(face, b, false);
                    if (coincide(joined, Side::VMax, face, Side::VMin, tol) < 0) face->UReverse();  // the other way round: turned over
                    joined = joinAlongV(joined, face, tol, names[k]);
                    used[k] = found = true;
                    break;
                }
                if (found) break;
            }
        }
        if (!found) {
            std::string left;
            for (std::size_t k = 0; k < faces.size(); ++k)
                if (!used[k]) left += (left.empty() ? "" : ", ") + names[k];
            throw Error(ErrorCode::InvalidArgument, left + ": no whole side in common with the faces joined before (" + names.front() +
                                                        " ...): a shell is joined only where its faces meet side to side");
        }
    }
    return joined;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
