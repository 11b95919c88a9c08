// Small geometric helpers on one cross-section polygon, shared by validation and fitting.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Mean of the polygon's vertices.
inline Point3 vertexCentroid(const std::vector<Point3>& poly)
{
    Point3 c;
    for (const Point3& p : poly) c = c + p;
    return (1.0 / static_cast<double>(poly.size())) * c;
}

/// The vector area (1/2) sum p_i x p_{i+1} of the closed polygon, taken about its centroid.
inline Vector3 vectorArea(const std::vector<Point3>& poly)
{
    const Point3 c = vertexCentroid(poly);
    Vector3 a;
    for (std::size_t i = 0; i < poly.size(); ++i)
        a = a + cross(poly[i] - c, poly[(i + 1) % poly.size()] - c);
    return 0.5 * a;
}

/// Perimeter of the closed polygon.
inline double perimeter(const std::vector<Point3>& poly)
{
    double l = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) l += distance(poly[i], poly[(i + 1) % poly.size()]);
    return l;
}

/// Bounding-box diagonal of the polygon.
inline double extent(const std::vector<Point3>& poly)
{
    BoundingBox b;
    for (const Point3& p : poly) b.add(p);
    return b.diagonal();
}

/// The largest coordinate magnitude a stack may hold, and the smallest extent of a section:
/// within these a tow's volume (about size^3) and area stay finite and normal in double
/// precision, whatever the units.
constexpr double kMaxCoordinate = 1e100;
constexpr double kMinSectionExtent = 1e-100;

/// A unit vector along @p v (zero for a zero vector), scaled first so that components near
/// 1e100 cannot overflow.
inline Vector3 unitVector(const Vector3& v)
{
    const double big = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(big > 0.0)) return {};
    const Vector3 w = (1.0 / big) * v;
    return (1.0 / norm(w)) * w;
}

/// The cosine between the vector area of section @p i and the tow's local direction there
/// (from the previous to the next section's centroid, one-sided at the ends): positive when the
/// section goes counter-clockwise about the tow, near 0 when it lies along the tow.
inline double localOrientation(const std::vector<std::vector<Point3>>& sections, std::size_t i)
{
    const std::size_t m = sections.size();
    const Vector3 along = vertexCentroid(sections[i + 1 < m ? i + 1 : m - 1]) - vertexCentroid(sections[i == 0 ? 0 : i - 1]);
    return dot(unitVector(vectorArea(sections[i])), unitVector(along));
}

/// How section @p b corresponds to section @p a point by point under its best cyclic renumbering.
struct StartMatch {
    /// k: point j of @p a is matched with point (j + k) mod N of @p b.
    std::size_t shift = 0;
    /// The cosine between the two sections' point configurations under that matching (centroids
    /// removed, @p b's plane tilted onto @p a's, see bestStartShift()), in [-1, 1]: 1 when @p b
    /// is @p a moved, tilted and scaled; at least cos(theta) for @p a turned by theta within its
    /// plane; about 0 when the matched points are no closer than unrelated ones (scrambled
    /// points, a flat section turned across). A section going round the other way is not
    /// judged here (validateStack checks orientation first).
    double similarity = 0.0;
};

/// The smallest rotation that turns unit vector @p from onto unit vector @p to, applied to @p x
/// (Rodrigues); @p x unchanged when the two are (nearly) opposite, where no rotation is smallest.
inline Vector3 tiltOnto(const Vector3& from, const Vector3& to, const Vector3& x)
{
    const double c = dot(from, to);
    if (!(c > -0.999) || dot(from, from) == 0.0 || dot(to, to) == 0.0) return x;
    const Vector3 v = cross(from, to);
    return c * x + cross(v, x) + (dot(v, x) / (1.0 + c)) * v;
}

