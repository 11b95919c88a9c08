// How much of a tool surface a course plan covers: a regular (u,v) tessellation, each
// triangle's centroid tested against every tow's band (its edges' (u,v) cubics).
#include "towgeom/course_coverage.hpp"

#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <ostream>
#include <string>

#include "placement/periodic_surface.hpp"
#include "placement/tool_face.hpp"
#include "placement/uv_interpolation.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// A tow's band in (u,v): its outline, the right edge densely sampled on its cubic and the left
/// one back (ends closed by straight (u,v) chords), with its box for a quick rejection.
struct Band {
    std::vector<UV> outline;
    UV lo{1e300, 1e300}, hi{-1e300, -1e300};
};

constexpr int kSamplesPerEdge = 256;

/// @p count points along @p c's (u,v) cubic, evenly in its chord parameter (empty for no curve).
std::vector<UV> sampled(const CurveOnSurface& c, int count, const std::string& what)
{
    std::vector<UV> out;
    if (c.uv.size() < 2) return out;
    const Handle(Geom2d_BSplineCurve) cubic = detail::interpolateUV(c.uv, detail::chordParameters(c.uv));
    if (cubic.IsNull()) throw Error(ErrorCode::InvalidArgument, "courseCoverage: " + what + "'s points repeat");
    const double t0 = cubic->FirstParameter(), t1 = cubic->LastParameter();
    for (int k = 0; k < count; ++k) {
        const gp_Pnt2d p = cubic->Value(t0 + (t1 - t0) * k / (count - 1));
        out.push_back({p.X(), p.Y()});
    }
    return out;
}

/// @p right and @p left (a band's edges, on @p s) run on past the end where the face's boundary
/// cut the tow (@p atStart: their starts), straight along their end directions in (u,v), by half
/// the distance between their ends (in space, converted to (u,v) by the surface's rate along
/// each direction): the chord closing the band then lies off the face where the boundary bulges
/// out between the ends (by at most half the chord, a semicircle), so that the band reaches it
/// all across. A hole narrower than that is bridged.
void runOnPastCut(const Handle(Geom_BSplineSurface)& s, std::vector<UV>& right, std::vector<UV>& left, bool atStart)
{
    if (right.size() < 2 || left.size() < 2) return;
    const UV a = atStart ? right.front() : right.back(), b = atStart ? left.front() : left.back();
    const double reach = 0.5 * s->Value(a.u, a.v).Distance(s->Value(b.u, b.v));
    for (std::vector<UV>* e : {&right, &left}) {
        const UV end = atStart ? e->front() : e->back(), next = atStart ? (*e)[1] : (*e)[e->size() - 2];
        const double du = end.u - next.u, dv = end.v - next.v;
        gp_Pnt p;
        gp_Vec su, sv;
        s->D1(end.u, end.v, p, su, sv);
        const double rate = (su * du + sv * dv).Magnitude();  // length in space per unit of (du, dv)
        if (!(rate > 0.0)) continue;
        const UV beyond{end.u + du * reach / rate, end.v + dv * reach / rate};
        e->insert(atStart ? e->begin() : e->end(), beyond);
    }
}

/// The band of @p t; an edge wholly off the face (empty) replaced by the other's mirror image
/// about the centreline in (u,v) (out of the box where it hangs off, so open to the boundary);
/// run on past the ends the boundary cut (runOnPastCut()).
Band bandOf(const Handle(Geom_BSplineSurface)& s, const TowPath& t)
{
    std::vector<UV> right = sampled(t.right, kSamplesPerEdge, "tow " + t.name + "'s right edge");
    std::vector<UV> left = sampled(t.left, kSamplesPerEdge, "tow " + t.name + "'s left edge");
    if (right.empty() != left.empty()) {
        const std::vector<UV> centre = sampled(t.centreline, kSamplesPerEdge, "tow " + t.name + "'s centreline");
        std::vector<UV>& missing = right.empty() ? right : left;
        const std::vector<UV>& other = right.empty() ? left : right;
        for (int k = 0; k < kSamplesPerEdge; ++k) missing.push_back({2.0 * centre[k].u - other[k].u, 2.0 * centre[k].v - other[k].v});
    }
    if (!t.startBoundary.empty()) runOnPastCut(s, right, left, true);
    if (!t.endBoundary.empty()) runOnPastCut(s, right, left, false);
    Band band;
    band.outline = right;
    band.outline.insert(band.outline.end(), left.rbegin(), left.rend());
    for (const UV& p : band.outline) {
        band.lo = {std::min(band.lo.u, p.u), std::min(band.lo.v, p.v)};
        band.hi = {std::max(band.hi.u, p.u), std::max(band.hi.v, p.v)};
    }
    return band;
}

/// Whether @p p lies inside @p band's outline (crossing number).
bool inBand(const Band& band, const UV& p)
{
    if (band.outline.size() < 3 || p.u < band.lo.u || p.u > band.hi.u || p.v < band.lo.v || p.v > band.hi.v) return false;
    bool inside = false;
    const std::size_t n = band.outline.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const UV& a = band.outline[i];
        const UV& b = band.outline[j];
        if ((a.v > p.v) != (b.v > p.v) && p.u < (b.u - a.u) * (p.v - a.v) / (b.v - a.v) + a.u) inside = !inside;
    }
    return inside;
}

