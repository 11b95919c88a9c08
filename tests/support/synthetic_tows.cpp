#include "synthetic_tows.hpp"

#include <towgeom/stack_reader.hpp>
#include <towgeom/weave.hpp>

#include <cmath>
#include <fstream>
#include <functional>

namespace towgeom::testing {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Samples sections: frame(i) gives the centre c, and the two in-section axes e1, e2 of section
/// i; point j sits at c + a cos(t) e1 + b sin(t) e2.
TowStack sample(const Sampling& s, const std::string& name, double a, double b,
                const std::function<void(std::size_t, Point3&, Vector3&, Vector3&)>& frame)
{
    TowStack stack;
    stack.name = name;
    stack.source = name;
    for (std::size_t i = 0; i < s.sections; ++i) {
        Point3 c;
        Vector3 e1, e2;
        frame(i, c, e1, e2);
        std::vector<Point3> section;
        for (std::size_t j = 0; j < s.points; ++j) {
            const double sign = s.counterClockwise ? 1.0 : -1.0;
            const double t = s.startAngle + sign * 2.0 * kPi * static_cast<double>(j) / static_cast<double>(s.points);
            section.push_back(c + (a * std::cos(t)) * e1 + (b * std::sin(t)) * e2);
        }
        if (s.repeatClosingPoint) section.push_back(section.front());
        stack.sections.push_back(section);
    }
    return stack;
}

}  // namespace

TowStack ellipticalTube(double a, double b, double length, const Sampling& s, const std::string& name)
{
    return sample(s, name, a, b, [&](std::size_t i, Point3& c, Vector3& e1, Vector3& e2) {
        c = {length * static_cast<double>(i) / static_cast<double>(s.sections - 1), 0.0, 0.0};
        e1 = {0, 1, 0};
        e2 = {0, 0, 1};  // e1 x e2 = +x: counter-clockwise about the tow's direction
    });
}

TowStack bentTube(double r, double bendRadius, double sweep, const Sampling& s, const std::string& name)
{
    return growingBentTube(r, r, bendRadius, sweep, s, name);
}

TowStack growingBentTube(double r0, double r1, double bendRadius, double sweep, const Sampling& s,
                         const std::string& name)
{
    TowStack stack = sample(s, name, 1.0, 1.0, [&](std::size_t i, Point3& c, Vector3& e1, Vector3& e2) {
        const double phi = sweep * static_cast<double>(i) / static_cast<double>(s.sections - 1);
        const Vector3 radial{std::cos(phi), std::sin(phi), 0.0};
        c = bendRadius * radial;
        // e1 x e2 = z x radial = (-sin, cos, 0): the tangent, so counter-clockwise about it.
        const double r = r0 + (r1 - r0) * static_cast<double>(i) / static_cast<double>(s.sections - 1);
        e1 = {0, 0, r};
        e2 = r * radial;
    });
    return stack;
}

TowStack crimpedTow(double a, double b, double length, double amplitude, double wavelength, const Sampling& s,
                    const std::string& name)
{
    return sample(s, name, a, b, [&](std::size_t i, Point3& c, Vector3& e1, Vector3& e2) {
        const double x = length * static_cast<double>(i) / static_cast<double>(s.sections - 1);
        const double k = 2.0 * kPi / wavelength;
        c = {x, 0.0, amplitude * std::cos(k * x)};
        Vector3 t{1.0, 0.0, -amplitude * k * std::sin(k * x)};
        t = (1.0 / norm(t)) * t;
        e1 = {0, 1, 0};     // width across the tow
        e2 = cross(t, e1);  // thickness, normal to the centre line; e1 x e2 = t
    });
}

TowStack tubeAlongX(double r, double length, double dx, double dy, double dz, const Sampling& s, const std::string& name)
{
    TowStack t = ellipticalTube(r, r, length, s, name);
    for (auto& section : t.sections)
        for (Point3& p : section) p = {p.x + dx, p.y + dy, p.z + dz};
    return t;
}

