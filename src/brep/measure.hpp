// Areas and volumes of OpenCASCADE shapes (BRepGProp) at the precision the trimmed B-rep reports.
#pragma once

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS_Shape.hxx>

#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The relative error of OCCT's adaptive integrals of volumes and areas.
constexpr double kMeasureEps = 1e-9;

/// The area of @p shape's faces.
inline double areaOf(const TopoDS_Shape& shape)
{
    GProp_GProps a;
    BRepGProp::SurfaceProperties(shape, a, kMeasureEps);
    return a.Mass();
}

/// The volume @p shape's faces enclose (its magnitude).
inline double volumeOf(const TopoDS_Shape& shape)
{
    GProp_GProps v;
    BRepGProp::VolumeProperties(shape, v, kMeasureEps);
    return std::abs(v.Mass());
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
