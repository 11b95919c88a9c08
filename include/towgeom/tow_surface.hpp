/// @file tow_surface.hpp
/// @brief TowSurface: one tow as a bicubic B-spline surface, open along the tow, periodic around it.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "towgeom/curve3.hpp"
#include "towgeom/fit_options.hpp"
#include "towgeom/point.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace detail {
struct TowSurfaceAccess;
}  // namespace detail

/// The parameter rectangle of a TowSurface.
struct ParameterRange {
    double uMin = 0.0;  ///< first u (first section)
    double uMax = 1.0;  ///< last u (last section)
    double vMin = 0.0;  ///< start of the v period (the seam)
    double vMax = 1.0;  ///< end of the v period; v and v + (vMax - vMin) are the same point
    /// The period in v.
    double vPeriod() const { return vMax - vMin; }
};

/// Position and first derivatives at a (u,v).
struct SurfaceDerivatives {
    Point3 point;  ///< S(u,v)
    Vector3 du;    ///< dS/du
    Vector3 dv;    ///< dS/dv
};

/// Position, first and second derivatives at a (u,v).
struct SurfaceSecondDerivatives {
    Point3 point;  ///< S(u,v)
    Vector3 du;    ///< dS/du
    Vector3 dv;    ///< dS/dv
    Vector3 duu;   ///< d2S/du2
    Vector3 dvv;   ///< d2S/dv2
    Vector3 duv;   ///< d2S/dudv
};

/// How far the input points lie from the surface (closest-point distances).
struct Deviation {
    double max = 0.0;             ///< largest distance
    double rms = 0.0;             ///< root mean square distance
    std::size_t worstSection = 0;  ///< section index of the farthest point
    std::size_t worstPoint = 0;    ///< point index of the farthest point in the input's own numbering
                                   ///< (before the start shift and reversal; see TowSurface::inputPointIndex())
};

/// The jumps of position and derivatives across the v seam at one u, each relative to the size
/// of the quantity (|a - b| / max(|a|, |b|, tiny)). Both sides are evaluated on their own knot
/// span (the last span before the seam and the first after it), so this measures the actual
/// continuity of the representation, not the wrap-around of the parameter.
struct SeamJump {
    double position = 0.0;  ///< relative jump of S
    double first = 0.0;     ///< largest relative jump of dS/du, dS/dv
    double second = 0.0;    ///< largest relative jump of d2S/du2, d2S/dv2, d2S/dudv
};

/// @defgroup surfaces Fitting tow surfaces (stage 1)
/// @brief TowSurface::fit(): each tow's stack of sections as an exact periodic B-spline
/// surface, the input of every later stage.
///
/// @code
/// const towgeom::TowSurface tow = towgeom::TowSurface::fit(towgeom::readStackFile("warp_0.stw"));
/// std::cout << tow.name() << ": volume " << tow.volume() << ", largest deviation " << tow.deviation().max << "\n";
/// @endcode
/// @{

/// One tow as an immutable bicubic B-spline surface S(u,v) fitted to a TowStack.
///
/// **Parameterisation.** u runs along the tow over [0, 1]: section i of the input sits at
/// u = sectionParameters()[i], the normalised cumulative chord length between consecutive
/// sections averaged over the N point columns. v runs around the tow over the period [0, 1):
/// point j of every section sits at v = pointParameters()[j], the normalised cumulative chord
/// length around the section averaged over the M sections. The same v is used for every section
/// (a tensor product), so iso-v curves follow the input's point columns.
///
/// **Start points.** Tensor-product fitting puts point j of every section at the same v, so the
/// sections must correspond point by point. The first input point of a section may sit anywhere
/// around the tow (hand-traced sections drift by a point or more from one to the next): fit()
/// renumbers every section cyclically, section i by the shift that best matches it to section
/// i - 1 as already renumbered (the shift minimising the sum of squared distances between
/// matched points once the centroids are made to coincide and the sections' planes to agree;
/// see validateStack()). Section 0 keeps its first point. startShifts() reports the shifts;
/// sections() holds the renumbered points. A stack that already starts consistently has all
/// shifts 0.
///
/// **Seam.** v = 0 (equivalently v = 1) is the iso-curve through the first point of every
/// section as renumbered: the first input point of section 0, and of every section whose shift
/// is 0. The surface is periodic in v with simple knots, so for Interpolate and Approximate
/// fits it is C2 across the seam (see seamJump()); queries accept any v and wrap it.
///
/// **Orientation.** The surface is always built so that dS/du x dS/dv points out of the tow.
/// If the input sections go counter-clockwise about the tow's direction (the right-hand rule),
/// the point order within every section is reversed on input (the first point, after the
/// renumbering, stays first) and inputReversed() is true; pointParameters(), sections() and
/// startShifts() are given in the surface's order.
///
/// **Ends.** The surface is open in u; volume() closes the tube with its two end sections.
///
/// Copies are cheap (the surface is shared and never modified); every member is const and safe
/// to call from several threads at once.
class TOWGEOM_EXPORT TowSurface {
public:
    /// The kernel-side surface; defined in the library only.
    struct Impl;

    /// Validates @p stack (see validateStack()) and fits a surface to it.
    /// @throws towgeom::Error for invalid stacks (naming source and line), invalid options
    ///         (InvalidArgument) and fits the kernel cannot compute (FitFailed).
    static TowSurface fit(const TowStack& stack, const FitOptions& options = {});

