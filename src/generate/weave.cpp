// The weave generator: interlacement patterns, Catmull-Rom yarn paths, sections in the path's frame.
#include "towgeom/weave.hpp"

#include <cmath>
#include <numeric>
#include <string>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

[[noreturn]] void invalidWeave(const std::string& why) { throw Error(ErrorCode::InvalidArgument, "weave: " + why); }

/// The interlacement height: the crimp given, else half the yarn height less the overlap.
double crimpOf(const WeaveOptions& o) { return o.crimp > 0.0 ? o.crimp : 0.5 * o.height * (1.0 - o.overlap); }

/// value / divisor rounded down (towards minus infinity), divisor > 0.
long floorDiv(long value, long divisor) { return value / divisor - (value % divisor != 0 && value < 0 ? 1 : 0); }

int wrap(long value, long period) { return static_cast<int>(((value % period) + period) % period); }

/// True when warp i passes over weft j in a 2D weave (any integers: the pattern repeats).
bool warpOver(const WeaveOptions& o, long i, long j)
{
    switch (o.kind) {
    case WeaveKind::Plain: return wrap(i + j, 2) == 0;
    case WeaveKind::Twill: return wrap(j - static_cast<long>(o.step) * i, o.floatOver + o.floatUnder) < o.floatOver;
    case WeaveKind::Satin: return wrap(j - static_cast<long>(o.step) * i, o.floatOver) == 0;
    case WeaveKind::Basket: return wrap(floorDiv(i, static_cast<long>(o.floatOver)) + floorDiv(j, static_cast<long>(o.floatOver)), 2) == 0;
    case WeaveKind::Orthogonal: return false;
    }
    return false;
}

/// The section frame (n, b) at a path tangent: n = t x j / |t x j| with j = +z, b = n x t;
/// where t is (nearly) parallel to j, @p n is carried over from the previous frame instead.
void frame(const Vector3& tangent, Vector3& n, Vector3& b, bool first)
{
    const Vector3 t = (1.0 / norm(tangent)) * tangent;
    const Vector3 tj = cross(t, Vector3{0.0, 0.0, 1.0});
    if (norm(tj) > 1e-3) {
        // Keep n continuous: where the path turns back on itself through the vertical, t x j
        // flips; follow the previous frame's side instead of jumping half way round.
        const Vector3 candidate = (1.0 / norm(tj)) * tj;
        n = !first && dot(candidate, n) < 0.0 ? -1.0 * candidate : candidate;
    } else {
        // Rotation-minimising transport: project the previous n onto the new normal plane.
        Vector3 prev = first ? Vector3{0.0, 1.0, 0.0} : n;
        prev = prev - dot(prev, t) * t;
        if (norm(prev) < 1e-9) prev = Vector3{1.0, 0.0, 0.0} - t.x * t;
        n = (1.0 / norm(prev)) * prev;
    }
    b = cross(n, t);
}

GeneratedYarn makeYarn(const std::string& name, YarnRole role, const std::vector<Point3>& points,
                       const CrossSection& section, std::size_t sections, double tension = 0.0)
{
    GeneratedYarn y{name, role, YarnPath::cardinal(points, tension), {}, {}};
    const double last = y.path.lastParameter();
    for (std::size_t k = 0; k < sections; ++k) y.stations.push_back(last * static_cast<double>(k) / (sections - 1));
    y.sections.assign(sections, section);
    return y;
}

std::size_t defaultSections(const WeaveOptions& o, std::size_t intervals)
{
    return o.sectionsPerYarn ? o.sectionsPerYarn : 16 * intervals + 1;
}

void generate2D(const WeaveOptions& o, double c, Textile& t)
{
    const double s = o.spacing;
    const CrossSection section{o.shape, o.width, o.height, 1.0};
    for (std::size_t i = 0; i < o.warps; ++i) {
        std::vector<Point3> pts;
        for (long j = -1; j <= static_cast<long>(o.wefts); ++j)
            pts.push_back({j * s, i * s, warpOver(o, static_cast<long>(i), j) ? c : -c});
        t.yarns.push_back(makeYarn("warp_" + std::to_string(i), YarnRole::Warp, pts, section, defaultSections(o, o.wefts + 1)));
    }
    for (std::size_t j = 0; j < o.wefts; ++j) {
        std::vector<Point3> pts;
        for (long i = -1; i <= static_cast<long>(o.warps); ++i)
            pts.push_back({j * s, i * s, warpOver(o, i, static_cast<long>(j)) ? -c : c});
        t.yarns.push_back(makeYarn("weft_" + std::to_string(j), YarnRole::Weft, pts, section, defaultSections(o, o.warps + 1)));
    }
    for (std::size_t i = 0; i < o.warps; ++i)
        for (std::size_t j = 0; j < o.wefts; ++j)
            t.crossings.push_back({i, o.warps + j, {j * s, i * s, 0.0}, warpOver(o, static_cast<long>(i), static_cast<long>(j))});
}

