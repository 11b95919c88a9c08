/// @file knot_span_classification.hpp
/// @brief classifyKnotSpans(): each knot-span element of a resolved tow's B-spline surface as
/// valid (kept whole), invalid (removed whole) or trimmed (cut by the boundary of what the tow
/// keeps), with the trimming curves inside it, for isogeometric analysis of trimmed surfaces
/// (as Du et al. 2020 classify elements).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup iga Isogeometric analysis
/// @brief Bézier extraction and knot-span classification of the tows' surfaces.
/// @{

/// What the resolved tow keeps of a knot-span element.
enum class ElementClass : unsigned char {
    Valid,    ///< all of it
    Invalid,  ///< none of it (inside a tow ranked above, replaced by a mid-surface, or clipped away by a cell)
    Trimmed   ///< part of it: a trimming curve runs through it
};

/// One knot-span element (a u-span x a v-span of the surface's knots) and what is kept of it.
struct KnotSpanElement {
    std::size_t uSpan = 0;  ///< index among the u-spans (as BezierElement::uSpan)
    std::size_t vSpan = 0;  ///< index among the v-spans over one period (as BezierElement::vSpan)
    double uMin = 0.0;      ///< the element's parameter box: u from uMin ...
    double uMax = 0.0;      ///< ... to uMax
    double vMin = 0.0;      ///< v from vMin ...
    double vMax = 0.0;      ///< ... to vMax
    ElementClass kind = ElementClass::Valid;  ///< valid, invalid or trimmed
    double area = 0.0;      ///< surface area of the whole element
    double keptArea = 0.0;  ///< surface area of its kept part
    /// For a trimmed element: the pieces of the trimming curves inside it, each a polyline in
    /// (u,v) within the element's box (the boundary of the kept part of the surface in the tow's
    /// mesh: its loop chords, a cell's cut), the kept side on the left seen in (u,v).
    std::vector<std::vector<UV>> trimmingCurves;
};

/// Every knot-span element of one tow, u-spans outer, v-spans inner.
struct TOWGEOM_EXPORT KnotSpanClassification {
    std::string tow;                       ///< the tow's name
    std::vector<KnotSpanElement> elements;  ///< u-spans outer, v-spans inner
    /// The surface area the tow keeps of its own surface: the elements' kept areas added up.
    double keptArea() const;
    /// The number of elements of class @p kind.
    std::size_t count(ElementClass kind) const;
};

/// Classifies the knot-span elements of tow @p tow of @p resolved (resolveTextile()'s mesh of
/// @p tows): the part of its own surface it keeps is the (u,v) union of its own kept side
/// triangles (TowMesh::parameters; not a region's triangles taken from another tow, nor a
/// mid-surface's), so trimming curves are its loops' chords and a cell's cut as the mesh has
/// them. Each element is intersected with those triangles (CGAL, triangle against box) and the
/// surface area |S_u x S_v| integrated over every piece (12 x 12 Gauss-Legendre, on each
/// element's box and collapsed onto each triangle, exact surface derivatives; about 1e-9
/// relative). An element that a trimming curve runs through (not merely along its edge) and that
/// keeps part of its area is trimmed, with its kept area and the curve's pieces chained into
/// polylines; any other is valid (kept area = its area) or invalid (0), as its pieces cover it or
/// not. The mesh must be of these tows as they are (not of the shrunk tows of
/// ResolutionMethod::Shrink, whose surfaces differ).
///
/// @code
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows);
/// const towgeom::KnotSpanClassification c = towgeom::classifyKnotSpans(tows, r.mesh, 4);
/// std::cout << c.count(towgeom::ElementClass::Trimmed) << " trimmed elements\n";
/// @endcode
///
/// @throws towgeom::Error (InvalidArgument) for a tow index out of range or a mesh of other tows.
TOWGEOM_EXPORT KnotSpanClassification classifyKnotSpans(const std::vector<TowSurface>& tows, const TextileMesh& resolved, std::size_t tow);

/// Writes @p c as JSON: {"tow", "valid", "invalid", "trimmed", "kept_area",
/// "elements":[{"u_span","v_span","u":[min,max],"v":[min,max],"class","area","kept_area",
/// "trimming_curves":[[[u,v],...],...]}]}.
/// @throws towgeom::Error (WriteFailed) if @p out fails.
TOWGEOM_EXPORT void writeKnotSpansJson(const KnotSpanClassification& c, std::ostream& out);

/// Writes @p c's elements as legacy VTK polydata on @p tow's surface (each element a 4 x 4 grid
/// of quads split into triangles), cell data "class" (0 valid, 1 invalid, 2 trimmed) and
/// "element" (its index in c.elements), for ParaView.
/// @throws towgeom::Error (WriteFailed) if @p out fails.
TOWGEOM_EXPORT void writeKnotSpansVtk(const KnotSpanClassification& c, const TowSurface& tow, std::ostream& out);

/// @}

TOWGEOM_END_NAMESPACE
