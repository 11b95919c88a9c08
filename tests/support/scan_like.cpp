#include "scan_like.hpp"

#include <towgeom/weave.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace towgeom::testing {

namespace {

using Vec2 = std::array<double, 2>;

/// A section's plane: origin, two unit axes in it.
struct Plane {
    Point3 origin;
    Vector3 e1, e2;

    Vec2 to2(const Point3& p) const { return {dot(p - origin, e1), dot(p - origin, e2)}; }
    Point3 to3(const Vec2& q) const { return origin + q[0] * e1 + q[1] * e2; }
};

Plane planeOf(const std::vector<Point3>& polygon)
{
    Point3 c;
    for (const Point3& p : polygon) c = c + p;
    c = (1.0 / static_cast<double>(polygon.size())) * c;
    Vector3 n;  // Newell's normal
    for (std::size_t k = 0; k < polygon.size(); ++k) n = n + cross(polygon[k] - c, polygon[(k + 1) % polygon.size()] - c);
    n = (1.0 / norm(n)) * n;
    Vector3 e1 = polygon[0] - c;
    e1 = e1 - dot(e1, n) * n;
    e1 = (1.0 / norm(e1)) * e1;
    return {c, e1, cross(n, e1)};
}

double signedArea(const std::vector<Vec2>& q)
{
    double a = 0.0;
    for (std::size_t k = 0; k < q.size(); ++k) {
        const Vec2 &p = q[k], &r = q[(k + 1) % q.size()];
        a += p[0] * r[1] - r[0] * p[1];
    }
    return 0.5 * a;
}

/// Distance from @p x to polygon @p q, negative inside (even-odd rule).
double signedDistance(const std::vector<Vec2>& q, const Vec2& x)
{
    double best = 1e300;
    bool inside = false;
    for (std::size_t k = 0, j = q.size() - 1; k < q.size(); j = k++) {
        const Vec2 &a = q[j], &b = q[k];
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double len2 = dx * dx + dy * dy;
        const double t = len2 > 0.0 ? std::clamp(((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
        const double px = a[0] + t * dx - x[0], py = a[1] + t * dy - x[1];
        best = std::min(best, px * px + py * py);
        if ((a[1] > x[1]) != (b[1] > x[1]) && x[0] < a[0] + (x[1] - a[1]) * dx / dy) inside = !inside;
    }
    return inside ? -std::sqrt(best) : std::sqrt(best);
}

/// The longest closed contour at level 1/2 of grey values @p g (nx x ny nodes, spacing @p h from
/// @p origin), by marching squares with linear interpolation along the cell edges.
std::vector<Vec2> contour(const std::vector<double>& g, std::size_t nx, std::size_t ny, const Vec2& origin, double h)
{
    const auto at = [&](std::size_t i, std::size_t j) { return g[j * nx + i]; };
    const auto node = [&](std::size_t i, std::size_t j) { return Vec2{origin[0] + h * i, origin[1] + h * j}; };
    // A crossing point is named by its grid edge: (i, j, 0) from (i,j) to (i+1,j); (i, j, 1) up.
    using EdgeId = std::array<std::size_t, 3>;
    std::map<EdgeId, Vec2> points;
    std::map<EdgeId, std::vector<EdgeId>> links;
    const auto point = [&](const EdgeId& e) {
        const std::size_t i2 = e[2] == 0 ? e[0] + 1 : e[0], j2 = e[2] == 0 ? e[1] : e[1] + 1;
        const double a = at(e[0], e[1]), b = at(i2, j2);
        const double t = std::clamp((0.5 - a) / (b - a), 0.0, 1.0);
        const Vec2 p = node(e[0], e[1]), q = node(i2, j2);
        points[e] = {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
    };
    const auto link = [&](const EdgeId& x, const EdgeId& y) {
        point(x);
        point(y);
        links[x].push_back(y);
        links[y].push_back(x);
    };
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i) {
            const EdgeId bottom{i, j, 0}, top{i, j + 1, 0}, left{i, j, 1}, right{i + 1, j, 1};
            const bool b00 = at(i, j) > 0.5, b10 = at(i + 1, j) > 0.5, b11 = at(i + 1, j + 1) > 0.5, b01 = at(i, j + 1) > 0.5;
            const int c = b00 | (b10 << 1) | (b11 << 2) | (b01 << 3);
            const bool centre = 0.25 * (at(i, j) + at(i + 1, j) + at(i + 1, j + 1) + at(i, j + 1)) > 0.5;
            switch (c) {
            case 0: case 15: break;
            case 1: case 14: link(bottom, left); break;
            case 2: case 13: link(bottom, right); break;
            case 3: case 12: link(left, right); break;
            case 4: case 11: link(right, top); break;
            case 6: case 9: link(bottom, top); break;
            case 7: case 8: link(left, top); break;
            case 5:  // 00 and 11 inside
                if (centre) { link(bottom, right); link(left, top); } else { link(bottom, left); link(right, top); }
                break;
            case 10:  // 10 and 01 inside
                if (centre) { link(bottom, left); link(right, top); } else { link(bottom, right); link(left, top); }
                break;
            }
        }
    std::vector<Vec2> best;
    std::map<EdgeId, bool> used;
    for (const auto& [start, unusedLinks] : links) {
        if (used[start]) continue;
        // Every crossing point lies on an edge shared by two cells: two links each.
        std::vector<Vec2> loop;
        EdgeId prev = start, cur = start;
        do {
            used[cur] = true;
            loop.push_back(points[cur]);
            const std::vector<EdgeId>& next = links[cur];
            const EdgeId to = (cur == start || next[0] != prev) ? next[0] : next[1];
            prev = cur;
            cur = to;
        } while (cur != start && !used[cur]);
        if (loop.size() > best.size()) best = loop;
    }
    return best;
}

/// @p loop resampled to @p n points uniform in arc length, from arc length @p from.
std::vector<Vec2> resample(const std::vector<Vec2>& loop, std::size_t n, double from)
{
    std::vector<double> s{0.0};
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const Vec2 &a = loop[k], &b = loop[(k + 1) % loop.size()];
        s.push_back(s.back() + std::hypot(b[0] - a[0], b[1] - a[1]));
    }
    const double perimeter = s.back();
    std::vector<Vec2> out;
    std::size_t seg = 0;
    for (std::size_t k = 0; k < n; ++k) {
        double t = std::fmod(from + perimeter * static_cast<double>(k) / static_cast<double>(n), perimeter);
        if (t < 0.0) t += perimeter;
        seg = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin()) - 1;
        seg = std::min(seg, loop.size() - 1);
        const double len = s[seg + 1] - s[seg];
        const double f = len > 0.0 ? (t - s[seg]) / len : 0.0;
        const Vec2 &a = loop[seg], &b = loop[(seg + 1) % loop.size()];
        out.push_back({a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])});
    }
    return out;
}

}  // namespace