/// The cyclic shift k that minimises sum_j |T(b_{(j+k) mod N} - cb) - (a_j - ca)|^2, the sum of
/// squared distances between matched points after removing the difference of the centroids
/// (so a section that moves sideways still matches) and the tilt between the sections' planes
/// (T: the smallest rotation turning @p b's unit vector area onto @p a's; the identity for
/// parallel sections, e.g. slices of a scan; for a tow that bends, its sections tilt as it
/// turns); ties go to the smallest k. @p a and @p b have the same N >= 1 points. Each section is
/// taken in units of its own extent, so that any coordinates up to 1e100 are safe; this does
/// not change k (the squared lengths of each section do not depend on k, so k maximises
/// sum_j (a_j - ca).T(b_{j+k} - cb)). O(N^2).
inline StartMatch bestStartShift(const std::vector<Point3>& a, const std::vector<Point3>& b)
{
    const std::size_t n = a.size();
    const Point3 ca = vertexCentroid(a), cb = vertexCentroid(b);
    const double ua = 1.0 / std::fmax(extent(a), 1e-300), ub = 1.0 / std::fmax(extent(b), 1e-300);
    const Vector3 na = unitVector(vectorArea(a)), nb = unitVector(vectorArea(b));
    std::vector<Vector3> da(n), db(n);
    double sa = 0.0, sb = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        da[j] = ua * (a[j] - ca);
        db[j] = tiltOnto(nb, na, ub * (b[j] - cb));
        sa += dot(da[j], da[j]);
        sb += dot(db[j], db[j]);
    }
    // A shift stops as soon as it cannot beat the best so far: what its remaining terms can add
    // is at most |rest of a| |b| (Cauchy-Schwarz). Shift 0, usually the best, goes first, so most
    // others stop after a few points: O(N) per section for consistent input instead of O(N^2).
    std::vector<double> rest(n + 1, 0.0);  // sqrt of sum_{i >= j} |da_i|^2
    for (std::size_t j = n; j-- > 0;) rest[j] = dot(da[j], da[j]) + rest[j + 1];
    for (double& r : rest) r = std::sqrt(r);
    const double norms = std::sqrt(sa) * std::sqrt(sb), slack = 1e-9 * norms;
    StartMatch best;
    double bestDot = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        double sum = 0.0;
        bool beaten = false;
        for (std::size_t j = 0; j < n; ++j) {
            sum += dot(da[j], db[(j + k) % n]);
            if (k > 0 && (j & 7) == 7 && sum + rest[j + 1] * std::sqrt(sb) < bestDot - slack) {
                beaten = true;
                break;
            }
        }
        if (!beaten && (k == 0 || sum > bestDot)) {
            bestDot = sum;
            best.shift = k;
        }
    }
    best.similarity = norms > 0.0 ? bestDot / norms : 0.0;
    return best;
}

/// The cumulative start shifts of a stack's sections, in their own (input) order: shifts[0] = 0
/// and section i, renumbered so that its point j is its input point (j + shifts[i]) mod N,
/// matches section i - 1 (renumbered the same way) best: shifts[i] = (shifts[i-1] +
/// bestStartShift(sections[i-1], sections[i]).shift) mod N. The sections must all have N >= 1
/// points.
inline std::vector<std::size_t> cumulativeStartShifts(const std::vector<std::vector<Point3>>& sections)
{
    std::vector<std::size_t> shifts(sections.size(), 0);
    for (std::size_t i = 1; i < sections.size(); ++i)
        shifts[i] = (shifts[i - 1] + bestStartShift(sections[i - 1], sections[i]).shift) % sections[i].size();
    return shifts;
}

/// @p section renumbered cyclically: point j of the result is point (j + shift) mod N of it.
inline std::vector<Point3> cyclicallyShifted(const std::vector<Point3>& section, std::size_t shift)
{
    const std::size_t n = section.size();
    std::vector<Point3> out(n);
    for (std::size_t j = 0; j < n; ++j) out[j] = section[(j + shift) % n];
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
