// A tool surface fitted to a grid of points (OpenCASCADE's GeomAPI_PointsToBSplineSurface:
// interpolation, or its smoothing approximation within a tolerance).
#include "placement/surface_grid.hpp"

#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "placement/nurbs_geometry.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// @p knots scaled from their range to [0, 1].
void normalise(TColStd_Array1OfReal& knots)
{
    const double a = knots.First(), b = knots.Last();
    for (int i = knots.Lower(); i <= knots.Upper(); ++i) knots(i) = (knots(i) - a) / (b - a);
}

}  // namespace

PlacementSurface fitPlacementSurface(const std::vector<Point3>& grid, std::size_t uCount, std::size_t vCount, double tolerance)
{
    if (uCount < 4 || vCount < 4) throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: a grid of at least 4 x 4 points");
    if (uCount > 100000 || vCount > 100000 || grid.size() != uCount * vCount)
        throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: " + std::to_string(grid.size()) + " points for a grid of " + std::to_string(uCount) +
                                                    " x " + std::to_string(vCount));
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: a tolerance of 0 or more");
    Point3 lo = grid.front(), hi = lo;
    for (const Point3& p : grid) {
        if (!(std::abs(p.x) <= 1e100 && std::abs(p.y) <= 1e100 && std::abs(p.z) <= 1e100))
            throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: a point is not finite or beyond 1e100");
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    // Neighbours along a row or a column must be apart (a collapsed row or repeated point has
    // no chord-length parameters; OpenCASCADE's projection would then search without end).
    // (hypot: no underflow of squared tiny distances.)
    const auto gap = [](const Point3& a, const Point3& b) { return std::hypot(std::hypot(a.x - b.x, a.y - b.y), a.z - b.z); };
    const double apart = 1e-12 * gap(lo, hi);
    for (std::size_t i = 0; i < uCount; ++i)
        for (std::size_t j = 0; j < vCount; ++j) {
            const Point3& p = grid[i * vCount + j];
            if (j > 0 && !(gap(p, grid[i * vCount + j - 1]) > apart))
                throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: row " + std::to_string(i) + ": points " + std::to_string(j - 1) + " and " +
                                                            std::to_string(j) + " coincide");
            if (i > 0 && !(gap(p, grid[(i - 1) * vCount + j]) > apart))
                throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: column " + std::to_string(j) + ": points " + std::to_string(i - 1) + " and " +
                                                            std::to_string(i) + " coincide");
        }
    PlacementSurface out;
    try {
        TColgp_Array2OfPnt points(1, static_cast<int>(uCount), 1, static_cast<int>(vCount));
        for (std::size_t i = 0; i < uCount; ++i)
            for (std::size_t j = 0; j < vCount; ++j) points.SetValue(static_cast<int>(i + 1), static_cast<int>(j + 1), detail::toOcct(grid[i * vCount + j]));
        GeomAPI_PointsToBSplineSurface fit;
        if (tolerance == 0.0) fit.Interpolate(points, Approx_ChordLength);
        else fit.Init(points, Approx_ChordLength, 3, 8, GeomAbs_C2, tolerance);
        if (!fit.IsDone()) throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: OpenCASCADE cannot fit the grid (repeated points?)");
        Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(fit.Surface()->Copy());
        TColStd_Array1OfReal uk(1, s->NbUKnots()), vk(1, s->NbVKnots());
        s->UKnots(uk);
        s->VKnots(vk);
        normalise(uk);
        normalise(vk);
        s->SetUKnots(uk);
        s->SetVKnots(vk);
        // An interpolation passes through every point; an approximation is measured (nearest
        // surface points) and held to its tolerance.
        if (tolerance > 0.0) {
            for (const Point3& p : grid) {
                GeomAPI_ProjectPointOnSurf projection(detail::toOcct(p), s);
                if (projection.NbPoints() == 0) throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: a grid point does not project onto the fit");
                out.fitDeviation = std::max(out.fitDeviation, projection.LowerDistance());
            }
            if (out.fitDeviation > tolerance)
                throw Error(ErrorCode::InvalidArgument, "fitPlacementSurface: the approximation is " + std::to_string(out.fitDeviation) +
                                                            " from a grid point, more than the tolerance " + std::to_string(tolerance) +
                                                            " (noisier than that? raise it)");
        }
        out.surface = detail::nurbsSurface(s);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::InvalidArgument, std::string("fitPlacementSurface: OpenCASCADE cannot fit the grid: ") + e.GetMessageString());
    }
    return out;
}

namespace detail {

PlacementSurface readGridSurface(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw Error(ErrorCode::FileNotFound, "cannot open the point grid", path);
    std::size_t nu = 0, nv = 0, number = 0, last = 0;
    std::vector<Point3> points;
    std::vector<std::size_t> lines;  // each point's line
    const auto count = [&](const std::string& word) {  // a whole number from 4 to 100000
        std::size_t used = 0, n = 0;
        const bool digits = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
        if (digits && word.size() <= 6) n = std::stoul(word, &used);
        return digits && used == word.size() && n >= 4 && n <= 100000 ? n : 0;
    };
    for (std::string line; std::getline(in, line);) {
        ++number;
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream words(line);
        if (nu == 0) {
            std::string word, a, b;
            if (!(words >> word >> a >> b) || word != "grid" || !(words >> std::ws).eof() || !(nu = count(a)) || !(nv = count(b)))
                throw Error(ErrorCode::InvalidArgument, "expected 'grid NU NV' (rows, and points per row: whole numbers from 4 to 100000)", path,
                            number);
            last = number;
            continue;
        }
        if (points.size() == nu * nv) throw Error(ErrorCode::InvalidArgument, "more points than the grid's " + std::to_string(nu) + " x " + std::to_string(nv), path, number);
        Point3 p;
        if (!(words >> p.x >> p.y >> p.z) || !(words >> std::ws).eof()) throw Error(ErrorCode::InvalidArgument, "expected a point 'x y z'", path, number);
        if (!(std::abs(p.x) <= 1e100 && std::abs(p.y) <= 1e100 && std::abs(p.z) <= 1e100))
            throw Error(ErrorCode::InvalidArgument, "a coordinate is not finite or beyond 1e100", path, number);
        points.push_back(p);
        lines.push_back(number);
        last = number;
    }
    if (nu == 0) throw Error(ErrorCode::InvalidArgument, "no 'grid NU NV' line", path);
    if (points.size() != nu * nv)
        throw Error(ErrorCode::InvalidArgument, "the file ends after " + std::to_string(points.size()) + " of the grid's " + std::to_string(nu) + " x " +
                                                    std::to_string(nv) + " points", path, last);
    try {
        return fitPlacementSurface(points, nu, nv);
    } catch (const Error& e) {
        // "row I: points J and K coincide" / "column J: points I and K coincide": K's line.
        const char* m = e.message().c_str();
        std::size_t a = 0, b = 0, c = 0;
        if (std::sscanf(m, "fitPlacementSurface: row %zu: points %zu and %zu", &a, &b, &c) == 3 && a * nv + c < lines.size())
            throw Error(e.code(), e.message(), path, lines[a * nv + c]);
        if (std::sscanf(m, "fitPlacementSurface: column %zu: points %zu and %zu", &a, &b, &c) == 3 && c * nv + a < lines.size())
            throw Error(e.code(), e.message(), path, lines[c * nv + a]);
        throw Error(e.code(), e.message(), path);
    }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
