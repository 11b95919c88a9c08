/// @file weave.hpp
/// @brief The weave generator: textiles with known geometry and controllable interpenetration.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/cross_section.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/yarn_path.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// The weave patterns of generateWeave().
enum class WeaveKind {
    Plain,      ///< warp i over weft j when i + j is even
    Twill,      ///< n/m twill: warp i over weft j when (j - step * i) mod (n + m) < n
    Satin,      ///< n-harness satin: warp i over weft j only when j = step * i (mod n)
    Basket,     ///< plain weave of groups of n yarns: over when (i / n + j / n) is even
    Orthogonal  ///< 3D orthogonal: straight warp layers, straight weft layers between them, and
                ///< binder warps that run over the top and under the bottom on a 2/2 twill path
};

/// "plain", "twill", "satin", "basket" or "orthogonal".
TOWGEOM_EXPORT const char* weaveKindName(WeaveKind kind) noexcept;

/// What a generated yarn is in its textile.
enum class YarnRole {
    Warp,   ///< runs along x
    Weft,   ///< runs along y
    Binder  ///< a through-thickness warp (3D weaves), runs along x
};

/// "warp", "weft" or "binder".
TOWGEOM_EXPORT const char* yarnRoleName(YarnRole role) noexcept;

/// Parameters of generateWeave(). Lengths are in the user's units.
struct TOWGEOM_EXPORT WeaveOptions {
    WeaveKind kind = WeaveKind::Plain;  ///< the pattern
    std::size_t warps = 4;              ///< number of warps (along x), at y = i * spacing
    std::size_t wefts = 4;              ///< number of wefts (along y), at x = j * spacing
    int floatOver = 2;                  ///< twill n (warp over n wefts); satin harness n; basket group n
    int floatUnder = 2;                 ///< twill m (warp under m wefts)
    int step = 1;                       ///< twill/satin step between neighbouring warps
    std::size_t layers = 2;             ///< orthogonal: number of warp layers (wefts: layers + 1)
    double spacing = 1.0;               ///< distance between neighbouring yarns' centre lines
    double width = 0.8;                 ///< yarn width
    double height = 0.2;                ///< yarn height (thickness)
    /// Half the vertical distance between the centre lines of a warp and a weft at their
    /// crossing. 0 (default) means height / 2 * (1 - overlap): just touching without overlap.
    double crimp = 0.0;
    /// Interpenetration at every crossing as a fraction of the yarn height (0: none).
    double overlap = 0.0;
    SectionShape shape = SectionShape::Lenticular;  ///< section shape of every yarn
    std::size_t sectionsPerYarn = 0;    ///< sections along each yarn (0: 16 per spacing + 1)
    std::size_t pointsPerSection = 32;  ///< points around each section
    /// Yarns run one spacing beyond the outermost crossings on both sides, so every crossing of
    /// the repeat is complete.
    double margin() const { return spacing; }

    /// Throws towgeom::Error (InvalidArgument) naming the first invalid parameter.
    void validate() const;
};

/// A crossing of a warp (or binder) over or under a weft.
struct Crossing {
    std::size_t warp = 0;   ///< index in Textile::yarns of the warp or binder
    std::size_t weft = 0;   ///< index in Textile::yarns of the weft
    Point3 position;        ///< where their centre lines cross in plan (z halfway between them)
    bool warpOver = false;  ///< true when the warp is above the weft here
};

/// One generated yarn: its centre line and its sections along it. Every section has its own
/// CrossSection, so shape, size and flattening may vary along the yarn.
struct TOWGEOM_EXPORT GeneratedYarn {
    std::string name;                    ///< e.g. "warp_0", "weft_3", "binder_1"
    YarnRole role = YarnRole::Warp;      ///< warp, weft or binder
    YarnPath path;                       ///< the centre line
    std::vector<double> stations;        ///< path parameters of the sections, increasing
    std::vector<CrossSection> sections;  ///< one per station

    /// The yarn as a stack: section k is sections[k].sample(points) placed in the frame of the
    /// path at stations[k] (see generateWeave() for the frame).
    /// @throws towgeom::Error (InvalidArgument) if stations and sections differ in number.
    TowStack stack(std::size_t points) const;
    /// The index of the section whose centre is nearest to @p p in plan (x, y).
    std::size_t nearestSection(const Point3& p) const;
};

/// A generated textile: yarns, their crossings, and the options that made it.
struct TOWGEOM_EXPORT Textile {
    WeaveOptions options;              ///< the parameters used
    std::vector<GeneratedYarn> yarns;  ///< warps first, then wefts, then binders
    std::vector<Crossing> crossings;   ///< every warp/binder-weft crossing in plan

    /// Every yarn as a stack with options.pointsPerSection points per section.
    std::vector<TowStack> stacks() const;

    /// The weave's unit cell, periodic (Cell::periodic): one repeat of the pattern along x and y
    /// (plain 2 x 2 yarns; n/m twill n + m wefts by (n + m) / gcd(step, n + m) warps; n-harness
    /// satin n by n; basket 2n by 2n), its faces halfway between yarns from x = y = spacing / 2,
    /// and in z the yarns' sampled extent plus a quarter of their height on each side. A yarn's path between two
    /// interlacements depends on the two beyond them only (Catmull-Rom), so the textile repeats
    /// there exactly when there are at least a repeat + 2 wefts and warps; with fewer (or for
    /// the orthogonal weave) there is no such cell and the result is empty.
    std::optional<Cell> unitCell() const;
};

/// Generates a textile. Warps run along +x at y = i * spacing, wefts along +y at
/// x = j * spacing, each through its interlacement points (z = +-crimp) as a Catmull-Rom path
/// (binders of the orthogonal weave: a cardinal path with tension 0.5, which does not overshoot
/// where it turns into the thickness).
///
/// Sections sit in the frame t = r'/|r'|, n = (t x j)/|t x j|, b = n x t with the reference
/// vector j = +z: x of the section along n (horizontal, across the yarn), y along b (up). Where
/// t is within 1e-3 rad of j (vertical binder segments) the frame is carried from the previous
/// section by rotation-minimising transport instead, and n keeps the previous section's side
/// where a path turns back through the vertical (so no section starts half way round).
/// @throws towgeom::Error (InvalidArgument) for invalid options.
TOWGEOM_EXPORT Textile generateWeave(const WeaveOptions& options);

TOWGEOM_END_NAMESPACE
