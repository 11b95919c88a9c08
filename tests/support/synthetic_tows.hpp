// Tows with known geometry for tests and benchmarks: analytic tubes sampled as stacks.
#pragma once

#include <towgeom/cell.hpp>
#include <towgeom/tow_stack.hpp>
#include <towgeom/tow_surface.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace towgeom::testing {

/// How a synthetic tube is sampled.
struct Sampling {
    std::size_t sections = 21;      ///< M
    std::size_t points = 24;        ///< N
    double startAngle = 0.0;        ///< angle of the first point of every section (radians)
    bool counterClockwise = true;   ///< direction around the +axis (right-hand rule)
    bool repeatClosingPoint = false;  ///< append the first point again at the end of each section
};

/// A straight elliptical tube along +x from x = 0 to x = length, semi-axes a (along y) and b
/// (along z). Exact volume: pi a b length.
TowStack ellipticalTube(double a, double b, double length, const Sampling& s = {}, const std::string& name = "tube");

/// A circular tube of radius r bent around the z axis: centre-line radius R, from angle 0 to
/// sweep (radians). Exact volume (Pappus): pi r^2 R sweep.
TowStack bentTube(double r, double bendRadius, double sweep, const Sampling& s = {}, const std::string& name = "bent");

/// A circular tube bent around the z axis (centre-line radius R, from angle 0 to sweep) whose
/// radius grows linearly from r0 to r1. Exact volume: pi R sweep (r0^2 + r0 r1 + r1^2) / 3.
TowStack growingBentTube(double r0, double r1, double bendRadius, double sweep, const Sampling& s = {},
                         const std::string& name = "growing");

/// A crimped elliptical tow along x with centre line z = amplitude cos(2 pi x / wavelength),
/// sections normal to the centre line (a woven-like tow; no closed-form volume).
TowStack crimpedTow(double a, double b, double length, double amplitude, double wavelength, const Sampling& s = {},
                    const std::string& name = "crimped");

/// A round tube of radius r along +x from x = dx to x = dx + length, its axis at (y = dy,
/// z = dz); the first point of each section at startAngle from +y towards +z.
TowStack tubeAlongX(double r, double length, double dx, double dy, double dz, const Sampling& s = {},
                    const std::string& name = "x");

/// A round tube of radius r along +y from y = -2 to y = 2, its axis at (x = 2, z = d): with
/// tubeAlongX(R, 4, 0, 0, 0) it makes a crossing whose loop is known in closed form.
TowStack tubeAlongY(double r, double d, const Sampling& s = {}, const std::string& name = "y");

/// tubeAlongY(r, d) with a dent in its underside at y = 0: points below the axis are lifted by
/// dent * exp(-x'^2 / widthX^2 - y^2 / width^2) * sin^2(angle) (x' the offset from the axis;
/// widthX = width unless given, infinite for a groove across the whole underside). Over
/// tubeAlongX(R, 4, 0, 0, 0) with d - r < R < d - r + dent the overlap is a ring: an outer loop
/// and an island loop inside it where the surfaces separate again. A groove with
/// dent = R - (d - r) touches the x-tube's top at (2, 0, R), tangent there: a saddle, where
/// the intersection curve crosses itself (a figure-8).
TowStack dentedTubeAlongY(double r, double d, double dent, double width, const Sampling& s = {},
                          const std::string& name = "dented", double widthX = 0.0);

