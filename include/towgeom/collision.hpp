/// @file collision.hpp
/// @brief Collision detection between faceted yarns and the "just touching" collision response.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "towgeom/tow_stack.hpp"
#include "towgeom/weave.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// How detectCollisions() finds candidate triangle pairs.
enum class CollisionMethod {
    Hierarchy,  ///< boxes of yarns, then of triangles (CGAL box intersection), then exact tests
    BruteForce  ///< every triangle pair of every yarn pair, exact test (a reference)
};

/// The colliding triangle pairs of two yarns.
struct YarnCollision {
    std::size_t yarnA = 0;  ///< index of the first yarn (yarnA < yarnB)
    std::size_t yarnB = 0;  ///< index of the second yarn
    /// (triangle of A, triangle of B), sorted; triangle k of a yarn is the k-th triangle of
    /// facetedTube(stack, false).
    std::vector<std::pair<std::size_t, std::size_t>> triangles;
};

/// Everything detectCollisions() found.
struct TOWGEOM_EXPORT CollisionReport {
    std::vector<YarnCollision> collisions;  ///< yarn pairs with at least one colliding triangle pair, sorted
    std::size_t yarnPairsTested = 0;        ///< yarn pairs that reached triangle tests
    std::size_t trianglePairsTested = 0;    ///< exact triangle-triangle tests performed
    /// Total number of colliding triangle pairs.
    std::size_t trianglePairCount() const;
};

/// Finds every pair of intersecting triangles between different yarns (exact predicates).
TOWGEOM_EXPORT CollisionReport detectCollisions(const std::vector<TowStack>& yarns, CollisionMethod method = CollisionMethod::Hierarchy);

/// The colliding triangle pairs of @p report attributed to the crossings of @p textile: for
/// each crossing, how many of its warp's and weft's colliding triangle pairs lie nearer (in
/// plan, by the warp triangle's centroid) to it than to any other crossing of the same two
/// yarns. @p stacks are the stacks the report was computed on (textile.stacks()).
TOWGEOM_EXPORT std::vector<std::size_t> collisionsPerCrossing(const Textile& textile, const std::vector<TowStack>& stacks,
                                               const CollisionReport& report);

/// What flattenToTouching() did at one crossing.
struct CrossingResponse {
    std::size_t crossing = 0;   ///< index in Textile::crossings
    bool collided = false;      ///< whether the yarns collided there before the response
    double flattening = 1.0;    ///< the factor applied at the crossing (1: untouched)
    /// After the response: how far the warp's faceted sections near the crossing must move
    /// vertically towards the weft's to touch them (to 1 % of the tolerance); 0 if they touch.
    double gap = 0.0;
};

/// The collision response of Smith & Chen (2008), sections 4.1-4.3: at every crossing where a
/// warp and a weft collide, flatten both yarns' sections near it (fully across the other yarn's
/// width, blending to 1 as cos^2 by half a spacing from the crossing), in steps of 1/16 of the height, until no triangles collide, then bisect the flattening interval
/// until the gap it can leave is below @p tolerance: the yarns end just touching, neither
/// interpenetrating nor floating (gap <= tolerance). Sets the flattening of every section of
/// the yarns involved (replacing what it was); a section in reach of two crossings takes the
/// stronger flattening, and passes over all crossings repeat (at most 4) until none changes.
/// @throws towgeom::Error (InvalidArgument) for a non-positive tolerance, (Internal) if no
///         flattening down to 1/16 separates a crossing (e.g. parallel yarns that overlap).
TOWGEOM_EXPORT std::vector<CrossingResponse> flattenToTouching(Textile& textile, double tolerance);

TOWGEOM_END_NAMESPACE