std::vector<Point3> rescannedSection(const std::vector<Point3>& polygon, double pixel, double noise, std::size_t points,
                                     double startShift, unsigned seed)
{
    const Plane plane = planeOf(polygon);
    std::vector<Vec2> q;
    for (const Point3& p : polygon) q.push_back(plane.to2(p));
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec2& p : q) {
        x0 = std::min(x0, p[0]);
        y0 = std::min(y0, p[1]);
        x1 = std::max(x1, p[0]);
        y1 = std::max(y1, p[1]);
    }
    // No coarser than a sixth of the section's smaller extent (a thin binder): a scan resolves it.
    pixel = std::min(pixel, std::min(x1 - x0, y1 - y0) / 6.0);
    // The pixel grid (random sub-pixel offset) with three pixels of margin.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const Vec2 origin{x0 - (3.0 + unit(rng)) * pixel, y0 - (3.0 + unit(rng)) * pixel};
    const std::size_t nx = static_cast<std::size_t>(std::ceil((x1 - origin[0]) / pixel)) + 4;
    const std::size_t ny = static_cast<std::size_t>(std::ceil((y1 - origin[1]) / pixel)) + 4;
    std::vector<double> grey(nx * ny);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const double d = signedDistance(q, {origin[0] + pixel * i, origin[1] + pixel * j}) / pixel;
            const bool border = i == 0 || j == 0 || i + 1 == nx || j + 1 == ny;
            grey[j * nx + i] = border ? 0.0 : std::clamp(0.5 - d, 0.0, 1.0) + noise * gauss(rng);
        }
    std::vector<Vec2> loop = contour(grey, nx, ny, origin, pixel);
    if (loop.size() < 6) throw std::runtime_error("rescannedSection: no contour (pixel too coarse for the section)");
    if ((signedArea(loop) > 0.0) != (signedArea(q) > 0.0)) std::reverse(loop.begin(), loop.end());
    // Arc length of the contour point nearest the polygon's first point.
    std::size_t nearest = 0;
    double best = 1e300;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const double d = std::hypot(loop[k][0] - q[0][0], loop[k][1] - q[0][1]);
        if (d < best) {
            best = d;
            nearest = k;
        }
    }
    double s = 0.0, perimeter = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const double len = std::hypot(loop[(k + 1) % loop.size()][0] - loop[k][0], loop[(k + 1) % loop.size()][1] - loop[k][1]);
        if (k < nearest) s += len;
        perimeter += len;
    }
    std::vector<Point3> out;
    for (const Vec2& p : resample(loop, points, s + startShift * perimeter / static_cast<double>(points))) out.push_back(plane.to3(p));
    return out;
}

