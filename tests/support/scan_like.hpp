// A family of scan-like textiles (issue 38): generated weaves pressed until neighbours overlap,
// each section voxelised as a micro-CT scan sees it and contoured back, starts drifting, tows
// cut by the scan's box. Built to be harder than real data, and independent of the code under
// test: only the weave generator and the stack type are towgeom's.
#pragma once

#include <towgeom/tow_stack.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace towgeom::testing {

/// The random choices behind one scan-like textile.
struct ScanLikeChoices {
    std::string weave;         ///< plain, twill or orthogonal
    std::string section;       ///< racetrack, lenticular or ellipse
    std::size_t yarns = 0;     ///< warps (= wefts)
    double height = 0.0;       ///< yarn thickness (spacing 1)
    double width = 0.0;        ///< yarn width
    double overlap = 0.0;      ///< interpenetration at crossings, a fraction of the thickness
    double pixel = 0.0;        ///< voxel size, a fraction of the thickness (1/12 to 1/6)
    double noise = 0.0;        ///< grey-value noise (a fraction of the contrast)
    std::size_t sections = 0;  ///< sections per yarn before the cut
    std::size_t points = 0;    ///< points per contoured section

    /// One line naming every choice (for a failing test's message).
    std::string describe() const;
};

/// A scan-like textile and how it was made.
struct ScanLikeTextile {
    std::vector<TowStack> stacks;
    ScanLikeChoices choices;
};

/// The scan-like textile of @p seed: a plain, twill or 3D orthogonal weave (2 or 3 yarns each
/// way; 2 warp layers and binders for orthogonal) of random section shape and size, its
/// crossings overlapping 5-30 % of the thickness; every section rasterised at a pixel of 1/12 to
/// 1/6 of the thickness as partial-volume grey values with noise, contoured back by marching
/// squares, resampled to N points uniform in arc length from a start that drifts from section to
/// section; then cut by a box whose faces fall at random inside the textile, so that tows end
/// inside others and a binder leaving the box and coming back becomes two tows.
ScanLikeTextile scanLikeTextile(unsigned seed);

/// The size of a large scan-like textile: a real scan's (57 tows of ~30 sections x 32 points).
struct ScanLikeSize {
    std::size_t yarns = 9;      ///< warps per layer (= wefts per layer)
    std::size_t layers = 2;     ///< warp layers (one more weft layer)
    std::size_t sections = 30;  ///< sections per yarn before the cut
    std::size_t points = 32;    ///< points per contoured section
    /// Yarn width (spacing 1). The binders get half the gap between warps: at the family's
    /// widest (0.9) they would be 18 x thinner than the warps, and meshed at a size relative to
    /// their own, ~8 M triangles (a real scan's binders are a fraction of the warps' size).
    double width = 0.7;
};

/// A 3D orthogonal scan-like textile of @p size, made as scanLikeTextile() makes one (section
/// shape, thickness, overlap, pixel, noise and box drawn from @p seed; the width is size.width):
/// with the defaults 53 yarns, binders split by the box into more tows.
ScanLikeTextile largeScanLikeTextile(unsigned seed, const ScanLikeSize& size = {});

/// binder_2_p1 of largeScanLikeTextile(1), the one tow of it whose fitted surface folds: sections
/// 0.4 and 0.8 apart after a right-angle bend, 0.085 thick; the cubic through them dips 0.1 below
/// the last sections' centres and crosses itself (tests/test_surface_fold.cpp checks the place
/// against CGAL on a dense tessellation).
TowStack foldingBinder();

/// @p polygon (a closed planar section, not repeated at its end) as a scan gives it back: its
/// plane rasterised with pixel @p pixel (at most a sixth of its smaller extent; grey = covered fraction, ramp of one pixel, plus normal
/// noise of @p noise), contoured at 1/2 by marching squares, resampled to @p points points uniform
/// in arc length, the first at arc length @p startShift x (perimeter / points) past the contour
/// point nearest polygon[0], in the polygon's direction around. @p rng is any 32-bit seed.
std::vector<Point3> rescannedSection(const std::vector<Point3>& polygon, double pixel, double noise, std::size_t points,
                                     double startShift, unsigned rng);

}  // namespace towgeom::testing
