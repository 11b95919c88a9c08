/// @file bezier_extraction.hpp
/// @brief Bézier extraction of a tow's B-spline surface for isogeometric analysis (Borden et al.,
/// "Isogeometric finite element data structures based on Bézier extraction of NURBS", 2011):
/// every knot-span element as a Bézier patch, with the operator that maps the B-spline basis onto
/// the element's Bernstein basis.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// One knot-span element (a u-span x a v-span of non-zero length) as a Bézier patch.
struct TOWGEOM_EXPORT BezierElement {
    std::size_t uSpan = 0;  ///< the element's index among the u-spans (0-based)
    std::size_t vSpan = 0;  ///< its index among the v-spans
    double uMin = 0.0;      ///< its parameter box: u from uMin ...
    double uMax = 0.0;      ///< ... to uMax
    double vMin = 0.0;      ///< v from vMin ...
    double vMax = 0.0;      ///< ... to vMax
    /// The (p+1)(q+1) B-spline basis functions non-zero on the element, local index
    /// a = au + (p+1) av, each as its global index iu * BezierSurface::vFunctions + iv (iv of
    /// the periodic basis, (vSpan + av) mod vFunctions: the elements next to the seam share
    /// functions across it; iu = the first non-zero u function + au).
    std::vector<std::size_t> functions;
    /// The element extraction operator C_e, row-major ((p+1)(q+1) rows a, as many columns b):
    /// N_a = sum_b C_e[a][b] B_b, with B_b = B_bu(s) B_bv(t) the Bernstein polynomials of degree
    /// (p, q) of the element's local coordinates s = (u - uMin) / (uMax - uMin), t likewise
    /// (local b = bu + (p+1) bv). The tensor product of the u and v operators.
    std::vector<double> extraction;
    /// The Bézier control points (local index b): sum_a C_e[a][b] times the control point of
    /// function a.
    std::vector<Point3> controlPoints;
};

/// A tow's lateral surface (the tube, not its end caps) as B-spline data and its Bézier
/// elements. The surface is polynomial (weights 1), open and clamped along the tow (u),
/// periodic around it (v).
struct TOWGEOM_EXPORT BezierSurface {
    std::size_t uDegree = 0;    ///< p
    std::size_t vDegree = 0;    ///< q
    std::size_t uFunctions = 0;  ///< B-spline basis functions along u
    std::size_t vFunctions = 0;  ///< along v: the periodic basis's (as many as control points around)
    bool vPeriodic = true;       ///< v is periodic: function iv continues across the seam
    /// The full (flat) knot vector along u, clamped.
    std::vector<double> uKnots;
    /// Along v, the periodic knots unrolled over one period and q spans beyond it on each side
    /// (open, not clamped: OCCT's SetVNotPeriodic()); the elements cover one period. Unrolled
    /// basis function j (of vKnots) is periodic function j mod vFunctions.
    std::vector<double> vKnots;
    /// Control points, global index iu * vFunctions + iv.
    std::vector<Point3> controlPoints;
    /// Every element, u-spans outer, v-spans inner.
    std::vector<BezierElement> elements;

    /// The point of element @p e at local coordinates (@p s, @p t) in [0, 1]^2 by Bernstein
    /// evaluation of its Bézier control points.
    Point3 point(const BezierElement& e, double s, double t) const;
};

/// The Bézier extraction of @p tow's lateral surface: its basis functions evaluated by OCCT
/// (BSplCLib) at p+1 points per span and the operator that maps them onto the Bernstein basis
/// there (entries below 64 machine epsilons set to 0: the operator's zeros).
/// @throws towgeom::Error (Internal) if the kernel's surface is rational or periodic along the
/// tow (fitted tows never are), or its basis cannot be read span by span.
TOWGEOM_EXPORT BezierSurface extractBezier(const TowSurface& tow);

/// Writes @p bezier as one JSON object for isogeometric codes: {"tow", "u_degree", "v_degree",
/// "u_functions", "v_functions", "v_periodic", "u_knots", "v_knots", "control_points":[[x,y,z]...] (global
/// index iu * v_functions + iv), "elements":[{"u_span", "v_span", "u":[min,max], "v":[min,max],
/// "functions":[global indices], "extraction":[row-major C_e], "bezier_points":[[x,y,z]...]}]}
/// (see BezierElement for the local orders).
/// @throws towgeom::Error (WriteFailed) if @p out fails.
TOWGEOM_EXPORT void writeBezierJson(const BezierSurface& bezier, const std::string& tow, std::ostream& out);

TOWGEOM_END_NAMESPACE
