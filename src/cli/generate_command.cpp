// towgeom generate: weaves with known geometry, optional overlap, flattening to "just touching".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kGenerateHelp = R"(Usage: towgeom generate --weave KIND --out DIR [options]

Generates a textile with known geometry: warps along x at y = i * spacing, wefts along y at
x = j * spacing, each a Catmull-Rom path through its interlacement points (z = +-crimp), with
sections in the path's frame. Writes DIR/NAME.stw per yarn and DIR/textile.json (yarn names,
roles warp/weft/binder, the weave's parameters, every crossing), then prints a JSON summary
with the collisions found between the faceted yarns: per yarn pair, and per crossing
(each colliding triangle pair counts at the nearest crossing of its two yarns).

Weave:
  --weave KIND     plain | twill | satin | basket | orthogonal (3D: straight warp layers,
                   weft layers between them, binder warps on a 2/2 twill path)
  --repeat R       twill: N/M (warp over N, under M; default 2/2); satin: harness N (default 5);
                   basket: group size N (default 2)
  --step S         twill step (default 1), satin step (default 2; coprime with N)
  --tows WxF       number of warps and wefts (default: one repeat, at least 2x2)
  --layers L       orthogonal: warp layers (default 2)
Geometry (in your units):
  --spacing S      distance between neighbouring yarns (default 1)
  --width W        yarn width (default 0.8)
  --height H       yarn height (default 0.2)
  --crimp C        half the vertical distance of warp and weft centre lines at a crossing
                   (default H/2 * (1 - overlap): just touching)
  --overlap F      interpenetration at every crossing, a fraction of H (default 0)
  --section SHAPE  lenticular (default) | ellipse | racetrack | circle | hermite
  --sections M     sections per yarn (default 16 per spacing)
  --points N       points per section (default 32; even for lenticular and hermite)
Collision response:
  --flatten TAU    flatten colliding yarns at each crossing (Smith & Chen 2008) until they
                   just touch: no colliding triangles, gap at most TAU
Output:
  --out DIR        where to write (created if needed; nothing is written on error)
  --faceted LIST   also write the faceted yarns (ends closed): vtk (DIR/NAME.faceted.vtk,
                   for ParaView), stl (DIR/NAME.faceted.stl, binary), or vtk,stl
  --quiet          no progress lines on stderr
  -h, --help       this help

Exit status: 0 success; 2 invalid options; 1 output could not be written.

Example (the bundled example textile, examples/data/twill):
  towgeom generate --weave twill --repeat 2/2 --tows 4x4 --overlap 0.08 --sections 61 --points 24 --out twill
)";

std::pair<std::size_t, std::size_t> parsePair(const std::string& text, char sep, const char* what)
{
    const auto at = text.find(sep);
    try {
        std::size_t used = 0;
        const long a = std::stol(text.substr(0, at), &used);
        if (at == std::string::npos) {
            if (used != text.size() || a < 1) throw std::invalid_argument("x");
            return {static_cast<std::size_t>(a), 0};
        }
        if (used != at) throw std::invalid_argument("x");
        const std::string rest = text.substr(at + 1);
        const long b = std::stol(rest, &used);
        if (used != rest.size() || a < 1 || b < 1 || a > 100000 || b > 100000) throw std::invalid_argument("x");
        return {static_cast<std::size_t>(a), static_cast<std::size_t>(b)};
    } catch (const std::logic_error&) {
        throw UsageError(std::string("invalid ") + what + " '" + text + "'");
    }
}

WeaveKind parseWeave(const std::optional<std::string>& text)
{
    if (!text) throw UsageError("--weave is required (plain, twill, satin, basket or orthogonal)");
    for (const WeaveKind k : {WeaveKind::Plain, WeaveKind::Twill, WeaveKind::Satin, WeaveKind::Basket, WeaveKind::Orthogonal})
        if (*text == weaveKindName(k)) return k;
    throw UsageError("unknown weave '" + *text + "'");
}