std::vector<TowStack> tubesCrossingAt(double degrees, double width, double height, double lift, double side)
{
    const double angle = degrees * 3.14159265358979323846 / 180.0;
    Sampling s;
    s.sections = 51;
    s.points = 32;
    TowStack a = ellipticalTube(width, height, 10.0, s, "a");
    TowStack b = ellipticalTube(width, height, 10.0, s, "b");
    for (auto& section : a.sections)
        for (Point3& p : section) p.x -= 3.0;
    for (auto& section : b.sections)
        for (Point3& p : section) {
            const double x = p.x - 3.0 - 2.0;
            p = {2.0 + x * std::cos(angle) - p.y * std::sin(angle), x * std::sin(angle) + p.y * std::cos(angle) + side, p.z + lift};
        }
    return {a, b};
}

TowStack tubeAlongY(double r, double d, const Sampling& s, const std::string& name)
{
    TowStack t = ellipticalTube(r, r, 4.0, s, name);
    for (auto& section : t.sections)
        for (Point3& p : section) p = {2.0 - p.y, p.x - 2.0, p.z + d};
    return t;
}

TowStack dentedTubeAlongY(double r, double d, double dent, double width, const Sampling& s, const std::string& name,
                          double widthX)
{
    if (widthX == 0.0) widthX = width;
    TowStack t = tubeAlongY(r, d, s, name);
    for (auto& section : t.sections)
        for (Point3& p : section) {
            const double below = (d - p.z) / r;  // sin of the angle below the axis
            if (below <= 0.0) continue;
            const double dx = p.x - 2.0;
            p.z += dent * std::exp(-dx * dx / (widthX * widthX) - p.y * p.y / (width * width)) * below * below;
        }
    return t;
}

Point2 racetrackPoint(double w, double h, double s)
{
    const double rho = h / 2, half = (w - h) / 2;
    const double arc = kPi * rho, perimeter = 4 * half + 2 * arc;
    s = std::fmod(std::fmod(s, perimeter) + perimeter, perimeter);
    const auto onArc = [&](double cx, double phi) { return Point2{cx + rho * std::cos(phi), rho * std::sin(phi)}; };
    if (s < arc / 2) return onArc(half, s / rho);
    s -= arc / 2;
    if (s < 2 * half) return {half - s, rho};
    s -= 2 * half;
    if (s < arc) return onArc(-half, kPi / 2 + s / rho);
    s -= arc;
    if (s < 2 * half) return {-half + s, -rho};
    s -= 2 * half;
    return onArc(half, 3 * kPi / 2 + s / rho);
}


TracedTow tracedRacetrack(std::size_t m, std::size_t n, const std::vector<double>& offset, bool clockwise)
{
    const double g = 1.0 / 50.0, h = 0.25;
    TracedTow t;
    t.stack.name = "traced";
    double previousArea = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        const double x = 2 * g * static_cast<double>(i);
        const double w = 1.0 + 0.1 * std::sin(x);
        const double yc = 0.05 * std::sin(2 * x), zc = 0.03 * std::cos(3 * x);
        const double perimeter = 2 * (w - h) + kPi * h;
        const double area = (w - h) * h + kPi * h * h / 4;
        if (i) t.volume += 0.5 * (area + previousArea) * 2 * g;
        previousArea = area;
        t.spacing += perimeter / static_cast<double>(n) / static_cast<double>(m);
        std::vector<Point3> section;
        for (std::size_t j = 0; j < n; ++j) {
            const double s = (offset[i] + static_cast<double>(j)) * perimeter / static_cast<double>(n);
            const Point2 p = racetrackPoint(w, h, clockwise ? -s : s);
            section.push_back({x, g * std::round((yc + p.x) / g), g * std::round((zc + p.y) / g)});
        }
        t.stack.sections.push_back(section);
    }
    return t;
}


