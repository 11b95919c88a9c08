// validateStack(): every rule a TowSurface relies on, with messages naming source and line.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/section_geometry.hpp"
#include "towgeom/error.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kDuplicateTolerance = 1e-9;  // relative to the section's extent
constexpr double kAreaTolerance = 1e-9;       // relative to the section's extent squared
// Consecutive sections whose best-matched point configurations are less similar than this are
// refused (detail::StartMatch::similarity: 1 for a section that is the previous one moved,
// tilted and scaled, at least cos(theta) for one turned by theta in its plane, about 0 for
// unrelated points).
constexpr double kMinStartSimilarity = 0.5;

std::string sectionLabel(std::size_t i) { return "section " + std::to_string(i + 1); }

[[noreturn]] void fail(const TowStack& s, ErrorCode code, const std::string& message, std::size_t i,
                       std::size_t j = 0)
{
    throw Error(code, message, s.source.empty() ? "tow '" + s.name + "'" : s.source, s.lineOf(i, j));
}

/// The section projected on its best-fit (least-squares) plane, in that plane's coordinates.
/// Returns false when the points are collinear (no plane).
bool projectOnBestPlane(const std::vector<Point3>& poly, double size, std::vector<Kernel::Point_2>& out)
{
    // In units of the section's size, so that coordinates up to 1e100 cannot overflow.
    const Point3 c = detail::vertexCentroid(poly);
    const double unit = 1.0 / size;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Point3& p : poly) {
        const Eigen::Vector3d d(unit * (p.x - c.x), unit * (p.y - c.y), unit * (p.z - c.z));
        cov += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
    if (!(lambda(1) > 1e-18 * lambda(2))) return false;
    const Eigen::Vector3d e1 = eig.eigenvectors().col(2);
    const Eigen::Vector3d e2 = eig.eigenvectors().col(1);
    out.clear();
    for (const Point3& p : poly) {
        const Eigen::Vector3d d(unit * (p.x - c.x), unit * (p.y - c.y), unit * (p.z - c.z));
        out.emplace_back(d.dot(e1), d.dot(e2));
    }
    return true;
}

void checkSection(const TowStack& s, std::size_t i)
{
    const std::vector<Point3>& poly = s.sections[i];
    for (std::size_t j = 0; j < poly.size(); ++j) {
        const Point3& p = poly[j];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail(s, ErrorCode::NonFinite, "coordinate is not finite", i, j);
        if (std::fabs(p.x) > detail::kMaxCoordinate || std::fabs(p.y) > detail::kMaxCoordinate ||
            std::fabs(p.z) > detail::kMaxCoordinate)
            fail(s, ErrorCode::OutOfRange, "coordinate is beyond +-1e100", i, j);
    }
    const double size = detail::extent(poly);
    if (size < detail::kMinSectionExtent) {
        std::ostringstream what;
        what << sectionLabel(i) << " is only " << size
             << " across, below 1e-100: its tow's area and volume could not be represented (give the input in larger units)";
        fail(s, ErrorCode::OutOfRange, what.str(), i);
    }
    for (std::size_t j = 0; j < poly.size(); ++j) {
        const std::size_t next = (j + 1) % poly.size();
        if (distance(poly[j], poly[next]) <= kDuplicateTolerance * size)
            fail(s, ErrorCode::DuplicatePoint,
                 sectionLabel(i) + ": point " + std::to_string(next + 1) + " repeats point " + std::to_string(j + 1),
                 i, next);
    }
    std::vector<Kernel::Point_2> plane;
    if (!projectOnBestPlane(poly, size, plane))
        fail(s, ErrorCode::ZeroAreaSection, sectionLabel(i) + " has zero area: its points are collinear", i);
    if (!CGAL::is_simple_2(plane.begin(), plane.end(), Kernel()))
        fail(s, ErrorCode::SelfIntersectingSection, sectionLabel(i) + " crosses itself (not a simple polygon)", i);
    const double area = std::fabs(CGAL::polygon_area_2(plane.begin(), plane.end(), Kernel()));
    if (area <= kAreaTolerance)  // the projection is in units of the section's size
        fail(s, ErrorCode::ZeroAreaSection, sectionLabel(i) + " has (almost) zero area", i);
}

