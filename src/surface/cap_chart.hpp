// A tow's two end caps as the continuation of its (u,v) space, so that the closed tow (tube and
// caps) is one chart: an intersection curve that runs across a cap keeps continuous parameters.
//
// The start cap takes u in [uPole, uMin), the end cap u in (uMax, uPole]; v is the polar angle
// about the cap's centre, matched to the tube's v at the rim:
//     S(u, v) = c + rho (S(uRim, v) - c),   rho = (u - uPole) / (uRim - uPole) in [0, 1]
// a cone from the centre c to the rim, which is the planar cap when the end section is planar.
// It is one-to-one when the rim is star-shaped about c (CapChart::valid). Its orientation
// continues the tube's: S_u x S_v points out of the tow on the caps too. The depth |uRim - uPole|
// makes a step in u on the cap about as long as one along the tube.
#pragma once

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <gp_XYZ.hxx>

#include <vector>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One end cap's chart.
struct CapChart {
    bool valid = false;     ///< the rim is star-shaped about the centre: the chart is one-to-one
    double uRim = 0.0;      ///< u of the rim (the tube's uMin or uMax)
    double uPole = 0.0;     ///< u of the centre (beyond the rim)
    gp_XYZ centre{0, 0, 0};  ///< c
    gp_XYZ normal{0, 0, 1};  ///< unit normal of the cap's plane (out of the tow)
    gp_XYZ e1{1, 0, 0}, e2{0, 1, 0};  ///< in-plane axes, e1 x e2 = normal
    std::vector<double> v;      ///< rim samples' v, increasing over one period
    std::vector<double> angle;  ///< their polar angles about the centre, unwrapped, monotone
    double radius = 0.0;        ///< mean distance of the rim from the centre

    /// True when @p u lies on this cap (beyond its rim, up to its centre).
    bool contains(double u) const { return uPole < uRim ? u < uRim && u >= uPole : u > uRim && u <= uPole; }
};

/// Both caps of a tow and its tube's u range.
struct TowCaps {
    double uMin = 0.0, uMax = 1.0;
    CapChart start, end;
    /// The whole chart's u range: [start.uPole, end.uPole] (the tube's end where a cap is not
    /// valid).
    double uLow() const { return start.valid ? start.uPole : uMin; }
    double uHigh() const { return end.valid ? end.uPole : uMax; }
    /// The valid cap @p u lies on, or null (on the tube, or beyond an end without a valid cap).
    const CapChart* capAt(double u) const
    {
        return u < uMin ? (start.valid ? &start : nullptr) : u > uMax ? (end.valid ? &end : nullptr) : nullptr;
    }
};

/// The caps of @p surface (open in u, periodic in v, outward normals).
TowCaps capChartsOf(const Handle(Geom_BSplineSurface)& surface);

/// The chart and its first derivatives at (u, v) (u within [uLow, uHigh]); @p tube evaluates the
/// tube's surface.
void chartD1(const GeomAdaptor_Surface& tube, const TowCaps& caps, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv);

/// The chart's point at (u, v).
Point3 chartPoint(const GeomAdaptor_Surface& tube, const TowCaps& caps, double u, double v);

/// The chart parameters of @p p, a point on (or next to) @p cap's plane: v the rim's v in the
/// direction of p from the centre (moved by whole periods to within half a period of @p vNear),
/// u from the distance. False when the chart is not valid or p is at the centre.
bool capParameters(const GeomAdaptor_Surface& tube, const CapChart& cap, const gp_Pnt& p, double vNear, double& u, double& v);

}  // namespace detail
TOWGEOM_END_NAMESPACE