std::string ScanLikeChoices::describe() const
{
    std::ostringstream s;
    s << weave << " " << yarns << "x" << yarns << ", " << section << " " << width << " x " << height << ", overlap " << overlap
      << ", pixel " << pixel << " x thickness, noise " << noise << ", " << sections << " sections x " << points << " points";
    return s.str();
}

namespace {

/// The runs of consecutive sections of @p stack whose centres lie in the box [lo, hi], each of
/// at least 4 sections, as tows named NAME or NAME_pK.
std::vector<TowStack> cutByBox(const TowStack& stack, const Point3& lo, const Point3& hi)
{
    std::vector<TowStack> pieces;
    TowStack run;
    const auto flush = [&]() {
        if (run.sections.size() >= TowStack::kMinSections) pieces.push_back(run);
        run.sections.clear();
    };
    for (const auto& section : stack.sections) {
        Point3 c;
        for (const Point3& p : section) c = c + p;
        c = (1.0 / static_cast<double>(section.size())) * c;
        const bool inside = c.x >= lo.x && c.x <= hi.x && c.y >= lo.y && c.y <= hi.y && c.z >= lo.z && c.z <= hi.z;
        if (inside)
            run.sections.push_back(section);
        else
            flush();
    }
    flush();
    for (std::size_t k = 0; k < pieces.size(); ++k)
        pieces[k].name = pieces.size() == 1 ? stack.name : stack.name + "_p" + std::to_string(k + 1);
    return pieces;
}

/// The weave of @p o (its choices in @p c) as a scan gives it back: every section rescanned,
/// starts drifting, the tows cut by a random box (the rest of @p rng's choices).
ScanLikeTextile scanned(const WeaveOptions& o, const ScanLikeChoices& c, std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ScanLikeTextile t;
    t.choices = c;
    const std::vector<TowStack> yarns = generateWeave(o).stacks();

    // The scan box: faces at random inside the yarns' ends (x, y), and for a 3D weave a top face
    // at random through the binders' highest reach half of the time.
    Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const TowStack& s : yarns)
        for (const auto& section : s.sections)
            for (const Point3& p : section) {
                lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
                hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
            }
    const double reach = 0.6 * o.spacing;
    lo.x += reach * unit(rng);
    lo.y += reach * unit(rng);
    hi.x -= reach * unit(rng);
    hi.y -= reach * unit(rng);
    if (o.kind == WeaveKind::Orthogonal && unit(rng) < 0.5) hi.z -= 0.5 * o.height * unit(rng);
    lo.z -= 1.0;