void checkCounts(const TowStack& s)
{
    if (s.sections.empty()) fail(s, ErrorCode::EmptyInput, "no sections", 0);
    const std::size_t n = s.sections.front().size();
    for (std::size_t i = 0; i < s.sections.size(); ++i) {
        const std::size_t ni = s.sections[i].size();
        if (ni < TowStack::kMinPointsPerSection)
            fail(s, ErrorCode::TooFewPoints,
                 sectionLabel(i) + " has " + std::to_string(ni) + " points; at least " +
                     std::to_string(TowStack::kMinPointsPerSection) + " are needed",
                 i);
        if (ni != n)
            fail(s, ErrorCode::UnequalSectionSize,
                 sectionLabel(i) + " has " + std::to_string(ni) + " points but section 1 has " + std::to_string(n), i);
    }
    if (s.sections.size() < TowStack::kMinSections)
        fail(s, ErrorCode::TooFewSections,
             std::to_string(s.sections.size()) + " section(s); a tow needs at least " +
                 std::to_string(TowStack::kMinSections),
             s.sections.size() - 1);
}

/// Section i + 1 must correspond to section i point by point under some cyclic renumbering of
/// its points (its first point may sit anywhere around the tow; TowSurface::fit renumbers it):
/// under the best one (detail::bestStartShift), the similarity of the two point configurations
/// must be at least kMinStartSimilarity.
void checkStartPoints(const TowStack& s, std::size_t i, const detail::StartMatch& match)
{
    if (match.similarity >= kMinStartSimilarity) return;
    std::ostringstream what;
    what.precision(2);
    what << sectionLabel(i + 1) << " does not correspond point by point to " << sectionLabel(i)
         << " under any renumbering of its points from another first point (the best, " << match.shift
         << " point(s) on, leaves a similarity of " << match.similarity << "; at least " << kMinStartSimilarity
         << " is needed): it is not the next cross-section of this tow";
    fail(s, ErrorCode::InconsistentStart, what.str(), i + 1);
}

void checkAlongTow(const TowStack& s)
{
    const std::size_t m = s.sections.size();
    // How each section best matches the previous one; the checks below compare matched points.
    std::vector<detail::StartMatch> matches(m - 1);
    for (std::size_t i = 0; i + 1 < m; ++i) matches[i] = detail::bestStartShift(s.sections[i], s.sections[i + 1]);
    double size = 0.0;
    for (std::size_t i = 0; i < m; ++i) size += detail::perimeter(s.sections[i]) / m;
    for (std::size_t i = 0; i + 1 < m; ++i) {
        const auto& a = s.sections[i];
        const auto& b = s.sections[i + 1];
        double chord = 0.0;
        for (std::size_t j = 0; j < a.size(); ++j) chord += distance(a[j], b[(j + matches[i].shift) % b.size()]);
        if (chord / a.size() <= kDuplicateTolerance * size)
            fail(s, ErrorCode::DegenerateTow, sectionLabel(i + 1) + " coincides with " + sectionLabel(i), i + 1);
    }
    // Orientation before start points: a section going the other way round matches no
    // renumbering either, and its own message says why.
    int orientation = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const double d = detail::localOrientation(s.sections, i);
        if (!(std::fabs(d) > 1e-6))
            fail(s, ErrorCode::InconsistentOrientation,
                 sectionLabel(i) + " lies along the tow instead of across it", i);
        const int sign = d > 0 ? 1 : -1;
        if (orientation == 0) orientation = sign;
        if (sign != orientation)
            fail(s, ErrorCode::InconsistentOrientation,
                 sectionLabel(i) + " goes around the tow in the opposite direction to section 1", i);
    }
    for (std::size_t i = 0; i + 1 < m; ++i) checkStartPoints(s, i, matches[i]);
}

}  // namespace

void validateStack(const TowStack& stack)
{
    checkCounts(stack);
    for (std::size_t i = 0; i < stack.sections.size(); ++i) checkSection(stack, i);
    checkAlongTow(stack);
}

TOWGEOM_END_NAMESPACE
