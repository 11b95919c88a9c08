// The kernel side of TowSurface: the OCCT surface and the input it was fitted to.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <string>
#include <vector>

#include "surface/cap_chart.hpp"
#include "surface/frame.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

struct TowSurface::Impl {
    std::string name;
    FitMode mode = FitMode::Interpolate;
    bool reversed = false;
    std::vector<std::vector<Point3>> sections;  // input points in the surface's order (aligned, reversed)
    std::vector<std::size_t> startShifts;       // see TowSurface::startShifts()
    std::vector<double> uParams;                // u of each section
    std::vector<double> vParams;                // v of each point index
    double towSize = 0.0;
    Handle(Geom_BSplineSurface) surface;        // open in u, periodic in v, outward normals
    // The same surface in the tow's unit frame (its box centred, its size about 1): integrals and
    // projections are computed there, so that no absolute kernel tolerance and no overflow or
    // underflow depends on the user's units.
    detail::Frame unitFrame;
    Handle(Geom_BSplineSurface) unit;
    // The end caps as the continuation of the surface's (u,v) space (see cap_chart.hpp).
    detail::TowCaps caps;
};

namespace detail {

/// Builds TowSurface handles from kernel data (the library's own use).
struct TowSurfaceAccess {
    static TowSurface make(std::shared_ptr<const TowSurface::Impl> impl) { return TowSurface(std::move(impl)); }
};

/// @p surface moved into @p frame (a copy; the parameters are unchanged).
Handle(Geom_BSplineSurface) surfaceInFrame(const Handle(Geom_BSplineSurface)& surface, const Frame& frame);

/// @p tow with its surface, input points and size moved into @p frame: the same tow in the
/// frame's coordinates, with the same parameters. The kernel stages compute on such copies.
TowSurface inFrame(const TowSurface& tow, const Frame& frame);

/// Sets @p tow's unitFrame and unit from its sections, size and surface.
void setUnitFrame(TowSurface::Impl& tow);

/// Fits the surface of @p stack (already validated) with @p options.
std::shared_ptr<const TowSurface::Impl> fitSurface(const TowStack& stack, const FitOptions& options);
}  // namespace detail

TOWGEOM_END_NAMESPACE