SectionShape parseShape(const std::string& text)
{
    for (const SectionShape s : {SectionShape::Lenticular, SectionShape::Ellipse, SectionShape::Racetrack,
                                 SectionShape::Circle, SectionShape::Hermite})
        if (text == sectionShapeName(s)) return s;
    throw UsageError("unknown section shape '" + text + "'");
}

std::size_t count(const Args& args, const char* name, std::size_t fallback)
{
    const auto x = args.number(name);
    if (!x) return fallback;
    if (*x < 1 || *x != std::floor(*x) || *x > 1e7) throw UsageError(std::string("--") + name + " needs a positive integer");
    return static_cast<std::size_t>(*x);
}

WeaveOptions parseOptions(const Args& args)
{
    WeaveOptions o;
    o.kind = parseWeave(args.value("weave"));
    std::size_t repeat = 2;
    if (o.kind == WeaveKind::Twill) {
        const auto [n, m] = parsePair(args.value("repeat").value_or("2/2"), '/', "--repeat (twill N/M)");
        if (m == 0) throw UsageError("a twill --repeat needs N/M, e.g. 2/1");
        o.floatOver = static_cast<int>(n);
        o.floatUnder = static_cast<int>(m);
        repeat = n + m;
    } else if (o.kind == WeaveKind::Satin || o.kind == WeaveKind::Basket) {
        const std::size_t n =
            parsePair(args.value("repeat").value_or(o.kind == WeaveKind::Satin ? "5" : "2"), '/', "--repeat").first;
        o.floatOver = static_cast<int>(n);
        if (o.kind == WeaveKind::Satin) o.step = 2;
        repeat = o.kind == WeaveKind::Satin ? n : 2 * n;
    } else if (args.has("repeat")) {
        throw UsageError(std::string("--repeat does not apply to ") + weaveKindName(o.kind) + " weaves");
    }
    o.step = static_cast<int>(count(args, "step", static_cast<std::size_t>(o.step)));
    const std::size_t tows = std::max<std::size_t>(repeat, 2);
    const auto [warps, wefts] = parsePair(args.value("tows").value_or(std::to_string(tows) + "x" + std::to_string(tows)),
                                          'x', "--tows (WARPSxWEFTS)");
    if (wefts == 0) throw UsageError("--tows needs WARPSxWEFTS, e.g. 4x4");
    o.warps = warps;
    o.wefts = wefts;
    o.layers = count(args, "layers", o.layers);
    o.spacing = args.number("spacing").value_or(o.spacing);
    o.width = args.number("width").value_or(o.width);
    o.height = args.number("height").value_or(o.height);
    o.crimp = args.number("crimp").value_or(0.0);
    o.overlap = args.number("overlap").value_or(0.0);
    if (const auto s = args.value("section")) o.shape = parseShape(*s);
    o.sectionsPerYarn = count(args, "sections", 0);
    o.pointsPerSection = count(args, "points", o.pointsPerSection);
    return o;
}

TextileOutput parseFaceted(const std::optional<std::string>& text)
{
    TextileOutput out;
    if (!text) return out;
    std::size_t start = 0;
    while (start <= text->size()) {
        const std::size_t comma = std::min(text->find(',', start), text->size());
        const std::string format = text->substr(start, comma - start);
        if (format == "vtk")
            out.facetedVtk = true;
        else if (format == "stl")
            out.facetedStl = true;
        else
            throw UsageError("--faceted takes vtk, stl or vtk,stl, not '" + *text + "'");
        start = comma + 1;
    }
    return out;
}