    for (const TowStack& yarn : yarns) {
        TowStack rescanned = yarn;
        rescanned.sections.clear();
        const std::size_t n = yarn.sections.size();
        double shift = 0.0;
        std::normal_distribution<double> drift(0.0, 0.4);
        for (std::size_t i = 0; i < n; ++i) {
            shift += drift(rng);
            rescanned.sections.push_back(rescannedSection(yarn.sections[i], c.pixel * o.height, c.noise, c.points, shift,
                                                          static_cast<unsigned>(rng())));
        }
        for (TowStack& piece : cutByBox(rescanned, lo, hi)) t.stacks.push_back(std::move(piece));
    }
    return t;
}

/// The random choices every scan-like textile makes the same way: section shape and size,
/// overlap, pixel and noise (drawn from @p rng in this order, after the weave's kind).
void chooseSectionAndScan(std::mt19937& rng, WeaveOptions& o, ScanLikeChoices& c)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(unit(rng) * static_cast<double>(n)) % n; };
    const std::size_t shape = pick(3);
    o.shape = shape == 0 ? SectionShape::Racetrack : shape == 1 ? SectionShape::Lenticular : SectionShape::Ellipse;
    c.section = shape == 0 ? "racetrack" : shape == 1 ? "lenticular" : "ellipse";
    c.yarns = o.kind == WeaveKind::Twill ? 4 : 2 + pick(2);
    o.warps = o.wefts = c.yarns;
    o.layers = 2;
    c.height = o.height = 0.15 + 0.15 * unit(rng);
    c.width = o.width = 0.6 + 0.3 * unit(rng);
    c.overlap = o.overlap = 0.05 + 0.25 * unit(rng);
    c.sections = o.sectionsPerYarn = 12 + pick(13);
    c.points = 24 + 2 * pick(5);
    o.pointsPerSection = 48;  // the "true" tows, finer than what the scan gives back
    c.pixel = 1.0 / (6.0 + 6.0 * unit(rng));
    c.noise = 0.1 * unit(rng);
}

}  // namespace

ScanLikeTextile scanLikeTextile(unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    WeaveOptions o;
    ScanLikeChoices c;
    const std::size_t kind = static_cast<std::size_t>(unit(rng) * 3.0) % 3;
    o.kind = kind == 0 ? WeaveKind::Plain : kind == 1 ? WeaveKind::Twill : WeaveKind::Orthogonal;
    c.weave = kind == 0 ? "plain" : kind == 1 ? "twill" : "orthogonal";
    chooseSectionAndScan(rng, o, c);
    return scanned(o, c, rng);
}

ScanLikeTextile largeScanLikeTextile(unsigned seed, const ScanLikeSize& size)
{
    std::mt19937 rng(seed);
    WeaveOptions o;
    ScanLikeChoices c;
    o.kind = WeaveKind::Orthogonal;
    c.weave = "orthogonal";
    chooseSectionAndScan(rng, o, c);
    c.yarns = o.warps = o.wefts = size.yarns;
    o.layers = size.layers;
    c.sections = o.sectionsPerYarn = size.sections;
    c.points = size.points;
    c.width = o.width = size.width;
    return scanned(o, c, rng);
}

TowStack foldingBinder()
{
    for (TowStack& s : largeScanLikeTextile(1).stacks)
        if (s.name == "binder_2_p1") return std::move(s);
    throw std::logic_error("largeScanLikeTextile(1) has no binder_2_p1 any more");
}

}  // namespace towgeom::testing
