#include "intersect/intersection_point.hpp"

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <Eigen/Dense>

#include <cmath>

#include "surface/occt_convert.hpp"

namespace towgeom::detail {

namespace {

struct Eval {
    gp_Pnt pa, pb;
    gp_Vec dua, dva, dub, dvb;
};

Eval evaluate(const SurfacePair& s, const PointOn2& x)
{
    Eval e;
    if (!s.evalA.IsNull() && !s.evalB.IsNull()) {
        s.evalA->D1(x.ua, x.va, e.pa, e.dua, e.dva);
        s.evalB->D1(x.ub, x.vb, e.pb, e.dub, e.dvb);
    } else {
        s.a->D1(x.ua, x.va, e.pa, e.dua, e.dva);
        s.b->D1(x.ub, x.vb, e.pb, e.dub, e.dvb);
    }
    return e;
}

bool inside(const SurfacePair& s, const PointOn2& x)
{
    const double ea = 1e-9 * (s.uMaxA - s.uMinA), eb = 1e-9 * (s.uMaxB - s.uMinB);
    return x.ua >= s.uMinA - ea && x.ua <= s.uMaxA + ea && x.ub >= s.uMinB - eb && x.ub <= s.uMaxB + eb;
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

}  // namespace towgeom::detail