    /// The tow's name (from the stack).
    const std::string& name() const;
    /// The method the surface was fitted with.
    FitMode mode() const;
    /// Number of input sections (M).
    std::size_t sectionCount() const;
    /// Number of input points per section (N).
    std::size_t pointsPerSection() const;
    /// True when the input's point order was reversed to make normals point outwards.
    bool inputReversed() const;
    /// The input points in the surface's order, each section renumbered from its start shift
    /// and reversed when inputReversed(): sections()[i][j] sits at
    /// (sectionParameters()[i], pointParameters()[j]) and is input point inputPointIndex(i, j)
    /// of section i.
    const std::vector<std::vector<Point3>>& sections() const;
    /// The start shift of every section (M values in [0, N), the first 0): point j of section i
    /// in the surface's order is point (j + startShifts()[i]) mod N of the input section taken
    /// in the surface's direction, i.e. after the reversal when inputReversed() (there, point m
    /// of the reversed section is input point (N - m) mod N). Section i's shift is the one that
    /// best matches it to section i - 1 as already shifted; see the class notes.
    const std::vector<std::size_t>& startShifts() const;
    /// The input index of point @p j of section @p i in the surface's order (sections()[i][j]):
    /// (j + startShifts()[i]) mod N, or N minus that (mod N) when inputReversed().
    /// @throws towgeom::Error (InvalidArgument) for i >= M or j >= N.
    std::size_t inputPointIndex(std::size_t i, std::size_t j) const;
    /// u of each input section.
    const std::vector<double>& sectionParameters() const;
    /// v of each input point index (in the surface's order).
    const std::vector<double>& pointParameters() const;
    /// The tow size used for relative tolerances: the mean section perimeter divided by pi.
    double towSize() const;
    /// Number of control points along u and around v.
    std::size_t controlPointCount(bool alongU) const;

    /// The parameter rectangle.
    ParameterRange parameterRange() const;
    /// S(u,v). u must lie in [uMin, uMax] (to 1e-9 of the range); v is wrapped into the period.
    /// @throws towgeom::Error (InvalidArgument) for u outside the range or non-finite input.
    Point3 point(double u, double v) const;
    /// A point of the closed tow (tube and end caps): point(u,v) for u in [uMin, uMax]; for u
    /// beyond the tube's ends a point of its first or last end cap in the cap's chart (see
    /// LoopPoint), as intersection loops give them.
    /// @throws towgeom::Error (InvalidArgument) for u beyond a cap's centre or non-finite input.
    Point3 pointOnClosed(double u, double v) const;
    /// S and its first derivatives at (u,v); same domain rules as point().
    SurfaceDerivatives derivatives(double u, double v) const;
    /// S and its first and second derivatives at (u,v); same domain rules as point().
    SurfaceSecondDerivatives secondDerivatives(double u, double v) const;
    /// The unit outward normal at (u,v); same domain rules as point().
    /// @throws towgeom::Error (Internal) where the surface is singular (dS/du x dS/dv = 0).
    Vector3 normal(double u, double v) const;
    /// The (u,v) of the surface point closest to @p p (global search).
    UV closestParameters(const Point3& p) const;
    /// The (u,v) of the surface point closest to @p p, searched locally from @p start (fast
    /// when a good guess is known, e.g. while marching along a curve). start.v may lie outside
    /// the period (unwrapped); it is wrapped.
    UV closestParameters(const Point3& p, UV start) const;
    /// A box holding the whole surface (from the control points: conservative).
    BoundingBox boundingBox() const;
    /// The section curve v -> S(u, v) at station @p u, closed and periodic.
    Curve3 isoU(double u) const;
    /// The area of the section curve at @p u: the length of its vector area
    /// (1/2) * integral of C x C' dv, exact up to rounding (Gauss quadrature per knot span).
    /// For a planar section this is its area; otherwise the area of its projection on the plane
    /// it is closest to.
    double sectionArea(double u) const;
    /// The volume of the tow, closed at its ends by its end sections (planar ends are closed by
    /// their plane; non-planar ones by the cone from their centroid). Divergence theorem with
    /// Gauss quadrature per knot span: exact up to rounding for the polynomial surface.
    double volume() const;
    /// The lateral surface area (Gauss quadrature per knot span; not counting the end caps).
    double area() const;
    /// The volume of the faceted input: quads between sections split into triangles, ends
    /// closed by fans from their centroids. For comparison with volume().
    double facetedVolume() const;
    /// Closest-point distances of the input points from the surface.
    Deviation deviation() const;
    /// The continuity of the representation across the v seam at station @p u.
    SeamJump seamJump(double u) const;
    /// A triangulation of the surface on a uniform (u,v) grid of @p nu x @p nv vertices (nv
    /// around, the seam shared), with outward normals: a closed-at-seam tube, open at its ends.
    /// @throws towgeom::Error (InvalidArgument) for nu < 2 or nv < 3.
    TriangleMesh tessellate(std::size_t nu, std::size_t nv) const;

    /// The kernel-side surface; for the library's own use.
    const Impl& impl() const { return *impl_; }

private:
    friend struct detail::TowSurfaceAccess;
    explicit TowSurface(std::shared_ptr<const Impl> impl);
    std::shared_ptr<const Impl> impl_;
};

/// @}

TOWGEOM_END_NAMESPACE
