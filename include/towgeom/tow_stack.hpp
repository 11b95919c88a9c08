/// @file tow_stack.hpp
/// @brief TowStack: one tow as exported by a textile simulator, a stack of cross-section polygons.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// One tow as a stack of cross-sections: M sections along the tow, each N points around it.
///
/// Conventions (the same as the `.stw` file format, see stack_reader.hpp):
/// - sections are in order along the tow; every section has the same number of points;
/// - the points go around in a consistent direction (either direction; TowSurface detects it);
/// - the first point of a section may sit anywhere around the tow: sections traced by hand
///   often start a point or more further round than the previous one. A TowStack keeps the
///   points as given; TowSurface::fit renumbers every section cyclically to match the previous
///   one (see TowSurface::startShifts()). Sections must correspond point by point under some
///   such renumbering (validateStack());
/// - the closing point is not repeated.
struct TowStack {
    /// Minimum number of sections accepted by validateStack().
    static constexpr std::size_t kMinSections = 4;
    /// Minimum number of points per section accepted by validateStack().
    static constexpr std::size_t kMinPointsPerSection = 6;

    std::string name;                          ///< the tow's name (file stem unless the file names it)
    std::string source;                        ///< where it came from (a path), for messages
    std::vector<std::vector<Point3>> sections;  ///< sections[i][j]: point j of section i
    /// Optional: lines[i][j] is the 1-based source line of sections[i][j]; empty when unknown.
    std::vector<std::vector<std::size_t>> lines;

    /// Number of sections (M).
    std::size_t sectionCount() const { return sections.size(); }
    /// Number of points per section (N), 0 if there are no sections.
    std::size_t pointsPerSection() const { return sections.empty() ? 0 : sections.front().size(); }
    /// The source line of point @p j of section @p i, 0 if not known.
    std::size_t lineOf(std::size_t i, std::size_t j) const
    {
        return i < lines.size() && j < lines[i].size() ? lines[i][j] : 0;
    }
};

/// Checks a stack against every rule a TowSurface relies on and throws towgeom::Error naming the
/// source and line of the first offence:
/// at least TowStack::kMinSections sections and TowStack::kMinPointsPerSection points each, equal
/// point counts, finite coordinates of magnitude at most 1e100, sections at least 1e-100 across, no consecutive duplicate points,
/// no zero-area or self-intersecting section (checked exactly, in the section's best-fit plane),
/// one orientation for all sections, no two consecutive sections that coincide (under the
/// renumbering below), and consecutive sections that correspond point by point.
///
/// Correspondence: section i + 1 is renumbered by the cyclic shift k that matches it best to
/// section i, the k minimising sum_j |T(b_{(j+k) mod N} - cb) - (a_j - ca)|^2 (a, b the two
/// sections, ca, cb their vertex centroids: a section that moves sideways still matches; T the
/// smallest rotation that turns b's plane onto a's, the identity for parallel sections such as
/// the slices of a scan: the sections of a bending tow tilt as it turns). Its first point may
/// therefore drift around the tow by any number of points. The stack is refused
/// (ErrorCode::InconsistentStart, naming section i + 1 and its first line) only when no shift
/// makes the sections consistent: when under the best one the cosine between the two point
/// configurations, sum_j (a_j - ca).T(b_{j+k} - cb) / sqrt(sum |a_j - ca|^2 sum |b_j - cb|^2),
/// is below 1/2. It is 1 for a section that is the previous one moved, tilted and scaled, at
/// least cos(theta) for one turned by theta within its plane, and about 0 when matched points
/// are no closer than unrelated ones (a flat section turned across the tow, e.g. one from
/// another place, or scrambled points). Orientation is checked first: a section going round the
/// other way is refused as InconsistentOrientation.
///
/// A point counts as a duplicate of its neighbour when they are closer than 1e-9 times the
/// section's size (its bounding-box diagonal); a section has zero area when its area is below
/// 1e-9 times its size squared.
TOWGEOM_EXPORT void validateStack(const TowStack& stack);

/// The faceted tube of a stack: the quad between points j, j+1 of sections i, i+1 split into
/// triangles (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1), 2 (M-1) N triangles in that order,
/// vertices numbered i * N + j. With @p closeEnds, each end is closed by a fan from the mean of
/// its points (2 extra vertices, 2 N extra triangles), orientation consistent with the sides.
TOWGEOM_EXPORT TriangleMesh facetedTube(const TowStack& stack, bool closeEnds);

TOWGEOM_END_NAMESPACE
