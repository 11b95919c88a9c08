// extractBezier(): each knot-span element of a tow's B-spline surface as a Bézier patch, checked
// against the surface itself (Bernstein evaluation of the extracted control points equals the
// B-spline's value) and for the partition of unity of the extracted basis.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <map>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace towgeom;

namespace {

/// The largest distance, relative to the tow's size, between Bernstein evaluation of @p b's
/// elements and the tow's surface at @p samples random points.
double worstDeviation(const TowSurface& tow, const BezierSurface& b, std::size_t samples)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> pick(0, b.elements.size() - 1);
    double worst = 0.0;
    for (std::size_t k = 0; k < samples; ++k) {
        const BezierElement& e = b.elements[pick(random)];
        const double s = unit(random), t = unit(random);
        const Point3 bezier = b.point(e, s, t);
        const Point3 exact = tow.point(e.uMin + s * (e.uMax - e.uMin), e.vMin + t * (e.vMax - e.vMin));
        const double d = distance(bezier, exact) / tow.towSize();
        if (!(d <= worst)) worst = d;  // a NaN sticks
    }
    return worst;
}

}  // namespace

TEST_CASE("Bézier extraction of the twill's tows: Bernstein evaluation equals the B-spline, the basis sums to one", "[iga][bezier]")
{
    for (const char* name : {"warp_0", "weft_2"}) {
        INFO(name);
        const TowSurface tow = TowSurface::fit(readStackFile(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/" + name + ".stw"));
        const BezierSurface b = extractBezier(tow);
        REQUIRE(b.uDegree == 3);
        REQUIRE(b.vDegree == 3);
        const std::size_t n = (b.uDegree + 1) * (b.vDegree + 1);
        // One element per pair of distinct consecutive knots of the active range (from knot p to
        // knot n: the clamped ends' repeated knots are outside it), the functions in range.
        const auto active = [](const std::vector<double>& knots, std::size_t degree) {
            return std::set<double>(knots.begin() + static_cast<long>(degree), knots.end() - static_cast<long>(degree));
        };
        CHECK(b.elements.size() == (active(b.uKnots, b.uDegree).size() - 1) * (active(b.vKnots, b.vDegree).size() - 1));
        CHECK(b.controlPoints.size() == b.uFunctions * b.vFunctions);
        CHECK(b.uKnots.size() == b.uFunctions + b.uDegree + 1);
        double worstSum = 0.0;
        std::size_t outOfRange = 0;
        for (const BezierElement& e : b.elements) {
            REQUIRE(e.extraction.size() == n * n);
            REQUIRE(e.functions.size() == n);
            for (std::size_t f : e.functions) outOfRange += f >= b.controlPoints.size();
            // Partition of unity: sum_a N_a = sum_b (sum_a C[a][b]) B_b = 1 for all (s, t) iff
            // every column of C_e sums to 1 (this follows from OCCT's basis summing to 1; the
            // evaluation below is what checks C_e).
            for (std::size_t col = 0; col < n; ++col) {
                double sum = 0.0;
                for (std::size_t row = 0; row < n; ++row) sum += e.extraction[row * n + col];
                if (!(std::abs(sum - 1.0) <= worstSum)) worstSum = std::abs(sum - 1.0);
            }
        }
        CHECK(outOfRange == 0);
        CHECK(worstSum < 1e-12);
        const double worst = worstDeviation(tow, b, 1000);
        WARN(name << ": " << b.elements.size() << " Bézier elements, largest deviation from the B-spline " << worst
                  << " of the tow's size, column sums within " << worstSum << " of 1");
        CHECK(worst < 1e-12);
    }
}

TEST_CASE("Bézier extraction: an element's corner control points are the surface's corners, across the v seam too", "[iga][bezier]")
{
    const TowSurface tow = TowSurface::fit(readStackFile(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/warp_1.stw"));
    const BezierSurface b = extractBezier(tow);
    const std::size_t p = b.uDegree, q = b.vDegree;
    double worst = 0.0;
    for (const BezierElement& e : b.elements) {
        // A Bézier patch interpolates its four corner control points.
        const Point3 corners[4] = {e.controlPoints[0], e.controlPoints[p], e.controlPoints[(p + 1) * q], e.controlPoints[p + (p + 1) * q]};
        const Point3 exact[4] = {tow.point(e.uMin, e.vMin), tow.point(e.uMax, e.vMin), tow.point(e.uMin, e.vMax), tow.point(e.uMax, e.vMax)};
        for (int k = 0; k < 4; ++k) {
            const double d = distance(corners[k], exact[k]) / tow.towSize();
            if (!(d <= worst)) worst = d;
        }
    }
    CHECK(worst < 1e-12);
    // The last v-span ends where the first begins: the seam.
    const double vMax = std::max_element(b.elements.begin(), b.elements.end(), [](const auto& a, const auto& c) { return a.vMax < c.vMax; })->vMax;
    const ParameterRange r = tow.parameterRange();
    CHECK(vMax == Approx(r.vMax).epsilon(1e-12));
    // The basis is periodic: in each row of elements along v, every v function is non-zero on
    // exactly q+1 elements (a basis cut at the seam has functions on fewer).
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> onElements;  // (u span, v function) -> elements
    for (const BezierElement& e : b.elements)
        for (std::size_t av = 0; av <= q; ++av) ++onElements[{e.uSpan, e.functions[(p + 1) * av] % b.vFunctions}];
    std::size_t wrong = 0;
    for (const auto& [key, n] : onElements) wrong += n != q + 1;
    CHECK(wrong == 0);
    CHECK(onElements.size() == (b.elements.back().uSpan + 1) * b.vFunctions);
}
