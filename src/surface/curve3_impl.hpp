// The kernel side of Curve3.
#pragma once

#include <Geom_Curve.hxx>

#include "towgeom/curve3.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

struct Curve3::Impl {
    Handle(Geom_Curve) curve;
};

TOWGEOM_END_NAMESPACE
