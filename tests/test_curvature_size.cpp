// Surface meshes graded by curvature (issue 39, item 3: volume meshes an analyst can afford).
// The size field against the closed form of an elliptical tube's curvature, k(t) = a b / (a^2
// sin^2 t + b^2 cos^2 t)^(3/2), and the graded mesh's chord deviation measured against the exact
// ellipse (distance by dense sampling and a Newton step, independent of the code under test).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "mesh/curvature_size.hpp"
#include "towgeom/error.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/surface_mesher.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

double ellipseCurvature(double a, double b, double t)
{
    const double s = std::sin(t), c = std::cos(t);
    return a * b / std::pow(a * a * s * s + b * b * c * c, 1.5);
}

/// The distance from (y, z) to the ellipse y = a cos t, z = b sin t: the nearest of 1,000
/// samples, refined by Newton's method on the squared distance.
double distanceToEllipse(double a, double b, double y, double z)
{
    constexpr int kSamples = 1000;
    double best = 0.0, bestD2 = 1e300;
    for (int k = 0; k < kSamples; ++k) {
        const double t = 2.0 * kPi * k / kSamples;
        const double d2 = std::pow(a * std::cos(t) - y, 2) + std::pow(b * std::sin(t) - z, 2);
        if (d2 < bestD2) bestD2 = d2, best = t;
    }
    for (int it = 0; it < 20; ++it) {  // f(t) = (P(t) - q) . P'(t) = 0
        const double c = std::cos(best), s = std::sin(best);
        const double f = (a * c - y) * (-a * s) + (b * s - z) * (b * c);
        const double df = a * a * s * s + b * b * c * c + (a * c - y) * (-a * c) + (b * s - z) * (-b * s);
        if (df == 0.0) break;
        best -= f / df;
    }
    return std::hypot(a * std::cos(best) - y, b * std::sin(best) - z);
}

/// The mean over the ellipse's perimeter of (largest / size)^2, size = sqrt(8 d / k) within
/// [smallest, largest] (and at most @p cap): how many times more triangles than at the largest
/// size everywhere.
double closedFormDensity(double a, double b, double d, double largest, double smallest, double cap = 1e300)
{
    double weighted = 0.0, perimeter = 0.0;
    constexpr int kSteps = 200000;
    for (int k = 0; k < kSteps; ++k) {
        const double t = 2.0 * kPi * (k + 0.5) / kSteps;
        const double ds = std::hypot(a * std::sin(t), b * std::cos(t));
        const double size = std::min(cap, std::clamp(std::sqrt(8.0 * d / ellipseCurvature(a, b, t)), smallest, largest));
        weighted += ds * (largest / size) * (largest / size);
        perimeter += ds;
    }
    return weighted / perimeter;
}

/// A straight tube along +x over [0, length], sections the ellipse (a cos t, b sin t) in (y, z).
TowStack ellipticalTube(double a, double b, double length, std::size_t sections, std::size_t points)
{
    TowStack stack;
    stack.name = "ellipse";
    for (std::size_t i = 0; i < sections; ++i) {
        std::vector<Point3> section;
        for (std::size_t j = 0; j < points; ++j) {
            const double t = 2.0 * kPi * static_cast<double>(j) / static_cast<double>(points);
            section.push_back({length * static_cast<double>(i) / static_cast<double>(sections - 1), a * std::cos(t), b * std::sin(t)});
        }
        stack.sections.push_back(section);
    }
    return stack;
}

/// The (u,v) of input point @p j of section @p i of the stack @p tow was fitted to (no search).
UV inputUV(const TowSurface& tow, std::size_t i, std::size_t j)
{
    const std::size_t n = tow.pointParameters().size();
    for (std::size_t k = 0; k < n; ++k)
        if (tow.inputPointIndex(i, k) == j % n) return {tow.sectionParameters()[i], tow.pointParameters()[k]};
    throw std::logic_error("no such input point");
}

}  // namespace

