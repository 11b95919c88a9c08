#include "volume/volume_conformity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/parallel.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Face = std::array<std::size_t, 3>;

Face sorted(Face f)
{
    std::sort(f.begin(), f.end());
    return f;
}

/// The tetrahedra's faces, each as its smallest node and the other two packed in 64 bits,
/// bucketed by the smallest node (counting sort) and sorted within each bucket: a face's
/// tetrahedra are a run of equal entries.
class FaceTable {
public:
    FaceTable(const VolumeMesh& mesh, std::size_t threads) : first_(mesh.nodes.size() + 1, 0)
    {
        if (mesh.nodes.size() >= (std::uint64_t(1) << 32))
            throw Error(ErrorCode::Unsupported, "the volume mesh has too many nodes (" + std::to_string(mesh.nodes.size()) + ") to check");
        const auto eachFace = [&](auto&& take) {
            for (const auto& t : mesh.tetrahedra)
                for (int skip = 0; skip < 4; ++skip) {
                    Face f{};
                    for (int k = 0, i = 0; k < 4; ++k)
                        if (k != skip) f[static_cast<std::size_t>(i++)] = t[static_cast<std::size_t>(k)];
                    take(sorted(f));
                }
        };
        eachFace([&](const Face& f) { ++first_[f[0] + 1]; });
        for (std::size_t n = 1; n < first_.size(); ++n) first_[n] += first_[n - 1];
        rest_.resize(first_.back());
        std::vector<std::size_t> fill(first_.begin(), first_.end() - 1);
        eachFace([&](const Face& f) { rest_[fill[f[0]]++] = pack(f); });
        forEachBucket(threads, [&](std::size_t n) { std::sort(rest_.begin() + first_[n], rest_.begin() + first_[n + 1]); });
    }
    /// Calls @p body(n) for every smallest node n, in chunks on @p threads threads.
    template <class Body>
    void forEachBucket(std::size_t threads, Body&& body) const
    {
        const std::size_t buckets = first_.size() - 1, chunk = 4096;
        parallelFor((buckets + chunk - 1) / chunk, threads, [&](std::size_t c) {
            for (std::size_t n = c * chunk; n < std::min(buckets, (c + 1) * chunk); ++n) body(n);
        });
    }
    /// Calls @p visit(face, how many tetrahedra have it) for every distinct face, on @p threads
    /// threads (the first exception thrown is rethrown).
    template <class Visit>
    void forEach(std::size_t threads, Visit&& visit) const
    {
        forEachBucket(threads, [&](std::size_t n) {
            for (std::size_t i = first_[n]; i < first_[n + 1];) {
                std::size_t j = i + 1;
                while (j < first_[n + 1] && rest_[j] == rest_[i]) ++j;
                visit(Face{n, static_cast<std::size_t>(rest_[i] >> 32), static_cast<std::size_t>(rest_[i] & 0xffffffffu)}, j - i);
                i = j;
            }
        });
    }
    /// How many tetrahedra have face @p f (sorted).
    std::size_t count(const Face& f) const
    {
        if (f[0] + 1 >= first_.size()) return 0;
        const auto begin = rest_.begin() + first_[f[0]], end = rest_.begin() + first_[f[0] + 1];
        const auto [lo, hi] = std::equal_range(begin, end, pack(f));
        return static_cast<std::size_t>(hi - lo);
    }

private:
    static std::uint64_t pack(const Face& f) { return (std::uint64_t(f[1]) << 32) | std::uint64_t(f[2]); }
    std::vector<std::size_t> first_;  ///< per smallest node: where its faces start in rest_
    std::vector<std::uint64_t> rest_;
};

[[noreturn]] void refuse(const VolumeMesh& mesh, const Face& f, const std::string& what)
{
    const Point3 &a = mesh.nodes[f[0]], &b = mesh.nodes[f[1]], &c = mesh.nodes[f[2]];
    std::ostringstream text;
    text.precision(6);
    text << "the volume mesh does not conform: " << what << " at (" << (a.x + b.x + c.x) / 3.0 << ", " << (a.y + b.y + c.y) / 3.0
         << ", " << (a.z + b.z + c.z) / 3.0 << ")";
    throw Error(ErrorCode::Internal, text.str());
}

}  // namespace

void checkConformity(const VolumeMesh& mesh, const ConformityTarget& target, std::size_t threads)
{
    const FaceTable faces(mesh, threads);
    // Each surface triangle: one tetrahedron per side it bounds.
    std::vector<Face> surface;
    surface.reserve(target.outer.size() + target.between.size());
    for (const auto* list : {&target.outer, &target.between})
        for (const Face& t : *list) {
            const Face f = sorted(t);
            const std::size_t want = list == &target.outer ? 1 : 2, have = faces.count(f);
            if (have != want)
                refuse(mesh, f,
                       "a surface triangle " + std::string(want == 1 ? "on the outside" : "between two volumes") + " is a face of " +
                           std::to_string(have) + " tetrahedra, not " + std::to_string(want));
            surface.push_back(f);
        }
    std::sort(surface.begin(), surface.end());
    // Every other face: inner, so of exactly two tetrahedra.
    faces.forEach(threads, [&](const Face& f, std::size_t n) {
        if (n > 2) refuse(mesh, f, "a face is shared by " + std::to_string(n) + " tetrahedra");
        if (n == 1 && !std::binary_search(surface.begin(), surface.end(), f))
            refuse(mesh, f, "an inner face belongs to one tetrahedron only (a crack)");
    });
    // The volumes.
    std::vector<double> filled(target.volume.size(), 0.0);
    for (std::size_t k = 0; k < mesh.tetrahedra.size(); ++k)
        if (mesh.tow[k] < filled.size()) filled[mesh.tow[k]] += mesh.tetrahedronVolume(k);
    double largest = 0.0;
    for (double v : target.volume) largest = std::max(largest, std::abs(v));
    for (std::size_t t = 0; t < filled.size(); ++t)
        if (!(std::abs(filled[t] - target.volume[t]) <= 1e-9 * largest)) {
            std::ostringstream text;
            text.precision(12);
            text << "the volume mesh does not fill " << (t < target.name.size() ? target.name[t] : "a volume") << ": its tetrahedra add up to "
                 << filled[t] << ", its surface encloses " << target.volume[t];
            throw Error(ErrorCode::Internal, text.str());
        }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