/// 3D orthogonal: weft layer k at z = 2 k p, warp layer k at (2 k + 1) p, with the layer pitch
/// p = 2 c (touching without overlap); binders between the warp columns run over the top and
/// under the bottom weft layer on a 2/2 twill path and go straight through the thickness
/// between two wefts, with half the yarn height and a width that fits between the warps.
void generateOrthogonal(const WeaveOptions& o, double c, Textile& t)
{
    const double s = o.spacing, p = 2.0 * c;
    const std::size_t layers = o.layers;
    const CrossSection section{o.shape, o.width, o.height, 1.0};
    const double gap = s - o.width;
    CrossSection binder{o.shape, gap > 0.0 ? 0.5 * gap : 0.25 * o.width, 0.5 * o.height, 1.0};
    binder.height = std::min(binder.height, binder.width);
    const double top = 2.0 * p * static_cast<double>(layers) + 0.5 * (o.height + binder.height) * (1.0 - o.overlap);
    const double bottom = -0.5 * (o.height + binder.height) * (1.0 - o.overlap);
    for (std::size_t k = 0; k < layers; ++k)
        for (std::size_t i = 0; i < o.warps; ++i) {
            std::vector<Point3> pts;
            for (long j = -1; j <= static_cast<long>(o.wefts); ++j) pts.push_back({j * s, i * s, (2.0 * k + 1.0) * p});
            t.yarns.push_back(makeYarn("warp_L" + std::to_string(k) + "_" + std::to_string(i), YarnRole::Warp, pts, section,
                                       defaultSections(o, o.wefts + 1)));
        }
    const std::size_t firstWeft = t.yarns.size();
    for (std::size_t k = 0; k <= layers; ++k)
        for (std::size_t j = 0; j < o.wefts; ++j) {
            std::vector<Point3> pts;
            for (long i = -1; i <= static_cast<long>(o.warps); ++i) pts.push_back({j * s, i * s, 2.0 * k * p});
            t.yarns.push_back(makeYarn("weft_L" + std::to_string(k) + "_" + std::to_string(j), YarnRole::Weft, pts, section,
                                       defaultSections(o, o.wefts + 1)));
        }
    const std::size_t firstBinder = t.yarns.size();
    const auto binderUp = [](long j, std::size_t b) { return wrap(j - static_cast<long>(b), 4) < 2; };
    for (std::size_t b = 0; b + 1 < std::max<std::size_t>(o.warps, 2); ++b) {
        const double y = (b + 0.5) * s;
        std::vector<Point3> pts;
        for (long j = -1; j <= static_cast<long>(o.wefts); ++j) {
            const double z = binderUp(j, b) ? top : bottom;
            pts.push_back({j * s, y, z});
            if (j < static_cast<long>(o.wefts) && binderUp(j + 1, b) != binderUp(j, b)) {
                // Straight through the thickness, halfway between wefts j and j + 1.
                pts.push_back({(j + 0.5) * s, y, z});
                pts.push_back({(j + 0.5) * s, y, binderUp(j + 1, b) ? top : bottom});
            }
        }
        // Tension 0.5 keeps the path from overshooting where it turns into the thickness.
        t.yarns.push_back(makeYarn("binder_" + std::to_string(b), YarnRole::Binder, pts, binder,
                                   defaultSections(o, 2 * (o.wefts + 1)), 0.5));
    }
    for (std::size_t k = 0; k < layers; ++k)
        for (std::size_t i = 0; i < o.warps; ++i)
            for (std::size_t j = 0; j < o.wefts; ++j) {
                const std::size_t warp = k * o.warps + i;
                const double z = (2.0 * k + 1.0) * p;
                t.crossings.push_back({warp, firstWeft + k * o.wefts + j, {j * s, i * s, z - 0.5 * p}, true});
                t.crossings.push_back({warp, firstWeft + (k + 1) * o.wefts + j, {j * s, i * s, z + 0.5 * p}, false});
            }
    for (std::size_t b = firstBinder; b < t.yarns.size(); ++b)
        for (std::size_t j = 0; j < o.wefts; ++j) {
            const bool up = binderUp(static_cast<long>(j), b - firstBinder);
            const std::size_t weft = firstWeft + (up ? layers : 0) * o.wefts + j;
            t.crossings.push_back({b, weft, {j * s, (b - firstBinder + 0.5) * s, up ? top : bottom}, up});
        }
}

}  // namespace

const char* weaveKindName(WeaveKind kind) noexcept
{
    switch (kind) {
    case WeaveKind::Plain: return "plain";
    case WeaveKind::Twill: return "twill";
    case WeaveKind::Satin: return "satin";
    case WeaveKind::Basket: return "basket";
    case WeaveKind::Orthogonal: return "orthogonal";
    }
    return "unknown";
}

const char* yarnRoleName(YarnRole role) noexcept
{
    switch (role) {
    case YarnRole::Warp: return "warp";
    case YarnRole::Weft: return "weft";
    case YarnRole::Binder: return "binder";
    }
    return "unknown";
}

