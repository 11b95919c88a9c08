#include "cell/tow_cuts.hpp"

#include <GeomAPI_IntCS.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Plane.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "cell/axis.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {


std::string faceText(CellFace f) { return std::string("the cell's face ") + cellFaceName(f); }

/// Probes around the tow when deciding whether a plane cuts it all around.
constexpr int kProbes = 32;
/// Samples of a graded mesh size between two probes of a cut.
constexpr int kCutSizeSamples = 8;

/// Every u in [uMin, uMax] where the isoline S(., @p v) meets the plane x_a = @p c (OCCT's
/// curve/surface intersection, polished by Newton's method on the coordinate); @p inPlane is set
/// when a piece of the isoline lies in the plane.
std::vector<double> crossings(const Handle(Geom_BSplineSurface)& s, double v, int a, double c, const ParameterRange& r,
                              bool& inPlane)
{
    const Handle(Geom_Curve) iso = s->VIso(v);
    gp_Pnt origin(0.0, 0.0, 0.0);
    origin.SetCoord(a + 1, c);
    const Handle(Geom_Plane) plane = new Geom_Plane(origin, gp_Dir(a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, a == 2 ? 1.0 : 0.0));
    GeomAPI_IntCS meet(iso, plane);
    if (!meet.IsDone()) throw Error(ErrorCode::Internal, "OCCT's curve/plane intersection failed");
    inPlane = meet.NbSegments() > 0;
    std::vector<double> us;
    for (int i = 1; i <= meet.NbPoints(); ++i) {
        double pu = 0.0, pv = 0.0, w = 0.0;
        meet.Parameters(i, pu, pv, w);
        if (!(w >= r.uMin && w <= r.uMax)) continue;
        for (int k = 0; k < 4; ++k) {  // Newton on x_a(S(w, v)) = c, kept only while it stays in the range
            gp_Pnt p;
            gp_Vec du, dv;
            s->D1(w, v, p, du, dv);
            const double d = du.Coord(a + 1);
            const double next = d == 0.0 ? w : w - (p.Coord(a + 1) - c) / d;
            if (!(next >= r.uMin && next <= r.uMax)) break;
            w = next;
        }
        us.push_back(w);
    }
    std::sort(us.begin(), us.end());
    const double same = 1e-9 * (r.uMax - r.uMin);
    us.erase(std::unique(us.begin(), us.end(), [&](double x, double y) { return y - x < same; }), us.end());
    return us;
}

/// A face's cut of one tow before it is kept: the face, the end it closes and u per station.
struct Candidate {
    CellFace face;
    int end = 0;
    std::vector<double> u;
    bool onRim = false;  ///< the end section lies in the face's plane (within kOnFace): cut on its rim
};

/// How close (relative to the tow's size) an end section must lie to a face's plane to be on it.
constexpr double kOnFace = 1e-9;

/// Whether the section at @p u lies within @p tol of the plane x_a = @p c at every probe.
bool sectionOnPlane(const Handle(Geom_BSplineSurface)& s, double u, int a, double c, const ParameterRange& r, double tol)
{
    for (int j = 0; j < kProbes; ++j)
        if (!(std::abs(s->Value(u, r.vMin + r.vPeriod() * j / kProbes).Coord(a + 1) - c) <= tol)) return false;
    return true;
}

}  // namespace

bool CellCuts::keeps(std::size_t tow, const UV& p) const
{
    if (outside[tow]) return false;
    for (int end = 0; end < 2; ++end) {
        const auto& cut = cuts[tow][static_cast<std::size_t>(end)];
        if (!cut) continue;
        // Stations in increasing v from the seam (uniform but for loops' crossings of the face).
        const std::vector<UV>& st = cut->uv;
        const std::size_t n = st.size();
        const double v0 = st[0].v, period = vPeriod[tow];
        double x = v0 + std::fmod(p.v - v0, period);
        if (x < v0) x += period;
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(st.begin(), st.end(), x, [](double v, const UV& q) { return v < q.v; }) - st.begin() - 1);
        const double vk = st[k].v, vNext = k + 1 < n ? st[k + 1].v : v0 + period;
        const double f = vNext > vk ? (x - vk) / (vNext - vk) : 0.0;
        const double g = (1.0 - f) * st[k].u + f * st[(k + 1) % n].u;
        if (end == 0 ? !(p.u > g) : !(p.u < g)) return false;
    }
    return true;
}

