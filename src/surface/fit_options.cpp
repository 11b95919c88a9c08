#include "towgeom/fit_options.hpp"

namespace towgeom {

const char* fitModeName(FitMode mode) noexcept
{
    switch (mode) {
    case FitMode::Interpolate: return "interpolate";
    case FitMode::Approximate: return "approximate";
    case FitMode::ControlNet: return "controlnet";
    }
    return "unknown";
}

}  // namespace towgeom
