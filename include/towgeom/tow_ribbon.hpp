/// @file tow_ribbon.hpp
/// @brief towRibbon(): a fibre-placement tow laid on a surface as a tow stack (.stw), so that
/// towgeom's own intersection finds the overlaps between tows before the part is made (a gap
/// gives no intersection: measure it between the centrelines).
#pragma once

#include <cstddef>
#include <string>

#include "towgeom/cross_section.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// The tow of cross-section @p section laid on @p surface along @p centreline: at each of the
/// centreline's points a section of @p points points, its width along O = N x T (N the surface's
/// normal, T the centreline's tangent), its height along N, resting on the surface (its lowest
/// point on the centreline). The sections are flat: across a surface curving away from the
/// normal side the tow's edges stand off it by about width^2 kappa / 8, across one curving
/// towards it they sink into it by as much.
/// @throws towgeom::Error (InvalidArgument) for fewer than TowStack::kMinSections centreline
///         points, fewer than TowStack::kMinPointsPerSection points, an invalid section, or a
///         normal or tangent that vanishes.
TOWGEOM_EXPORT TowStack towRibbon(const NurbsSurface& surface, const CurveOnSurface& centreline, const CrossSection& section,
                                  std::size_t points, const std::string& name);

/// @}

TOWGEOM_END_NAMESPACE