std::optional<std::array<double, 2>> CellCuts::keptSpan(std::size_t tow, const ParameterRange& range) const
{
    if (outside[tow]) return std::nullopt;
    std::array<double, 2> span{range.uMin, range.uMax};
    const auto& [start, end] = cuts[tow];
    if (start)
        span[0] = std::min_element(start->uv.begin(), start->uv.end(), [](const UV& a, const UV& b) { return a.u < b.u; })->u;
    if (end) span[1] = std::max_element(end->uv.begin(), end->uv.end(), [](const UV& a, const UV& b) { return a.u < b.u; })->u;
    return span;
}

LoopConstraint CellCuts::constraint(std::size_t tow, int end, const ParameterRange& range) const
{
    const TowCut& cut = *cuts[tow][static_cast<std::size_t>(end)];
    LoopConstraint c;
    c.uv = cut.uv;
    c.nodes = cut.nodes;
    c.uv.push_back({cut.uv[0].u, range.vMax});
    c.nodes.push_back(cut.nodes[0]);
    return c;
}

CellCuts cutTows(const std::vector<TowSurface>& tows, const Cell& cell, const std::vector<double>& towH, std::vector<Point3>& nodes,
                 const std::vector<FaceCrossing>& loopCrossings, const std::vector<std::function<double(const UV&)>>& sizeAt)
{
    CellCuts out;
    out.outside.assign(tows.size(), 0);
    out.cuts.resize(tows.size());
    for (const TowSurface& t : tows) out.vPeriod.push_back(t.parameterRange().vPeriod());
    std::vector<std::vector<Point3>> positions(tows.size() * 2);  // per tow and end, the stations' points
    std::vector<std::vector<std::size_t>> given(tows.size() * 2);  // per station: its node if it has one (a crossing's)
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowSurface& tow = tows[t];
        const Handle(Geom_BSplineSurface)& s = tow.impl().surface;
        const ParameterRange r = tow.parameterRange();
        const std::string where = "tow '" + tow.name() + "'";
        const auto refuse = [&](const std::string& what) { throw Error(ErrorCode::InvalidArgument, where + ": " + what); };
        // The surface lies in its poles' box.
        BoundingBox box;
        for (int i = 1; i <= s->NbUPoles(); ++i)
            for (int j = 1; j <= s->NbVPoles(); ++j) {
                const gp_Pnt& p = s->Pole(i, j);
                box.add({p.X(), p.Y(), p.Z()});
            }
        // Each face first classified, so that a tow wholly outside through one face is not
        // refused for how another face's plane meets it.
        std::vector<Candidate> candidates;
        bool outside = false;
        std::string refusal;
        for (int f = 0; f < 6 && !outside; ++f) {
            const CellFace face = static_cast<CellFace>(f);
            const int a = axisOf(face);
            const double c = cell.plane(face), sign = isMaxFace(face) ? 1.0 : -1.0;  // outside: sign (x_a - c) > 0
            const double lo = std::min(sign * (coord(box.min, a) - c), sign * (coord(box.max, a) - c));
            const double hi = std::max(sign * (coord(box.min, a) - c), sign * (coord(box.max, a) - c));
            // An end section in the plane (a scan cut at the cell's faces, within kOnFace of the
            // tow's size): the face cuts it on its rim, whether the section lies a hair inside,
            // on or beyond the plane.
            const double touch = kOnFace * tow.towSize();
            if (lo >= -touch) {  // wholly beyond the plane, or touching it from there
                outside = true;
                break;
            }
            if (hi < -touch) continue;  // wholly inside this face's half-space
            if (hi <= touch) {
                const bool startOn = sectionOnPlane(s, r.uMin, a, c, r, touch);
                if (startOn || sectionOnPlane(s, r.uMax, a, c, r, touch)) {
                    candidates.push_back({face, startOn ? 0 : 1, {}, true});
                    continue;
                }
            }
            if (hi < 0.0) continue;  // inside, a hair from the plane but no end section on it
            int none = 0;
            bool many = false;
            for (int j = 0; j < kProbes && !many; ++j) {
                bool inPlane = false;
                const std::size_t count = crossings(s, r.vMin + r.vPeriod() * j / kProbes, a, c, r, inPlane).size();
                many = inPlane || count > 1;
                if (count == 0) ++none;
            }
            const auto note = [&](const std::string& what) {
                if (refusal.empty()) refusal = what;
            };
            if (many) {
                note("it crosses the plane of " + faceText(face) +
                     " more than once along its length, or runs in it: the cell's faces must cut each tow at most once, across it");
                continue;
            }
            if (none == kProbes) {  // no isoline crosses: the tow lies on one side, or the plane runs along it
                int beyond = 0;
                for (int j = 0; j < kProbes; ++j)
                    if (sign * (s->Value(0.5 * (r.uMin + r.uMax), r.vMin + r.vPeriod() * j / kProbes).Coord(a + 1) - c) > 0.0) ++beyond;
                if (beyond != 0 && beyond != kProbes)
                    note("the plane of " + faceText(face) + " runs along it (cuts it lengthwise): the cell's faces must cut each tow across it");
                if (beyond == kProbes) outside = true;
                continue;
            }
            if (none != 0) {
                note("the plane of " + faceText(face) +
                     " cuts it only partly (along its side, not all around): the cell's faces must cut each tow across it");
                continue;
            }
            // The end beyond the plane: the farther out of the two (a start lying in the plane,
            // a cell face through the tow's end, is still the end the face cuts).
            const int end = sign * s->Value(r.uMin, r.vMin).Coord(a + 1) > sign * s->Value(r.uMax, r.vMin).Coord(a + 1) ? 0 : 1;
            candidates.push_back({face, end, {}});
        }
        if (!outside && !refusal.empty()) refuse(refusal);
        if (outside) {
            out.outside[t] = 1;
            continue;
        }
        if (candidates.empty()) continue;
        // Stations at the tow's mesh size around the first cut.
        const int a0 = axisOf(candidates[0].face);
        const double c0 = cell.plane(candidates[0].face);
        // A cut is kept a hair inside the tow's ends (1e-9 of the u range).
        const double hair = 1e-9 * (r.uMax - r.uMin);
        const auto rimOf = [&](int end) { return end == 0 ? r.uMin + hair : r.uMax - hair; };
        double perimeter = 0.0;
        Point3 previous;
        std::vector<double> probeU;
        for (int j = 0; j <= kProbes; ++j) {
            bool inPlane = false;
            const double v = r.vMin + r.vPeriod() * (j % kProbes) / kProbes;
            const std::vector<double> us = candidates[0].onRim ? std::vector<double>{rimOf(candidates[0].end)} : crossings(s, v, a0, c0, r, inPlane);
            if (us.empty()) refuse("the plane of " + faceText(candidates[0].face) + " does not cut it once all around");
            const gp_Pnt g = s->Value(us.front(), v);
            const Point3 p{g.X(), g.Y(), g.Z()};
            if (j > 0) perimeter += distance(p, previous);
            previous = p;
            probeU.push_back(us.front());
        }
        // Evenly around at the tow's mesh size, or at the smallest its graded size asks for along
        // the cut (sampled 8 times between probes, u between the probes'): the cut's chords are
        // constraints the mesher never splits.
        double h = towH[t];
        if (t < sizeAt.size() && sizeAt[t])
            for (int j = 0; j < kProbes * kCutSizeSamples; ++j) {
                const double f = static_cast<double>(j % kCutSizeSamples) / kCutSizeSamples;
                const std::size_t i = static_cast<std::size_t>(j / kCutSizeSamples);
                const UV at{(1.0 - f) * probeU[i] + f * probeU[i + 1], r.vMin + r.vPeriod() * static_cast<double>(j) / (kProbes * kCutSizeSamples)};
                h = std::min(h, sizeAt[t](at));
            }
        const std::size_t n = std::max<std::size_t>(8, static_cast<std::size_t>(std::ceil(perimeter / h)));
        for (Candidate& cand : candidates) {
            for (std::size_t k = 0; k < n; ++k) {
                // A face through the tow's end section cuts it on its rim: the cut is kept a hair
                // inside (1e-9 of the u range; its nodes are put on the plane all the same), so
                // the end cap is dropped and the cut closes the tow.
                if (cand.onRim) {
                    cand.u.push_back(rimOf(cand.end));
                    continue;
                }
                bool inPlane = false;
                const double v = r.vMin + r.vPeriod() * static_cast<double>(k) / static_cast<double>(n);
                const std::vector<double> us = crossings(s, v, axisOf(cand.face), cell.plane(cand.face), r, inPlane);
                if (us.size() != 1 || inPlane)
                    refuse("the plane of " + faceText(cand.face) + " does not cut it once all around");
                cand.u.push_back(cand.end == 0 ? std::max(us.front(), rimOf(0)) : std::min(us.front(), rimOf(1)));
            }
        }
        // Per end the cut that bounds the kept part: of two faces across one end, one must lie
        // beyond the other all around (else the tow crosses the box's edge between them).
        std::array<const Candidate*, 2> active{nullptr, nullptr};
        for (const Candidate& cand : candidates) {
            const Candidate*& best = active[static_cast<std::size_t>(cand.end)];
            if (!best) {
                best = &cand;
                continue;
            }
            const auto inner = [&](double x, double y) { return cand.end == 0 ? x > y : x < y; };
            bool allInner = true, allOuter = true;
            for (std::size_t k = 0; k < n; ++k) {
                if (!inner(cand.u[k], best->u[k])) allInner = false;
                if (inner(cand.u[k], best->u[k])) allOuter = false;
            }
            if (allInner)
                best = &cand;
            else if (!allOuter)
                refuse(std::string("it crosses the edge of the cell's box between the faces ") + cellFaceName(cand.face) + " and " +
                       cellFaceName(best->face) + ": the cell's faces must cut each tow across it, away from the box's edges");
        }
        if (active[0] && active[1]) {
            std::size_t kept = 0;
            for (std::size_t k = 0; k < n; ++k)
                if (active[0]->u[k] < active[1]->u[k]) ++kept;
            if (kept == 0) {
                out.outside[t] = 1;
                continue;
            }
            if (kept != n)
                refuse(std::string("the faces ") + cellFaceName(active[0]->face) + " and " + cellFaceName(active[1]->face) +
                       " cut it across each other: it crosses the box's edge between them");
        }
        for (int end = 0; end < 2; ++end) {
            const Candidate* cand = active[static_cast<std::size_t>(end)];
            if (!cand) continue;
            TowCut cut;
            cut.face = cand->face;
            const int a = axisOf(cand->face);
            std::vector<Point3>& at = positions[2 * t + static_cast<std::size_t>(end)];
            for (std::size_t k = 0; k < n; ++k) {
                const UV uv{cand->u[k], r.vMin + r.vPeriod() * static_cast<double>(k) / static_cast<double>(n)};
                cut.uv.push_back(uv);
                const gp_Pnt g = s->Value(uv.u, uv.v);
                Point3 p{g.X(), g.Y(), g.Z()};
                coord(p, a) = cell.plane(cand->face);
                for (int b = 0; b < 3; ++b)
                    if (b != a && !(coord(p, b) > coord(cell.min, b) && coord(p, b) < coord(cell.max, b)))
                        refuse("its cut by " + faceText(cand->face) +
                               " leaves the face's rectangle: it crosses an edge of the cell's box (the cell's faces must cut each "
                               "tow across it, away from the box's edges)");
                at.push_back(p);
                given[2 * t + static_cast<std::size_t>(end)].push_back(SIZE_MAX);
            }
            out.cuts[t][static_cast<std::size_t>(end)] = std::move(cut);
        }
    }
    // The loops' crossings of the faces: stations of both tows' cuts there. With a periodic cell
    // a max face's crossing is its partner's on the min face moved (FaceCrossing::partner): the
    // same edit, at the same indices, keeps the two cuts' stations paired.
    std::vector<std::size_t> maxPartner(loopCrossings.size(), SIZE_MAX);
    for (std::size_t i = 0; i < loopCrossings.size(); ++i)
        if (cell.periodic && loopCrossings[i].partner < loopCrossings.size()) maxPartner[loopCrossings[i].partner] = i;
    const auto endCutBy = [&](std::size_t t, const FaceCrossing& x) {
        for (int e = 0; e < 2; ++e)
            if (out.cuts[t][static_cast<std::size_t>(e)] && out.cuts[t][static_cast<std::size_t>(e)]->face == x.face)
                return static_cast<std::size_t>(2 * t + static_cast<std::size_t>(e));
        throw Error(ErrorCode::InvalidArgument, "an intersection loop of tows '" + tows[x.towA].name() + "' and '" + tows[x.towB].name() +
                                                    "' crosses the cell's face " + cellFaceName(x.face) + " where that face does not cut tow '" +
                                                    tows[t].name() + "'");
    };
    // Station k of cut c (2 * tow + end): removed, or the crossing x put there.
    const auto erase = [&](std::size_t c, std::size_t k) {
        TowCut& cut = *out.cuts[c / 2][c % 2];
        cut.uv.erase(cut.uv.begin() + static_cast<long>(k));
        positions[c].erase(positions[c].begin() + static_cast<long>(k));
        given[c].erase(given[c].begin() + static_cast<long>(k));
    };
    const auto insert = [&](std::size_t c, std::size_t k, const FaceCrossing& x) {
        TowCut& cut = *out.cuts[c / 2][c % 2];
        cut.uv.insert(cut.uv.begin() + static_cast<long>(k), c / 2 == x.towA ? x.onA : x.onB);
        positions[c].insert(positions[c].begin() + static_cast<long>(k), nodes[x.node]);
        given[c].insert(given[c].begin() + static_cast<long>(k), x.node);
    };
    for (std::size_t i = 0; i < loopCrossings.size(); ++i) {
        const FaceCrossing& x = loopCrossings[i];
        if (cell.periodic && isMaxFace(x.face)) continue;  // with its partner
        const FaceCrossing* twin = maxPartner[i] < loopCrossings.size() ? &loopCrossings[maxPartner[i]] : nullptr;
        if (cell.periodic && !twin)
            throw Error(ErrorCode::Internal, "the intersection loop of tows '" + tows[x.towA].name() + "' and '" + tows[x.towB].name() +
                                                 "': its crossing of the periodic cell's face " + cellFaceName(x.face) + " has no partner");
        for (const std::size_t t : {x.towA, x.towB}) {
            const std::size_t c = endCutBy(t, x);
            const std::size_t d = twin ? endCutBy(t, *twin) : c;
            const UV uv = t == x.towA ? x.onA : x.onB;
            // Stations (not the first, at the seam, nor another crossing) closer than a quarter
            // of the tow's size to the crossing are left out: they would make slivers.
            std::vector<std::size_t> dropped;
            for (std::size_t k = given[c].size(); k-- > 1;)
                if (given[c][k] == SIZE_MAX && distance(positions[c][k], nodes[x.node]) < 0.25 * towH[t]) dropped.push_back(k);
            for (const std::size_t k : dropped) erase(c, k);
            const std::vector<UV>& uvs = out.cuts[t][c % 2]->uv;
            const std::size_t k = static_cast<std::size_t>(
                std::upper_bound(uvs.begin() + 1, uvs.end(), uv.v, [](double v, const UV& q) { return v < q.v; }) - uvs.begin());
            insert(c, k, x);
            if (!twin) continue;
            for (const std::size_t j : dropped) erase(d, j);
            insert(d, k, *twin);
            const std::vector<UV>& moved = out.cuts[t][d % 2]->uv;
            if (moved.size() != uvs.size() || !(moved[k - 1].v < moved[k].v) || (k + 1 < moved.size() && !(moved[k].v < moved[k + 1].v)))
                throw Error(ErrorCode::InvalidArgument, "tow '" + tows[t].name() + "': the intersection loop of tows '" + tows[x.towA].name() +
                                                            "' and '" + tows[x.towB].name() + "' crosses the periodic cell's faces " +
                                                            cellFaceName(x.face) + " and " + cellFaceName(twin->face) +
                                                            " at different places around the tow (or on both sides of its seam): the "
                                                            "textile does not repeat with the cell");
        }
    }
    // A periodic cell: the max face's cut of a tow is its min face's cut moved by the box.
    if (cell.periodic) {
        for (std::size_t t = 0; t < tows.size(); ++t) {
            if (out.outside[t]) continue;
            for (int a = 0; a < 3; ++a) {
                int minEnd = -1, maxEnd = -1;
                for (int end = 0; end < 2; ++end) {
                    const auto& cut = out.cuts[t][static_cast<std::size_t>(end)];
                    if (cut && axisOf(cut->face) == a) (isMaxFace(cut->face) ? maxEnd : minEnd) = end;
                }
                if (minEnd < 0 && maxEnd < 0) continue;
                const auto name = [&](int side) { return std::string(cellFaceName(static_cast<CellFace>(2 * a + side))); };
                if (minEnd < 0 || maxEnd < 0)
                    throw Error(ErrorCode::InvalidArgument,
                                "tow '" + tows[t].name() + "': the periodic cell's face " + name(minEnd < 0 ? 1 : 0) +
                                    " cuts it but the face " + name(minEnd < 0 ? 0 : 1) +
                                    " does not: the textile does not repeat with the cell (or the tow ends inside it)");
                Point3 shift;
                coord(shift, a) = coord(cell.max, a) - coord(cell.min, a);
                const std::vector<Point3>& from = positions[2 * t + static_cast<std::size_t>(minEnd)];
                std::vector<Point3>& to = positions[2 * t + static_cast<std::size_t>(maxEnd)];
                const TowCut& cut = *out.cuts[t][static_cast<std::size_t>(maxEnd)];
                double worst = 0.0;
                for (std::size_t k = 0; k < from.size(); ++k) {
                    Point3 p = from[k] + shift;
                    coord(p, a) = coord(cell.max, a);
                    worst = std::max(worst, distance(p, tows[t].point(cut.uv[k].u, cut.uv[k].v)));
                    to[k] = p;
                }
                if (worst > cell.periodTolerance * tows[t].towSize()) {
                    std::ostringstream m;
                    m.precision(3);
                    m << "tow '" << tows[t].name() << "': its cut by the periodic cell's face " << name(0) << ", moved onto the face "
                      << name(1) << ", lies up to " << worst / tows[t].towSize()
                      << " of the tow's size from its cut there (at the same place around the tow), over the period tolerance "
                      << cell.periodTolerance << ": the textile does not repeat with the cell (or its sections start at another place "
                      << "around the tow there)";
                    throw Error(ErrorCode::InvalidArgument, m.str());
                }
            }
        }
    }
    for (std::size_t t = 0; t < tows.size(); ++t)
        for (int end = 0; end < 2; ++end) {
            auto& cut = out.cuts[t][static_cast<std::size_t>(end)];
            if (!cut) continue;
            const std::vector<Point3>& at = positions[2 * t + static_cast<std::size_t>(end)];
            const std::vector<std::size_t>& node = given[2 * t + static_cast<std::size_t>(end)];
            for (std::size_t k = 0; k < at.size(); ++k) {
                if (node[k] != SIZE_MAX) {
                    cut->nodes.push_back(node[k]);
                    continue;
                }
                cut->nodes.push_back(nodes.size());
                nodes.push_back(at[k]);
            }
        }
    out.cutNode.assign(nodes.size(), 0);
    for (const auto& ends : out.cuts)
        for (const auto& cut : ends)
            if (cut)
                for (std::size_t node : cut->nodes) out.cutNode[node] = 1;
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