void WeaveOptions::validate() const
{
    const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
    if (warps < 1 || wefts < 1 || warps > 10000 || wefts > 10000) invalidWeave("warps and wefts must be between 1 and 10000");
    if (!positive(spacing)) invalidWeave("spacing must be positive");
    if (!positive(width) || !positive(height)) invalidWeave("yarn width and height must be positive");
    if (!(overlap >= 0.0 && overlap < 1.0)) invalidWeave("overlap must lie in [0, 1)");
    if (!(crimp >= 0.0 && std::isfinite(crimp))) invalidWeave("crimp must be non-negative");
    if (sectionsPerYarn != 0 && (sectionsPerYarn < 4 || sectionsPerYarn > 1000000)) invalidWeave("sections per yarn must be >= 4");
    if (pointsPerSection < 6 || pointsPerSection > 100000) invalidWeave("points per section must be >= 6");
    switch (kind) {
    case WeaveKind::Twill:
        if (floatOver < 1 || floatUnder < 1) invalidWeave("a twill needs n >= 1 and m >= 1 (n/m)");
        if (step < 1 || step >= floatOver + floatUnder) invalidWeave("the twill step must lie in [1, n + m)");
        break;
    case WeaveKind::Satin:
        if (floatOver < 5 && floatOver != 4) invalidWeave("a satin needs a harness of at least 4");
        if (step <= 1 || step >= floatOver - 1 || std::gcd(step, floatOver) != 1)
            invalidWeave("the satin step must be coprime with the harness and lie in (1, harness - 1)");
        break;
    case WeaveKind::Basket:
        if (floatOver < 1) invalidWeave("a basket weave needs a group size >= 1");
        break;
    case WeaveKind::Orthogonal:
        if (layers < 1 || layers > 100) invalidWeave("an orthogonal weave needs 1 to 100 warp layers");
        break;
    case WeaveKind::Plain: break;
    }
    CrossSection{shape, width, height, 1.0}.sample(pointsPerSection);  // validates shape and count
}

TowStack GeneratedYarn::stack(std::size_t points) const
{
    if (stations.size() != sections.size())
        throw Error(ErrorCode::InvalidArgument, "yarn " + name + ": one section per station is needed");
    TowStack s;
    s.name = name;
    s.source = name;
    Vector3 n, b;
    for (std::size_t k = 0; k < stations.size(); ++k) {
        const Point3 c = path.point(stations[k]);
        frame(path.derivative(stations[k]), n, b, k == 0);
        std::vector<Point3> ring;
        for (const Point2& p : sections[k].sample(points)) ring.push_back(c + p.x * n + p.y * b);
        s.sections.push_back(std::move(ring));
    }
    return s;
}

std::size_t GeneratedYarn::nearestSection(const Point3& p) const
{
    std::size_t best = 0;
    double bestDistance = 1e300;
    for (std::size_t k = 0; k < stations.size(); ++k) {
        const Point3 c = path.point(stations[k]);
        const double d = std::hypot(c.x - p.x, c.y - p.y);
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}

std::vector<TowStack> Textile::stacks() const
{
    std::vector<TowStack> out;
    for (const GeneratedYarn& y : yarns) out.push_back(y.stack(options.pointsPerSection));
    return out;
}

std::optional<Cell> Textile::unitCell() const
{
    const WeaveOptions& o = options;
    long repeatJ = 0, repeatI = 0;  // along the wefts' index (x) and the warps' (y)
    switch (o.kind) {
    case WeaveKind::Plain: repeatJ = repeatI = 2; break;
    case WeaveKind::Twill: {
        const long n = static_cast<long>(o.floatOver + o.floatUnder);
        repeatJ = n;
        repeatI = n / std::gcd(static_cast<long>(o.step), n);
        break;
    }
    case WeaveKind::Satin: repeatJ = repeatI = static_cast<long>(o.floatOver); break;
    case WeaveKind::Basket: repeatJ = repeatI = 2 * static_cast<long>(o.floatOver); break;
    case WeaveKind::Orthogonal: return std::nullopt;
    }
    if (static_cast<long>(o.wefts) < repeatJ + 2 || static_cast<long>(o.warps) < repeatI + 2) return std::nullopt;
    const double s = o.spacing;
    // In z the yarns' sampled extent (a Catmull-Rom path overshoots its points along a float)
    // and a quarter of their height on each side.
    double low = 0.0, high = 0.0;
    for (const TowStack& stack : stacks())
        for (const auto& section : stack.sections)
            for (const Point3& p : section) {
                low = std::min(low, p.z);
                high = std::max(high, p.z);
            }
    Cell cell;
    cell.min = {0.5 * s, 0.5 * s, low - 0.25 * o.height};
    cell.max = {(0.5 + static_cast<double>(repeatJ)) * s, (0.5 + static_cast<double>(repeatI)) * s, high + 0.25 * o.height};
    cell.periodic = true;
    return cell;
}

Textile generateWeave(const WeaveOptions& options)
{
    options.validate();
    Textile t;
    t.options = options;
    const double c = crimpOf(options);
    if (options.kind == WeaveKind::Orthogonal)
        generateOrthogonal(options, c, t);
    else
        generate2D(options, c, t);
    return t;
}

TOWGEOM_END_NAMESPACE
