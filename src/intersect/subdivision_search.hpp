// Loop detection that cannot miss a loop (issue 38): every pair of Bezier patches of two tows
// whose control hulls meet is halved until the hulls separate, or until the normal cones prove
// the patches' intersection holds no closed loop (Sinha, Klassen and Wang 1985; the loop test of
// Sederberg and Meyers 1988) and they are small enough to seed, or until they are smaller than a
// loop worth finding. Each such leaf is offered as a start guess; the caller walks from it (or
// finds a curve already walked there) and says whether it settled the leaf. A leaf that does not
// settle is halved further while it may.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "intersect/bezier_patches.hpp"
#include "intersect/seed_search.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// When the subdivision stops.
struct SubdivisionLimits {
    double overlap = 0.0;      ///< control hulls overlapping less than this are apart (the point tolerance)
    double seedSize = 0.0;     ///< patches with apart normal cones are offered once both are this small
    double smallest = 0.0;     ///< patches this small are offered whatever their cones
    std::size_t budget = 0;    ///< patch pairs examined at most
};

/// A leaf offered as a start guess: the guess, and the two patches' parts of the tows' (u, v).
struct Leaf {
    Seed seed;  ///< guess.point between the closest control points; facetSize the smaller patch's size
    double ua0 = 0.0, ua1 = 0.0, va0 = 0.0, va1 = 0.0;  ///< patch of tow A
    double ub0 = 0.0, ub1 = 0.0, vb0 = 0.0, vb1 = 0.0;  ///< patch of tow B
};

/// What the subdivision did.
struct SubdivisionStats {
    std::size_t examined = 0;   ///< patch pairs tested
    std::size_t offered = 0;    ///< leaves offered as start guesses
    std::size_t unsettled = 0;  ///< smallest leaves whose hulls meet but that no curve passes
    bool exhausted = false;     ///< the budget ran out: the search is incomplete
};

/// Offers start guesses for every intersection branch of the tubes @p a and @p b within the
/// broad phase's u-windows @p windows (outside them they cannot meet).
/// @p settle takes a leaf and returns true when a curve passes through it (both patches).
SubdivisionStats searchPatchPairs(const Handle(Geom_BSplineSurface)& a, const Handle(Geom_BSplineSurface)& b,
                                  const std::vector<WindowPair>& windows, const SubdivisionLimits& limits,
                                  const std::function<bool(const Leaf&)>& settle);

}  // namespace detail
TOWGEOM_END_NAMESPACE