std::vector<TowSurface> fitAll(const std::vector<TowStack>& stacks)
{
    std::vector<TowSurface> tows;
    for (const TowStack& s : stacks) tows.push_back(TowSurface::fit(s));
    return tows;
}

std::vector<TowSurface> bundledTwill(const std::string& exampleData)
{
    std::vector<TowSurface> tows;
    for (const char* name : {"warp_0", "warp_1", "warp_2", "warp_3", "weft_0", "weft_1", "weft_2", "weft_3"})
        tows.push_back(TowSurface::fit(readStackFile(exampleData + "/twill/" + name + ".stw")));
    return tows;
}

std::vector<TowStack> pressedOrthogonal(std::size_t tows, std::size_t layers, double overlap)
{
    WeaveOptions o;
    o.kind = WeaveKind::Orthogonal;
    o.warps = o.wefts = tows;
    o.layers = layers;
    o.shape = SectionShape::Racetrack;
    o.overlap = overlap;
    o.width = 0.9;
    o.sectionsPerYarn = 30;
    o.pointsPerSection = 32;
    return generateWeave(o).stacks();
}

std::vector<TowSurface> fittedTwill22()
{
    WeaveOptions w;
    w.kind = WeaveKind::Twill;
    w.floatOver = w.floatUnder = 2;
    w.overlap = 0.08;
    return fitAll(generateWeave(w).stacks());
}

std::vector<TowSurface> fittedTwill22SixBySix()
{
    WeaveOptions w;
    w.kind = WeaveKind::Twill;
    w.floatOver = w.floatUnder = 2;
    w.warps = w.wefts = 6;
    w.overlap = 0.08;
    return fitAll(generateWeave(w).stacks());
}

std::vector<TowStack> threeTowsAtAPoint(double offset, double height, double startAngle)
{
    Sampling s;
    s.sections = 41;
    s.points = 48;
    const Sampling round = s;
    s.startAngle = startAngle;
    TowStack w = tubeAlongX(0.3, 3.0, -1.5, offset, 0.0, s, "w");
    const double c = std::sqrt(0.5);
    for (auto& section : w.sections)
        for (Point3& p : section) p = {2.0 + c * p.x - c * p.y, c * p.x + c * p.y, p.z + height};
    return {tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, round, "x"), tubeAlongY(0.4, 0.82, round, "y"), w};
}

std::vector<TowStack> thinThrough(bool endsInside, bool startsInside)
{
    Sampling s;
    s.sections = 41;
    s.points = 32;
    TowStack thin = tubeAlongY(0.1, 0.0, s, "thin");
    if (endsInside) thin.sections.resize(21);  // y from -2 to 0
    if (startsInside) thin.sections.erase(thin.sections.begin(), thin.sections.begin() + 20);  // y from 0 to 2
    return {tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "outer"), thin};
}

std::string writeStacks(const std::filesystem::path& dir, const std::vector<TowStack>& stacks)
{
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::string files;
    for (const TowStack& t : stacks) {
        const auto path = dir / (t.name + ".stw");
        std::ofstream out(path);
        writeStack(out, t);
        files += " '" + path.string() + "'";
    }
    return files;
}

std::vector<TowSurface> crossingTubes(bool far)
{
    Sampling s;
    s.points = 48;
    std::vector<TowSurface> tows = {TowSurface::fit(tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "x")),
                                    TowSurface::fit(tubeAlongY(0.4, 0.7, s, "y"))};
    if (far) tows.push_back(TowSurface::fit(tubeAlongX(0.3, 4.0, 0.0, 3.0, 0.0, s, "far")));
    return tows;
}

Cell crossingAtCell()
{
    Cell cell;
    cell.min = {-1.0, -4.0, -1.0};
    cell.max = {2.0, 4.0, 1.7};
    return cell;
}

Cell twill22RepeatCell()
{
    Cell cell;
    cell.min = {0.5, 0.5, -0.5};
    cell.max = {4.5, 4.5, 0.5};
    cell.periodic = true;
    return cell;
}

}  // namespace towgeom::testing