Json collisionsJson(const Textile& textile, const std::vector<TowStack>& stacks, const CollisionReport& report)
{
    const std::vector<std::size_t> perCrossing = collisionsPerCrossing(textile, stacks, report);
    Json j;
    j["yarn_pairs"] = report.collisions.size();
    j["triangle_pairs"] = report.trianglePairCount();
    j["crossings"] = static_cast<std::size_t>(std::count_if(perCrossing.begin(), perCrossing.end(), [](std::size_t n) { return n > 0; }));
    Json crossings = Json::array();
    for (std::size_t c = 0; c < perCrossing.size(); ++c) {
        if (perCrossing[c] == 0) continue;
        const Crossing& x = textile.crossings[c];
        crossings.push_back({{"warp", textile.yarns[x.warp].name},
                             {"weft", textile.yarns[x.weft].name},
                             {"x", x.position.x},
                             {"y", x.position.y},
                             {"triangle_pairs", perCrossing[c]}});
    }
    j["per_crossing"] = std::move(crossings);
    Json pairs = Json::array();
    for (const YarnCollision& c : report.collisions)
        pairs.push_back({{"a", textile.yarns[c.yarnA].name}, {"b", textile.yarns[c.yarnB].name}, {"triangle_pairs", c.triangles.size()}});
    j["pairs"] = std::move(pairs);
    return j;
}

}  // namespace

int runGenerate(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"},        {"quiet"},        {"faceted", true}, {"weave", true},   {"repeat", true},
                         {"step", true},  {"tows", true},   {"layers", true}, {"spacing", true}, {"width", true},
                         {"height", true}, {"crimp", true}, {"overlap", true}, {"section", true}, {"sections", true},
                         {"points", true}, {"flatten", true}, {"out", true}});
        if (args.has("help")) {
            std::cout << kGenerateHelp;
            return kExitOk;
        }
        if (!args.positional().empty()) throw UsageError("unexpected argument '" + args.positional().front() + "'");
        const auto out = args.value("out");
        if (!out) throw UsageError("--out DIR is required");
        const WeaveOptions options = parseOptions(args);
        const auto tau = args.number("flatten");
        if (tau && !(*tau > 0.0)) throw UsageError("--flatten needs a positive tolerance");
        const bool quiet = args.has("quiet");
        const TextileOutput faceted = parseFaceted(args.value("faceted"));

        const auto start = std::chrono::steady_clock::now();
        Textile textile = generateWeave(options);
        const std::vector<TowStack> stacksBefore = textile.stacks();
        const CollisionReport before = detectCollisions(stacksBefore);
        if (!quiet)
            std::cerr << "towgeom generate: " << textile.yarns.size() << " yarns, " << textile.crossings.size()
                      << " crossings, " << before.collisions.size() << " colliding yarn pairs\n";
        std::vector<CrossingResponse> responses;
        CollisionReport after = before;
        std::vector<TowStack> stacksAfter = stacksBefore;
        if (tau) {
            responses = flattenToTouching(textile, *tau);
            stacksAfter = textile.stacks();
            after = detectCollisions(stacksAfter);
            if (!quiet) std::cerr << "towgeom generate: flattened; " << after.collisions.size() << " colliding yarn pairs left\n";
        }
        writeTextile(textile, *out, faceted);

        Json j;
        j["weave"] = weaveKindName(options.kind);
        Json yarns = Json::array();
        for (const GeneratedYarn& y : textile.yarns) yarns.push_back(y.name);
        j["yarns"] = std::move(yarns);
        j["crossings"] = textile.crossings.size();
        j["collisions"] = collisionsJson(textile, stacksAfter, after);
        if (tau) {
            j["collisions_before_flattening"] = collisionsJson(textile, stacksBefore, before);
            double maxGap = 0.0;
            std::size_t flattened = 0;
            for (const CrossingResponse& r : responses) {
                maxGap = std::max(maxGap, r.gap);
                flattened += r.collided;
            }
            j["flattened_crossings"] = flattened;
            j["max_gap"] = maxGap;
        }
        j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << jsonText(j) << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return reportError("generate", e);
    }
}

}  // namespace towgeom::cli