TEST_CASE("the curvature size of an elliptical tube follows the closed form sqrt(8 d / k)", "[mesh][curvature]")
{
    const double a = 0.4, b = 0.1, length = 3.0, d = 1e-4;
    const TowSurface tow = TowSurface::fit(ellipticalTube(a, b, length, 31, 256));
    // Largest 1 and smallest 1e-4: no clamp between k = 8 d (size 1) and k = 8e4 (1e-4); the
    // ellipse's curvature runs from b / a^2 = 0.625 to a / b^2 = 40.
    const double largest = 1.0, smallest = 1e-4;
    SECTION("ungraded: the closed form at every point")
    {
        const detail::CurvatureSize size(tow, d, largest, smallest, 1e9);
        double worst = 0.0;
        for (int k = 0; k < 64; ++k) {  // input points (x = 1.3, t = 2 pi j / 256), their (u,v) the fit's
            const std::size_t j = 4 * static_cast<std::size_t>(k) + 2;
            const double t = 2.0 * kPi * static_cast<double>(j) / 256.0;
            const UV at = inputUV(tow, 13, j);
            const double expected = std::sqrt(8.0 * d / ellipseCurvature(a, b, t));
            worst = std::max(worst, std::abs(size.at(at) / expected - 1.0));
        }
        // The grid's interpolation of the field between its nodes (256 around), and the fit.
        CHECK(worst < 0.02);
        // The triangle count's factor: the mean of (largest / size)^2 = k / (8 d) over the area;
        // each grid node takes the largest curvature of itself and half a step either side, so
        // a little over (2.1 % here).
        const double density = closedFormDensity(a, b, d, largest, smallest);
        CHECK(size.densityOverLargest() >= density);
        CHECK(size.densityOverLargest() <= 1.03 * density);
    }
    SECTION("clamped to [smallest, largest]")
    {
        const detail::CurvatureSize size(tow, d, 0.02, 0.005, 1e9);
        // At the minor axis's ends k = 0.625: sqrt(8 d / k) = 0.036, clamped to 0.02; at the
        // major axis's ends k = 40: 0.0045, clamped to 0.005.
        CHECK(size.at(inputUV(tow, 10, 64)) == Approx(0.02).epsilon(1e-9));  // (x, y, z) = (1, 0, b)
        CHECK(size.at(inputUV(tow, 10, 0)) == Approx(0.005).epsilon(1e-6));  // (1, a, 0)
    }
    SECTION("graded: the size grows by at most the slope times the distance, and the bound is reached")
    {
        // The ungraded field grows by up to about 0.15 per unit length here: a slope of 0.02
        // shrinks most of it.
        const double slope = 0.02;
        const detail::CurvatureSize size(tow, d, largest, smallest, slope), free(tow, d, largest, smallest, 1e9);
        // Neighbouring input points around the tube (t 2 pi / 256 apart) at every section.
        double worst = 0.0;
        for (std::size_t i = 2; i <= 28; ++i)
            for (std::size_t j = 0; j < 256; ++j) {
                const double tp = 2.0 * kPi * static_cast<double>(j) / 256.0, tq = 2.0 * kPi * static_cast<double>(j + 1) / 256.0;
                const Point3 P{0.1 * static_cast<double>(i), a * std::cos(tp), b * std::sin(tp)}, Q{P.x, a * std::cos(tq), b * std::sin(tq)};
                const double grow = std::abs(size.at(inputUV(tow, i, j)) - size.at(inputUV(tow, i, j + 1)));
                worst = std::max(worst, grow / distance(P, Q));
            }
        // Interpolated between grid nodes graded along the grid's edges: within 1.5 x the slope,
        // and near it somewhere (the graded field is steep wherever the grading acted).
        CHECK(worst <= 1.5 * slope);
        CHECK(worst >= 0.5 * slope);
        // Never larger than the ungraded field, and smaller where the grading acted: at the
        // minor axis's ends, 0.1 (a quarter of the way round) from the tips' 0.0045, at most
        // 0.0045 + 0.02 x 0.42 (the arc from a tip) = 0.0129 against the ungraded 0.036.
        for (std::size_t j = 0; j < 256; j += 4) {
            const UV at = inputUV(tow, 15, j);
            CHECK(size.at(at) <= free.at(at) * (1.0 + 1e-12));
        }
        const UV minor = inputUV(tow, 15, 64);  // (1.5, 0, b)
        CHECK(free.at(minor) == Approx(std::sqrt(8.0 * d / ellipseCurvature(a, b, 0.5 * kPi))).epsilon(0.02));
        CHECK(size.at(minor) < 0.0135);
        CHECK(size.at(minor) > 0.0045);
    }
}

