/// @file yarn_path.hpp
/// @brief YarnPath: a yarn's centre line through its interlacement points (cubic Hermite).
#pragma once

#include <memory>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// A yarn's centre line: a piecewise cubic Hermite curve through points p[0..n-1], one segment
/// per pair of consecutive points, C1 at the points. The parameter t runs over [0, n-1]; the
/// path passes through p[i] at t = i. Internally an OpenCASCADE B-spline (a Hermite spline is
/// a cubic B-spline with triple interior knots).
///
/// Tangents: catmullRom() uses (p[i+1] - p[i-1]) / 2; cardinal() uses
/// (1 - s) / 2 * (p[i+1] - p[i-1]) with tension s (s = 0 is Catmull-Rom, s = 1 gives zero
/// tangents); at the two ends the one-sided difference (p[1] - p[0], p[n-1] - p[n-2]) is used,
/// scaled the same way. Copies are cheap; every member is const and thread-safe.
class TOWGEOM_EXPORT YarnPath {
public:
    /// The kernel-side curve; defined in the library only.
    struct Impl;

    /// A Hermite path through @p points with the given @p tangents (one per point, derivative
    /// with respect to t). @throws towgeom::Error (InvalidArgument) for fewer than 2 points,
    /// mismatched sizes, non-finite input or coincident consecutive points.
    static YarnPath hermite(const std::vector<Point3>& points, const std::vector<Vector3>& tangents);
    /// The Catmull-Rom path through @p points (cardinal with tension 0).
    static YarnPath catmullRom(const std::vector<Point3>& points);
    /// The cardinal spline through @p points with tension @p tension in [0, 1].
    static YarnPath cardinal(const std::vector<Point3>& points, double tension);

    /// Number of points the path interpolates.
    std::size_t pointCount() const;
    /// The last parameter, pointCount() - 1 (the first is 0).
    double lastParameter() const;
    /// r(t); t is clamped to [0, lastParameter()].
    Point3 point(double t) const;
    /// r'(t).
    Vector3 derivative(double t) const;
    /// r''(t) (one-sided at the interpolated points, where it may jump).
    Vector3 secondDerivative(double t) const;
    /// Curvature |r' x r''| / |r'|^3 at t (0 where r' vanishes).
    double curvature(double t) const;
    /// Arc length between parameters @p t0 and @p t1 (Gauss integration to 1e-10).
    double length(double t0, double t1) const;

    /// The kernel-side curve; for the library's own use.
    const Impl& impl() const { return *impl_; }

private:
    explicit YarnPath(std::shared_ptr<const Impl> impl);
    std::shared_ptr<const Impl> impl_;
};

TOWGEOM_END_NAMESPACE
