// Surface-surface intersection per tow pair (issue 3): towgeom (OpenCASCADE's marching from
// facet-crossing seeds, consolidated and refined) against SISL (s1859 topology + s1310
// marching, the engine of the original method) on the same B-spline surfaces at the same
// geometric tolerance. Prints per-pair times and their ratio. Goal: towgeom not slower; exits 3
// when it is missed (bench_goal.hpp; --smoke: the ratio is only required to be measured).
//   bench_ssi_sisl [--tows N] [--sections M] [--points P] [--pairs K] [--smoke]
#include <towgeom/towgeom.hpp>

#include "bench_goal.hpp"
#include "bench_twill.hpp"

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <sisl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "surface/tow_surface_impl.hpp"

namespace {

double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The same surface for SISL: OCCT's periodic v made non-periodic (same geometry), flat knots,
/// control points with the first parameter running fastest.
SISLSurf* toSisl(const towgeom::TowSurface& tow)
{
    Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(tow.impl().surface->Copy());
    s->SetVNotPeriodic();
    const int nu = s->NbUPoles(), nv = s->NbVPoles(), pu = s->UDegree(), pv = s->VDegree();
    TColStd_Array1OfReal ku(1, nu + pu + 1), kv(1, nv + pv + 1);
    s->UKnotSequence(ku);
    s->VKnotSequence(kv);
    std::vector<double> et1(ku.begin(), ku.end()), et2(kv.begin(), kv.end()), coef;
    coef.reserve(3 * nu * nv);
    for (int j = 1; j <= nv; ++j)
        for (int i = 1; i <= nu; ++i) {
            const gp_Pnt& p = s->Pole(i, j);
            coef.insert(coef.end(), {p.X(), p.Y(), p.Z()});
        }
    return newSurf(nu, nv, pu + 1, pv + 1, et1.data(), et2.data(), coef.data(), 1, 3, 1);
}

struct SislResult {
    int curves = 0, closed = 0, status = 0;
};

SislResult sislIntersect(SISLSurf* a, SISLSurf* b, double tolerance)
{
    SislResult r;
    int points = 0, curves = 0, stat = 0;
    double *par1 = nullptr, *par2 = nullptr;
    SISLIntcurve** list = nullptr;
    s1859(a, b, 1e-15, tolerance, &points, &par1, &par2, &curves, &list, &stat);
    r.status = stat;
    for (int k = 0; k < curves; ++k) {
        int st = 0;
        s1310(a, b, list[k], tolerance, 0.0, 2, 3, &st);
        if (st < 0) r.status = st;
        ++r.curves;
        const SISLCurve* c = list[k]->pgeom;
        if (c && c->in > 1) {
            const double* first = c->ecoef;
            const double* last = c->ecoef + 3 * (c->in - 1);
            const double d = std::sqrt(std::pow(first[0] - last[0], 2) + std::pow(first[1] - last[1], 2) + std::pow(first[2] - last[2], 2));
            r.closed += d <= 1e3 * tolerance;
        }
    }
    if (list) freeIntcrvlist(list, curves);
    std::free(par1);
    std::free(par2);
    return r;
}

}  // namespace

int main(int argc, char** argv)
{
    const towgeom::bench::TwillArgs args = towgeom::bench::parseTwillArgs(argc, argv);
    const towgeom::WeaveOptions& o = args.weave;
    const std::size_t pairs = static_cast<std::size_t>(args.number("--pairs", 8));
    const towgeom::Textile textile = towgeom::generateWeave(o);
    std::vector<towgeom::TowSurface> tows;
    for (const towgeom::TowStack& s : textile.stacks()) tows.push_back(towgeom::TowSurface::fit(s));
    std::printf("towgeom bench_ssi_sisl: 2/2 twill, %zu tows of %zu sections x %zu points; %zu crossing pairs\n",
                tows.size(), o.sectionsPerYarn, o.pointsPerSection, std::min(pairs, textile.crossings.size()));
    std::printf("%-18s %10s %10s %8s %8s %8s\n", "pair", "towgeom_s", "sisl_s", "ratio", "loops", "sisl");
    double tTowgeom = 0.0, tSisl = 0.0;  // over the pairs where SISL agrees (see below)
    std::size_t ours = 0, sislClosed = 0, pairsRun = 0, sislFailed = 0, sislDisagrees = 0, compared = 0;
    for (std::size_t k = 0; k < pairs && k < textile.crossings.size(); ++k) {
        const towgeom::TowSurface& a = tows[textile.crossings[k].warp];
        const towgeom::TowSurface& b = tows[textile.crossings[k].weft];
        const double tolerance = 1e-7 * std::min(a.towSize(), b.towSize());
        towgeom::IntersectionOptions options;
        options.tolerance = tolerance;
        options.threads = 1;
        auto t0 = std::chrono::steady_clock::now();
        const std::vector<towgeom::IntersectionLoop> loops = towgeom::intersectPair(a, b, options);
        const double tt = since(t0);
        SISLSurf* sa = toSisl(a);
        SISLSurf* sb = toSisl(b);
        t0 = std::chrono::steady_clock::now();
        const SislResult s = sislIntersect(sa, sb, tolerance);
        const double ts = since(t0);
        freeSurf(sa);
        freeSurf(sb);
        std::size_t closed = 0;
        for (const auto& l : loops) closed += l.closed();
        ours += closed;
        sislClosed += static_cast<std::size_t>(std::max(s.closed, 0));
        ++pairsRun;
        // The peer checked before its time counts: a pair SISL fails on (error status), or where
        // it finds another number of closed loops, is reported and left out of the ratio.
        if (s.status < 0) {
            ++sislFailed;
        } else if (static_cast<std::size_t>(s.closed) != closed) {
            ++sislDisagrees;
        } else {
            ++compared;
            tTowgeom += tt;
            tSisl += ts;
        }
        std::printf("%-18s %10.4f %10.4f %7.1fx %8zu %5d/%d%s\n", (a.name() + " x " + b.name()).c_str(), tt, ts, ts / tt,
                    closed, s.closed, s.curves, s.status < 0 ? " (SISL error)" : "");
    }
    std::printf("%-18s %10.4f %10.4f %7.1fx  (the %zu pairs where SISL agrees; goal: towgeom not slower, ratio >= 1)\n",
                "total", tTowgeom, tSisl, tSisl / tTowgeom, compared);
    std::printf("SISL failed on %zu and found another number of closed loops on %zu of %zu pairs\n", sislFailed,
                sislDisagrees, pairsRun);
    // Every crossing of the generated twill overlaps: one closed loop each (CGAL agrees on the
    // faceted tubes, see bench_detect and the tests).
    std::printf("closed loops at %zu crossings: towgeom %zu, SISL %zu\n", pairsRun, ours, sislClosed);
    towgeom::bench::Goals goals(args.flag("--smoke"));
    goals.require("towgeom finds one closed loop per crossing", ours == pairsRun && pairsRun > 0);
    // towgeom's one closed loop per crossing is what CGAL finds on the faceted tubes too
    // (bench_detect, the tests): a pair where SISL fails or finds another count is SISL's miss,
    // left out of the ratio; the ratio must still rest on most of the pairs.
    goals.require("SISL agrees with towgeom on at least half of the pairs (the ratio's pairs)", 2 * compared >= pairsRun);
    goals.ratioAtLeast("towgeom vs SISL", tSisl / tTowgeom, 1.0);
    return goals.exitStatus();
}