TEST_CASE("largestCurvature: |H| + sqrt(H^2 - K) against the largest normal curvature over all directions", "[mesh][curvature]")
{
    // A twisted elliptical tube (sections turned by 1.5 radians over its length): its (u,v) lines
    // are not lines of curvature (F and M nonzero), unlike the straight tube's. The oracle: the
    // normal curvature II(t,t) / I(t,t) maximised over 20,000 directions t = cos(s) S_u + sin(s) S_v.
    TowStack twisted;
    twisted.name = "twisted";
    for (std::size_t i = 0; i < 41; ++i) {
        const double x = 3.0 * static_cast<double>(i) / 40.0, turn = 0.5 * x;
        std::vector<Point3> section;
        for (std::size_t j = 0; j < 64; ++j) {
            const double t = 2.0 * kPi * static_cast<double>(j) / 64.0, y = 0.4 * std::cos(t), z = 0.15 * std::sin(t);
            section.push_back({x, y * std::cos(turn) - z * std::sin(turn), y * std::sin(turn) + z * std::cos(turn)});
        }
        twisted.sections.push_back(section);
    }
    const TowSurface tow = TowSurface::fit(twisted);
    const ParameterRange r = tow.parameterRange();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(r.uMin + 0.1 * (r.uMax - r.uMin), r.uMax - 0.1 * (r.uMax - r.uMin)), v(r.vMin, r.vMax);
    double worst = 0.0, mixed = 0.0;
    for (int k = 0; k < 50; ++k) {
        const SurfaceSecondDerivatives d = tow.secondDerivatives(u(random), v(random));
        const Vector3 n = (1.0 / norm(cross(d.du, d.dv))) * cross(d.du, d.dv);
        double best = 0.0;
        for (int s = 0; s < 20000; ++s) {
            const double c = std::cos(kPi * s / 20000.0), si = std::sin(kPi * s / 20000.0);
            const Vector3 t = c * d.du + si * d.dv;
            const double second = c * c * dot(d.duu, n) + 2.0 * c * si * dot(d.duv, n) + si * si * dot(d.dvv, n);
            best = std::max(best, std::abs(second) / dot(t, t));
        }
        worst = std::max(worst, std::abs(detail::largestCurvature(d) / best - 1.0));
        mixed = std::max(mixed, std::abs(dot(d.du, d.dv)) / (norm(d.du) * norm(d.dv)) + std::abs(dot(d.duv, n)));
    }
    CHECK(mixed > 0.1);  // F and M are not zero: the test reaches the mixed terms
    CHECK(worst < 1e-6);
}

