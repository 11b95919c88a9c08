#include "intersect/intersection_point.hpp"

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "surface/occt_convert.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

struct Eval {
    gp_Pnt pa, pb;
    gp_Vec dua, dva, dub, dvb;
};

/// One side: on its cap when the pair has caps and u lies beyond the tube's end.
void evaluateSide(const Handle(Geom_BSplineSurface)& surface, const Handle(GeomAdaptor_Surface)& cached, const TowCaps* caps,
                  double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv)
{
    if (caps && !cached.IsNull() && caps->capAt(u))
        chartD1(*cached, *caps, u, v, p, du, dv);
    else if (!cached.IsNull())
        cached->D1(u, v, p, du, dv);
    else
        surface->D1(u, v, p, du, dv);
}

Eval evaluate(const SurfacePair& s, const PointOn2& x)
{
    Eval e;
    evaluateSide(s.a, s.evalA, s.capsA, x.ua, x.va, e.pa, e.dua, e.dva);
    evaluateSide(s.b, s.evalB, s.capsB, x.ub, x.vb, e.pb, e.dub, e.dvb);
    return e;
}

bool inside(const SurfacePair& s, const PointOn2& x)
{
    const double ea = 1e-9 * (s.uMaxA - s.uMinA), eb = 1e-9 * (s.uMaxB - s.uMinB);
    const double loA = s.capsA ? s.capsA->uLow() : s.uMinA, hiA = s.capsA ? s.capsA->uHigh() : s.uMaxA;
    const double loB = s.capsB ? s.capsB->uLow() : s.uMinB, hiB = s.capsB ? s.capsB->uHigh() : s.uMaxB;
    return x.ua >= loA - ea && x.ua <= hiA + ea && x.ub >= loB - eb && x.ub <= hiB + eb;
}

}  // namespace

Vector3 intersectionTangent(const SurfacePair& s, const PointOn2& x)
{
    const Eval e = evaluate(s, x);
    const gp_Vec t = e.dua.Crossed(e.dva).Crossed(e.dub.Crossed(e.dvb));
    const double n = t.Magnitude();
    if (!(n > 0.0) || !std::isfinite(n)) return {};
    return fromOcct(t / n);
}

bool refineOnIntersection(const SurfacePair& s, PointOn2& x, const PointCondition& c, double tolerance)
{
    PointOn2 y = x;
    constexpr int kMaxIterations = 12;
    bool polish = false;
    for (int it = 0; it < kMaxIterations; ++it) {
        if (!inside(s, y)) return false;
        const Eval e = evaluate(s, y);
        const gp_Vec f(e.pb, e.pa);  // S_A - S_B
        Eigen::Matrix4d J;
        Eigen::Vector4d F;
        J << e.dua.X(), e.dva.X(), -e.dub.X(), -e.dvb.X(),  //
            e.dua.Y(), e.dva.Y(), -e.dub.Y(), -e.dvb.Y(),    //
            e.dua.Z(), e.dva.Z(), -e.dub.Z(), -e.dvb.Z(),    //
            0, 0, 0, 0;
        F << f.X(), f.Y(), f.Z(), 0.0;
        switch (c.kind) {
        case PointCondition::Kind::Plane: {
            const gp_Vec n(c.normal.x, c.normal.y, c.normal.z);
            J(3, 0) = n.Dot(e.dua);
            J(3, 1) = n.Dot(e.dva);
            F(3) = n.Dot(gp_Vec(toOcct(c.origin), e.pa));
            break;
        }
        case PointCondition::Kind::FixVA: J(3, 1) = 1.0; F(3) = y.va - c.value; break;
        case PointCondition::Kind::FixVB: J(3, 3) = 1.0; F(3) = y.vb - c.value; break;
        case PointCondition::Kind::FixUA: J(3, 0) = 1.0; F(3) = y.ua - c.value; break;
        case PointCondition::Kind::FixUB: J(3, 2) = 1.0; F(3) = y.ub - c.value; break;
        }
        // Converged well below the tolerance: one step more (Newton converges quadratically)
        // costs little and leaves the gap at rounding level.
        if (f.Magnitude() <= 1e-3 * tolerance && std::abs(F(3)) <= 1e-3 * tolerance) {
            if (polish) break;
            polish = true;
        }
        const Eigen::FullPivLU<Eigen::Matrix4d> lu(J);
        if (lu.rank() < 4) return false;
        const Eigen::Vector4d dx = lu.solve(-F);
        if (!dx.allFinite()) return false;
        // Damp steps that would jump far in parameter space (a bad guess, not a correction).
        const double size = dx.cwiseAbs().maxCoeff();
        const double scale = size > 0.05 ? 0.05 / size : 1.0;
        y.ua += scale * dx(0);
        y.va += scale * dx(1);
        y.ub += scale * dx(2);
        y.vb += scale * dx(3);
    }
    if (!inside(s, y)) return false;
    const Eval e = evaluate(s, y);
    y.gap = e.pa.Distance(e.pb);
    if (!(y.gap <= tolerance)) return false;
    y.point = fromOcct(gp_Pnt(0.5 * (e.pa.XYZ() + e.pb.XYZ())));
    x = y;
    return true;
}

