// The kernel side of Curve3.
#pragma once

#include <Geom_Curve.hxx>

#include "towgeom/curve3.hpp"

namespace towgeom {

struct Curve3::Impl {
    Handle(Geom_Curve) curve;
};

}  // namespace towgeom
