/// @file cross_section.hpp
/// @brief CrossSection: the shape of a yarn across its path (circle, ellipse, racetrack,
/// lenticular, Hermite composite), sampled in its own (x, y) plane.
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// The section shapes of the weave generator.
enum class SectionShape {
    Circle,      ///< radius width / 2 (height is ignored)
    Ellipse,     ///< semi-axes width / 2 and height / 2: area pi a b
    Racetrack,   ///< a rectangle with semicircular ends of radius height / 2: area (w - h) h + pi h^2 / 4
    Lenticular,  ///< two circular arcs of radius r = (w^2 + h^2) / (4 h) meeting at the corners (+-w/2, 0)
    Hermite      ///< two cubic Hermite caps between the corners (+-w/2, 0), tangents set to match
                 ///< the lenticular arcs: magnitude u = 4 r (1 - cos a) / sin a for half-angle a
};

/// "circle", "ellipse", "racetrack", "lenticular" or "hermite".
TOWGEOM_EXPORT const char* sectionShapeName(SectionShape shape) noexcept;

/// A yarn cross-section in its own plane: x across the yarn (its width), y through its
/// thickness (its height); the centre line passes through (0, 0).
///
/// **Flattening** (the collision response of Smith & Chen, 2008): a factor f in (0, 1] scales
/// the height by f. For Hermite sections this is done by scaling the cap tangent magnitude u by
/// f (the caps' height is proportional to u); other shapes are scaled by f in y. Either way the
/// section then widens in proportion, by 1 + (1 - f) / 2 in x (a full area-preserving widening
/// by 1 / f would push material sideways into the neighbouring yarns). area() is the area of
/// the unflattened section.
///
/// **Lenticular** geometry: with r = (w^2 + h^2) / (4 h) each arc has half-angle a with
/// sin a = 2 w h / (w^2 + h^2); the arcs leave the corners at the cut-off angle
/// acos(2 w h / (w^2 + h^2)) = pi/2 - a from the y direction.
struct TOWGEOM_EXPORT CrossSection {
    SectionShape shape = SectionShape::Ellipse;  ///< which shape
    double width = 1.0;                          ///< full width (x extent), user's units
    double height = 0.25;                        ///< full height (y extent), user's units
    double flattening = 1.0;                     ///< height factor f in (0, 1]

    /// The exact area of the shape (closed forms; for Hermite caps the exact polynomial integral).
    double area() const;
    /// @p count points around the section, counter-clockwise in (x, y), the first at (xmax, 0):
    /// uniform in angle (circle, ellipse), in arc length (racetrack), or in each arc's or cap's
    /// own parameter (lenticular, Hermite; @p count must then be even).
    /// @throws towgeom::Error (InvalidArgument) for fewer than 6 points, an odd count where an
    ///         even one is needed, or invalid dimensions (non-positive, height > width for
    ///         racetrack and lenticular, flattening outside (0, 1]).
    std::vector<Point2> sample(std::size_t count) const;
    /// Throws towgeom::Error (InvalidArgument) when the dimensions are invalid (see sample()).
    void validate() const;
};

TOWGEOM_END_NAMESPACE