/// Whether some copy of @p p (moved by whole periods, in each periodic direction) lies in
/// @p band: only the copies inside the band's box are tried, however many turns it makes.
bool inBandAnywhere(const Handle(Geom_BSplineSurface)& s, const Band& band, const UV& p)
{
    if (band.outline.size() < 3) return false;
    const double pu = s->IsUPeriodic() ? s->UPeriod() : 0.0, pv = s->IsVPeriodic() ? s->VPeriod() : 0.0;
    const auto shifts = [](double at, double lo, double hi, double period) {
        if (!(period > 0.0)) return std::pair<long, long>{0, 0};
        const auto whole = [](double x) { return static_cast<long>(std::clamp(x, -1e6, 1e6)); };  // a million turns at most
        return std::pair<long, long>{whole(std::ceil((lo - at) / period)), whole(std::floor((hi - at) / period))};
    };
    const auto [iu0, iu1] = shifts(p.u, band.lo.u, band.hi.u, pu);
    const auto [iv0, iv1] = shifts(p.v, band.lo.v, band.hi.v, pv);
    for (long i = iu0; i <= iu1; ++i)
        for (long j = iv0; j <= iv1; ++j)
            if (inBand(band, {p.u + static_cast<double>(i) * pu, p.v + static_cast<double>(j) * pv})) return true;
    return false;
}

/// courseCoverage() of the face @p f: triangles whose centroid lies off it left out.
CourseCoverage coverageOn(const detail::ToolFace& f, const CoursePlan& plan, std::size_t cells)
{
    if (cells < 2 || cells > 4000) throw Error(ErrorCode::InvalidArgument, "courseCoverage: 2 to 4000 cells a side");
    const Handle(Geom_BSplineSurface)& s = f.surface;
    CourseCoverage out;
    try {
        std::vector<Band> bands;
        for (const TowPath& t : plan.tows) bands.push_back(bandOf(s, t));
        double u0, u1, v0, v1;
        s->Bounds(u0, u1, v0, v1);
        const std::size_t n = cells + 1;
        std::vector<UV> uv;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const UV p{u0 + (u1 - u0) * static_cast<double>(i) / cells, v0 + (v1 - v0) * static_cast<double>(j) / cells};
                uv.push_back(p);
                out.nodes.push_back(detail::fromOcct(s->Value(p.u, p.v)));
            }
        for (std::size_t i = 0; i < cells; ++i)
            for (std::size_t j = 0; j < cells; ++j) {
                const std::size_t a = i * n + j, b = a + n, c = b + 1, d = a + 1;
                for (const std::array<std::size_t, 3>& t : {std::array<std::size_t, 3>{a, b, c}, std::array<std::size_t, 3>{a, c, d}}) {
                    const double area = 0.5 * norm(cross(out.nodes[t[1]] - out.nodes[t[0]], out.nodes[t[2]] - out.nodes[t[0]]));
                    const UV centre{(uv[t[0]].u + uv[t[1]].u + uv[t[2]].u) / 3.0, (uv[t[0]].v + uv[t[1]].v + uv[t[2]].v) / 3.0};
                    if (f.trim && !detail::onFace(f, centre)) continue;  // off a trimmed face
                    std::size_t count = 0;
                    for (const Band& band : bands) count += inBandAnywhere(s, band, centre) ? 1 : 0;
                    out.triangles.push_back(t);
                    out.count.push_back(count);
                    out.area.push_back(area);
                    out.totalArea += area;
                    (count == 0 ? out.uncovered : count == 1 ? out.once : out.several) += area;
                }
            }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("courseCoverage: OpenCASCADE failed: ") + e.GetMessageString());
    }
    if (out.totalArea > 0.0) {
        out.uncovered /= out.totalArea;
        out.once /= out.totalArea;
        out.several /= out.totalArea;
    }
    return out;
}

}  // namespace

CourseCoverage courseCoverage(const NurbsSurface& surface, const CoursePlan& plan, std::size_t cells)
{
    return coverageOn(detail::toolFace(surface), plan, cells);
}

CourseCoverage courseCoverage(const PlacementSurface& tool, const CoursePlan& plan, std::size_t cells)
{
    return coverageOn(detail::toolFace(tool.surface, tool.trim), plan, cells);
}

void writeCourseCoverageVtk(const CourseCoverage& coverage, std::ostream& out)
{
    const std::streamsize precision = out.precision();
    out.precision(17);
    out << "# vtk DataFile Version 3.0\ntowgeom course coverage: tows over each triangle of the tool surface\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << coverage.nodes.size() << " double\n";
    for (const Point3& p : coverage.nodes) out << p.x << " " << p.y << " " << p.z << "\n";
    out << "CELLS " << coverage.triangles.size() << " " << 4 * coverage.triangles.size() << "\n";
    for (const auto& t : coverage.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    out << "CELL_TYPES " << coverage.triangles.size() << "\n";
    for (std::size_t k = 0; k < coverage.triangles.size(); ++k) out << "5\n";
    out << "CELL_DATA " << coverage.triangles.size() << "\nFIELD attributes 2\ncoverage 1 " << coverage.triangles.size() << " int\n";
    for (const std::size_t c : coverage.count) out << c << "\n";
    out << "area 1 " << coverage.triangles.size() << " double\n";
    for (const double a : coverage.area) out << a << "\n";
    out.precision(precision);
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the coverage's VTK");
}

TOWGEOM_END_NAMESPACE