bool refineTriplePoint(const SurfacePair& ab, const SurfacePair& ac, PointOn3& x, double tolerance)
{
    std::array<double, 6> y = x.uv;
    const auto inRange = [](double u, double lo, double hi) { return u >= lo - 1e-9 * (hi - lo) && u <= hi + 1e-9 * (hi - lo); };
    const auto insideAll = [&] {
        return inRange(y[0], ab.uMinA, ab.uMaxA) && inRange(y[2], ab.uMinB, ab.uMaxB) && inRange(y[4], ac.uMinB, ac.uMaxB);
    };
    struct Three {
        gp_Pnt p[3];
        gp_Vec du[3], dv[3];
    };
    const auto evaluate3 = [&] {
        Three e;
        const auto eval = [](const SurfacePair& s, bool a, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
            const Handle(GeomAdaptor_Surface)& cached = a ? s.evalA : s.evalB;
            if (!cached.IsNull())
                cached->D1(u, v, p, du, dv);
            else
                (a ? s.a : s.b)->D1(u, v, p, du, dv);
        };
        eval(ab, true, y[0], y[1], e.p[0], e.du[0], e.dv[0]);
        eval(ab, false, y[2], y[3], e.p[1], e.du[1], e.dv[1]);
        eval(ac, false, y[4], y[5], e.p[2], e.du[2], e.dv[2]);
        return e;
    };
    constexpr int kMaxIterations = 16;
    bool polish = false;
    for (int it = 0; it < kMaxIterations; ++it) {
        if (!insideAll()) return false;
        const Three e = evaluate3();
        const gp_Vec fb(e.p[1], e.p[0]), fc(e.p[2], e.p[0]);  // S_A - S_B, S_A - S_C
        Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> F;
        for (int r = 0; r < 3; ++r) {
            J(r, 0) = J(r + 3, 0) = e.du[0].Coord(r + 1);
            J(r, 1) = J(r + 3, 1) = e.dv[0].Coord(r + 1);
            J(r, 2) = -e.du[1].Coord(r + 1);
            J(r, 3) = -e.dv[1].Coord(r + 1);
            J(r + 3, 4) = -e.du[2].Coord(r + 1);
            J(r + 3, 5) = -e.dv[2].Coord(r + 1);
            F(r) = fb.Coord(r + 1);
            F(r + 3) = fc.Coord(r + 1);
        }
        if (fb.Magnitude() <= 1e-3 * tolerance && fc.Magnitude() <= 1e-3 * tolerance) {
            if (polish) break;
            polish = true;
        }
        const Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>> lu(J);
        if (lu.rank() < 6) return false;
        const Eigen::Matrix<double, 6, 1> dx = lu.solve(-F);
        if (!dx.allFinite()) return false;
        const double size = dx.cwiseAbs().maxCoeff();
        const double scale = size > 0.05 ? 0.05 / size : 1.0;
        for (int k = 0; k < 6; ++k) y[static_cast<std::size_t>(k)] += scale * dx(k);
    }
    if (!insideAll()) return false;
    const Three e = evaluate3();
    const double gap = std::max({e.p[0].Distance(e.p[1]), e.p[0].Distance(e.p[2]), e.p[1].Distance(e.p[2])});
    if (!(gap <= tolerance)) return false;
    x.uv = y;
    x.gap = gap;
    x.point = fromOcct(gp_Pnt((e.p[0].XYZ() + e.p[1].XYZ() + e.p[2].XYZ()) / 3.0));
    return true;
}

double capGuess(const SurfacePair& s, const PointOn2& a, const PointOn2& b, PointOn2& m)
{
    double turn = 0.0;
    const auto side = [&](const TowCaps* caps, const Handle(GeomAdaptor_Surface)& tube, double ua, double ub, double va, double vb,
                          double& u, double& v) {
        if (!caps || tube.IsNull()) return;
        const double eps = 1e-9 * (caps->uMax - caps->uMin);
        const auto rimOf = [&](double x) -> const CapChart* {
            if (const CapChart* c = caps->capAt(x)) return c;
            if (std::abs(x - caps->uMin) <= eps && caps->start.valid) return &caps->start;
            if (std::abs(x - caps->uMax) <= eps && caps->end.valid) return &caps->end;
            return nullptr;
        };
        const CapChart *ca = rimOf(ua), *cb = rimOf(ub);
        const CapChart* cap = caps->capAt(ua) ? ca : caps->capAt(ub) ? cb : ca == cb ? ca : nullptr;
        double cu = 0.0, cv = 0.0;
        if (!cap) return;
        turn = std::max(turn, std::abs(vb - va) / (cap->v.back() - cap->v.front()));
        if (capParameters(*tube, *cap, toOcct(m.point), v, cu, cv)) {
            u = cu;
            v = cv;
            return;
        }
        // At the cap's centre (a chord through it), where v is undefined: a point a little
        // along the chord instead.
        const Vector3 along = b.point - a.point;
        const Point3 off = m.point + 1e-3 * along;
        if (capParameters(*tube, *cap, toOcct(off), v, cu, cv)) {
            m.point = off;
            u = cu;
            v = cv;
        }
    };
    side(s.capsA, s.evalA, a.ua, b.ua, a.va, b.va, m.ua, m.va);
    side(s.capsB, s.evalB, a.ub, b.ub, a.vb, b.vb, m.ub, m.vb);
    return turn;
}

bool refineNearest(const SurfacePair& s, PointOn2& x, double tolerance)
{
    const Eval e = evaluate(s, x);
    gp_Vec t = e.dua.Crossed(e.dva).Crossed(e.dub.Crossed(e.dvb));
    if (!(t.Magnitude() > 0.0)) return false;
    PointCondition c;
    c.kind = PointCondition::Kind::Plane;
    c.origin = fromOcct(gp_Pnt(0.5 * (e.pa.XYZ() + e.pb.XYZ())));
    t.Normalize();
    c.normal = fromOcct(t);
    return refineOnIntersection(s, x, c, tolerance);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
