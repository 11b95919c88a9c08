/// @file curve3.hpp
/// @brief Curve3: an evaluable 3D curve (a handle on the geometry kernel's curve).
#pragma once

#include <memory>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// An evaluable, immutable 3D curve, e.g. an iso-parametric section of a TowSurface.
///
/// Copies are cheap and share the underlying curve; all members are const and thread-safe.
class TOWGEOM_EXPORT Curve3 {
public:
    /// The kernel-side curve; defined in the library only.
    struct Impl;

    /// Wraps a kernel curve; used by the library, not needed by callers.
    explicit Curve3(std::shared_ptr<const Impl> impl);

    /// First parameter of the curve's domain.
    double firstParameter() const;
    /// Last parameter of the curve's domain.
    double lastParameter() const;
    /// True when the curve is closed (its ends coincide).
    bool closed() const;
    /// The point at parameter @p t.
    Point3 point(double t) const;
    /// The first derivative at parameter @p t.
    Vector3 derivative(double t) const;
    /// Arc length over the whole domain (adaptive Gauss integration, relative accuracy 1e-10).
    double length() const;
    /// Points along the curve whose chords stay within @p chordalTolerance of the curve (and at
    /// least 8 of them). For a closed curve the first point is not repeated at the end.
    /// @throws towgeom::Error (InvalidArgument) if @p chordalTolerance is not positive.
    std::vector<Point3> polyline(double chordalTolerance) const;
    /// Points spaced at most @p spacing apart along the curve (uniform in arc length).
    /// For a closed curve the first point is not repeated at the end.
    /// @throws towgeom::Error (InvalidArgument) if @p spacing is not positive.
    std::vector<Point3> polylineBySpacing(double spacing) const;

    /// The kernel-side curve; for the library's own use.
    const Impl& impl() const { return *impl_; }

private:
    std::shared_ptr<const Impl> impl_;
};

TOWGEOM_END_NAMESPACE
