// The kernel side of TowSurface: the OCCT surface and the input it was fitted to.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <string>
#include <vector>

#include "towgeom/tow_surface.hpp"

namespace towgeom {

struct TowSurface::Impl {
    std::string name;
    FitMode mode = FitMode::Interpolate;
    bool reversed = false;
    std::vector<std::vector<Point3>> sections;  // input points in the surface's order
    std::vector<double> uParams;                // u of each section
    std::vector<double> vParams;                // v of each point index
    double towSize = 0.0;
    Handle(Geom_BSplineSurface) surface;        // open in u, periodic in v, outward normals
};

namespace detail {
/// Fits the surface of @p stack (already validated) with @p options.
std::shared_ptr<const TowSurface::Impl> fitSurface(const TowStack& stack, const FitOptions& options);
}  // namespace detail

}  // namespace towgeom
