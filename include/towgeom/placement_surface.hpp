/// @file placement_surface.hpp
/// @brief readPlacementSurface(): a fibre-placement tool surface from a STEP or IGES file as a
/// NurbsSurface.
#pragma once

#include <cstddef>
#include <string>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// A face read from a CAD file.
struct PlacementSurface {
    /// The face's surface as a clamped NURBS over the face's (u,v) box (OpenCASCADE's
    /// GeomConvert: exact for B-spline, Bezier, analytic, revolution and extrusion surfaces; other
    /// kinds, such as offset surfaces, approximated to 1e-4), its normal turned to the face's
    /// outward side (the u direction reversed when the face is reversed). The face's trimming
    /// curves are not kept: the whole box is the surface.
    NurbsSurface surface;
    std::size_t faceCount = 0;  ///< faces in the file
    std::size_t face = 0;       ///< which one this is (0-based, in the file's order)
};

/// Reads face @p face (0-based, in the order OpenCASCADE explores the file's shapes) of the STEP
/// (.step, .stp) or IGES (.iges, .igs) file @p path. Lengths come out in millimetres: OpenCASCADE's
/// readers convert the file's unit (a file in metres gives 1000 per metre). Safe to call from
/// several threads (OpenCASCADE's data exchange is serialised).
/// @throws towgeom::Error (FileNotFound, FileUnreadable naming the file) when it cannot be read
///         as STEP or IGES; (InvalidArgument) for another extension or a face index past the
///         file's faces (the message gives their count); (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT PlacementSurface readPlacementSurface(const std::string& path, std::size_t face = 0);

/// @}

TOWGEOM_END_NAMESPACE
