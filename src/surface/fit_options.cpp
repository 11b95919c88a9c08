#include "towgeom/fit_options.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

const char* fitModeName(FitMode mode) noexcept
{
    switch (mode) {
    case FitMode::Interpolate: return "interpolate";
    case FitMode::Approximate: return "approximate";
    case FitMode::ControlNet: return "controlnet";
    }
    return "unknown";
}

TOWGEOM_END_NAMESPACE