TEST_CASE("a mesh graded by curvature keeps its chord deviation and has fewer triangles", "[mesh][curvature][resolve]")
{
    const double a = 0.4, b = 0.1, length = 2.0;
    const std::vector<TowSurface> tows{TowSurface::fit(ellipticalTube(a, b, length, 21, 128))};
    const auto meshWith = [&](double h, double d) {
        ResolveOptions o;
        o.mesh.edgeLength = h;
        o.mesh.chordDeviation = d;
        o.mesh.caps = false;
        return resolveTextile(tows, o);
    };
    const double h = 0.1, d = 2e-4;
    const ResolveResult graded = meshWith(h, d), uniform = meshWith(h, 0.0);
    // The deviation of each tube triangle: its centroid's distance to the exact ellipse, bounded
    // by about s^2 k / 6 for a triangle of edges s (1.33 d at s = sqrt(8 d / k)); where the
    // clamp at h leaves the size under sqrt(8 d / k), smaller still.
    const auto worstDeviation = [&](const ResolveResult& r) {
        double worst = 0.0;
        for (const auto& tr : r.mesh.tows[0].triangles) {
            const Point3 c = (1.0 / 3.0) * (r.mesh.nodes[tr[0]] + r.mesh.nodes[tr[1]] + r.mesh.nodes[tr[2]]);
            worst = std::max(worst, distanceToEllipse(a, b, c.y, c.z));
        }
        return worst;
    };
    const double gradedDeviation = worstDeviation(graded), uniformDeviation = worstDeviation(uniform);
    const std::size_t gradedCount = graded.mesh.tows[0].triangles.size(), uniformCount = uniform.mesh.tows[0].triangles.size();
    WARN("graded: " << gradedCount << " triangles, deviation " << gradedDeviation << "; uniform h: " << uniformCount
                    << " triangles, deviation " << uniformDeviation);
    CHECK(gradedDeviation <= 1.5 * d);
    CHECK(uniformDeviation > 10.0 * d);  // the uniform mesh at h misses the tips by far more
    // The count the closed form predicts: (h / size)^2 times the uniform one on average (23 here;
    // the mesher's grading adds some, its coarser shapes take some), far fewer than a uniform
    // mesh at the tips' size sqrt(8 d / 40) = 0.0063 would need ((h / 0.0063)^2 = 250 times).
    const double ratio = static_cast<double>(gradedCount) / static_cast<double>(uniformCount);
    const double predicted = closedFormDensity(a, b, d, h, h / 100.0);
    CHECK(ratio > 0.5 * predicted);
    CHECK(ratio < 1.5 * predicted);
    CHECK(ratio < 250.0 / 5.0);
}

TEST_CASE("ParametricMesher grades by curvature as resolve does, with the host's size function", "[mesh][curvature]")
{
    const double a = 0.4, b = 0.1, d = 2e-4;
    const TowSurface tow = TowSurface::fit(ellipticalTube(a, b, 2.0, 21, 128));
    SurfaceMeshOptions o;
    o.edgeLength = 0.1;
    o.chordDeviation = d;
    o.caps = false;
    const auto worstDeviation = [&](const SurfaceMesh& m) {
        double worst = 0.0;
        for (const auto& tr : m.triangles) {
            const Point3 c = (1.0 / 3.0) * (m.nodes[tr[0]] + m.nodes[tr[1]] + m.nodes[tr[2]]);
            worst = std::max(worst, distanceToEllipse(a, b, c.y, c.z));
        }
        return worst;
    };
    const SurfaceMesh graded = ParametricMesher(tow, o).mesh({});
    CHECK(worstDeviation(graded) <= 1.5 * d);
    // A host's size function finer on half the tube (x < 1): the smaller of the two there, as
    // many times more triangles on that half as the closed form says (4.6).
    o.size = [](const UV& at) { return at.u < 0.5 ? 0.01 : 1.0; };
    const SurfaceMesh both = ParametricMesher(tow, o).mesh({});
    CHECK(worstDeviation(both) <= 1.5 * d);
    std::size_t finerHalf = 0, coarserHalf = 0;
    for (const auto& tr : both.triangles) ((both.nodes[tr[0]].x + both.nodes[tr[1]].x + both.nodes[tr[2]].x) < 3.0 ? finerHalf : coarserHalf)++;
    const double predicted = closedFormDensity(a, b, d, 0.1, 0.001, 0.01) / closedFormDensity(a, b, d, 0.1, 0.001);
    CHECK(static_cast<double>(finerHalf) / static_cast<double>(coarserHalf) == Approx(predicted).epsilon(0.4));
    // Refused: a negative deviation.
    o.chordDeviation = -1.0;
    CHECK_THROWS_AS(ParametricMesher(tow, o), Error);
}