/// Two elliptical tubes "a" and "b" (semi-axes @p width along y and @p height along z, 51
/// sections x 32 points over a length of 10): a along x from x = -3 on the x axis; b the same
/// turned by @p degrees about the vertical through (2, 0), then moved by @p side along y and
/// @p lift along z. Where their sections overlap they interpenetrate along their length.
std::vector<TowStack> tubesCrossingAt(double degrees, double width, double height, double lift, double side = 0.0);
/// "x" (r 0.5 along x from 0 to 4) and "y" (r 0.4 along y) crossing at x = 2, and "w" (r 0.3)
/// running diagonally between them, its axis at height @p height, offset @p offset sideways from
/// the crossing: each pair overlaps in one closed loop and the three loops cross where the three
/// surfaces meet (triple points). 41 sections x 48 points; @p startAngle of w's first points.
std::vector<TowStack> threeTowsAtAPoint(double offset, double height, double startAngle = 0.0);
/// "outer" (r 0.5 along x from 0 to 4) and "thin" (r 0.1 along y at x = 2, z = 0) right through
/// it, or, @p endsInside, ending at y = 0 on outer's axis (@p startsInside: starting there).
/// 41 sections x 32 points.
std::vector<TowStack> thinThrough(bool endsInside, bool startsInside = false);
/// Writes @p stacks as NAME.stw into a fresh @p dir (removed first): their quoted paths, each
/// after a space, for a command line.
std::string writeStacks(const std::filesystem::path& dir, const std::vector<TowStack>& stacks);
/// Fitted tubes "x" (r 0.5, along x from 0 to 4) and "y" (r 0.4, along y) crossing, 48 points
/// per section; with @p far also "far" (r 0.3, along x at y = 3).
std::vector<TowSurface> crossingTubes(bool far);
/// The cell for tubesCrossingAt(): [-1, 2] x [-4, 4] x [-1, 1.7], its face x = 2 through the
/// turning point, so it cuts across the tubes' overlap.
Cell crossingAtCell();

/// A point of a racetrack of width w and height h (semicircular ends of radius h/2), centred at
/// the origin, at arc length s from (w/2, 0) counter-clockwise; s is taken modulo the perimeter.
Point2 racetrackPoint(double w, double h, double s);

/// A flat racetrack tow as traced by hand on micro-CT slices (see tracedRacetrack()).
struct TracedTow {
    TowStack stack;
    double spacing = 0.0;  ///< mean point spacing around (perimeter / N)
    double volume = 0.0;   ///< of the unquantised tow, closed form per section (trapezoid rule along)
};

/// A flat racetrack tow (width about 1, height 0.25) as traced by hand on micro-CT slices: M
/// sections in the planes x = 2 i g (g = 1/50 of the width, the pixel), N points each, uniform
/// in arc length, the first point of section i at arc length offset[i] point spacings from the
/// tip at +y; the section wanders sideways and up and down and its width varies along the tow;
/// y and z are rounded to the pixel grid. Goes counter-clockwise about +x unless @p clockwise.
TracedTow tracedRacetrack(std::size_t m, std::size_t n, const std::vector<double>& offset, bool clockwise);

/// Every stack fitted (TowSurface::fit, default options), in order.
std::vector<TowSurface> fitAll(const std::vector<TowStack>& stacks);

/// A pressed 3D orthogonal weave (towgeom generate --weave orthogonal --tows NxN --layers L
/// --section racetrack --width 0.9 --sections 30 --points 32 --overlap O): racetrack sections
/// pressed @p overlap into each other (0: flat faces touching with no gap), binders between.
std::vector<TowStack> pressedOrthogonal(std::size_t tows, std::size_t layers, double overlap);

/// The generator's 4x4 2/2 twill (overlap 0.08, default sampling), fitted: 8 tows, 16 loops.
std::vector<TowSurface> fittedTwill22();

/// The generator's 6x6 2/2 twill (overlap 0.08, default sampling), fitted: 12 tows.
std::vector<TowSurface> fittedTwill22SixBySix();
/// Its 4x4 repeat as a periodic cell, faces halfway between yarns ([0.5, 4.5]^2 x [-0.5, 0.5]):
/// the outermost yarns lie wholly outside, the other 8 are cut by two opposite faces each; 16
/// crossings inside.
Cell twill22RepeatCell();

/// The bundled 2/2 twill (@p exampleData/twill, the README's example): 8 tows, 16 interpenetrations.
std::vector<TowSurface> bundledTwill(const std::string& exampleData);

}  // namespace towgeom::testing
