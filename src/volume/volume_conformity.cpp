#include "volume/volume_conformity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

#include "core/parallel.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Face = std::array<std::size_t, 3>;

/// @p f's nodes ascending, and whether that order runs the same way round as @p f (an even
/// permutation of it).
std::pair<Face, bool> sorted(Face f)
{
    bool same = true;
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t k = 0; k + 1 < 3; ++k)
            if (f[k] > f[k + 1]) {
                std::swap(f[k], f[k + 1]);
                same = !same;
            }
    return {f, same};
}

/// The tetrahedra's faces as each sees them from inside, outward: the face's smallest node
/// (the bucket), its other two and whether the sorted order runs the same way round, packed in
/// 64 bits; bucketed by counting sort and sorted within each bucket, so that a face's
/// tetrahedra are a run of entries equal but for the lowest bit. A tetrahedron (a, b, c, d) of
/// positive volume sees its faces (b, c, d), (a, d, c), (a, b, d), (a, c, b) outward.
class FaceTable {
public:
    FaceTable(const VolumeMesh& mesh, std::size_t threads) : first_(mesh.nodes.size() + 1, 0)
    {
        if (mesh.nodes.size() >= (std::uint64_t(1) << 31))
            throw Error(ErrorCode::Unsupported, "the volume mesh has too many nodes (" + std::to_string(mesh.nodes.size()) + ") to check");
        const auto eachFace = [&](auto&& take) {
            for (const auto& t : mesh.tetrahedra)
                for (const Face& f : {Face{t[1], t[2], t[3]}, Face{t[0], t[3], t[2]}, Face{t[0], t[1], t[3]}, Face{t[0], t[2], t[1]}})
                    take(sorted(f));
        };
        eachFace([&](const std::pair<Face, bool>& f) { ++first_[f.first[0] + 1]; });
        for (std::size_t n = 1; n < first_.size(); ++n) first_[n] += first_[n - 1];
        rest_.resize(first_.back());
        std::vector<std::size_t> fill(first_.begin(), first_.end() - 1);
        eachFace([&](const std::pair<Face, bool>& f) { rest_[fill[f.first[0]]++] = pack(f.first, f.second); });
        parallelFor(chunks(), threads, [&](std::size_t c) {
            for (std::size_t n = c * kChunk; n < std::min(buckets(), (c + 1) * kChunk); ++n)
                std::sort(rest_.begin() + first_[n], rest_.begin() + first_[n + 1]);
        });
    }
    /// The first defect @p judge(face, how many tetrahedra see it the face's own way round, how
    /// many the other way) finds, by smallest node (the same whatever the threads did).
    template <class Judge>
    std::optional<std::pair<Face, std::string>> firstDefect(std::size_t threads, Judge&& judge) const
    {
        std::vector<std::optional<std::pair<Face, std::string>>> found(chunks());
        parallelFor(chunks(), threads, [&](std::size_t c) {
            for (std::size_t n = c * kChunk; n < std::min(buckets(), (c + 1) * kChunk) && !found[c]; ++n)
                for (std::size_t i = first_[n]; i < first_[n + 1] && !found[c];) {
                    std::size_t j = i, same = 0;
                    for (; j < first_[n + 1] && (rest_[j] >> 1) == (rest_[i] >> 1); ++j) same += rest_[j] & 1;
                    const Face f{n, static_cast<std::size_t>(rest_[i] >> 32), static_cast<std::size_t>((rest_[i] >> 1) & 0x7fffffffu)};
                    if (std::optional<std::string> why = judge(f, same, j - i - same)) found[c] = std::make_pair(f, std::move(*why));
                    i = j;
                }
        });
        for (auto& f : found)
            if (f) return f;
        return std::nullopt;
    }
    /// How many tetrahedra see face @p f (sorted) the face's own way round and the other way.
    std::pair<std::size_t, std::size_t> count(const Face& f) const
    {
        if (f[0] >= buckets()) return {0, 0};
        const auto begin = rest_.begin() + first_[f[0]], end = rest_.begin() + first_[f[0] + 1];
        const auto from = std::lower_bound(begin, end, pack(f, false));
        std::pair<std::size_t, std::size_t> n{0, 0};
        for (auto it = from; it != end && (*it >> 1) == (pack(f, false) >> 1); ++it) ++((*it & 1) ? n.first : n.second);
        return n;
    }

private:
    static constexpr std::size_t kChunk = 4096;
    std::size_t buckets() const { return first_.size() - 1; }
    std::size_t chunks() const { return (buckets() + kChunk - 1) / kChunk; }
    static std::uint64_t pack(const Face& f, bool same)
    {
        return (std::uint64_t(f[1]) << 32) | (std::uint64_t(f[2]) << 1) | std::uint64_t(same ? 1 : 0);
    }
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
    // Each surface triangle: on the outside, one tetrahedron inside it (seeing it as the
    // surface faces, outward); between two volumes, one each side.
    std::vector<Face> outer;
    outer.reserve(target.outer.size());
    for (const Face& t : target.outer) {
        const auto [f, same] = sorted(t);
        const auto [withIt, against] = faces.count(f);
        const std::size_t inside = same ? withIt : against, outside = same ? against : withIt;
        if (inside != 1 || outside != 0)
            refuse(mesh, f,
                   "a surface triangle on the outside has " + std::to_string(inside) + " tetrahedra inside it and " + std::to_string(outside) +
                       " outside, not 1 and 0");
        outer.push_back(f);
    }
    std::vector<Face> between;
    between.reserve(target.between.size());
    for (const Face& t : target.between) {
        const Face f = sorted(t).first;
        const auto [withIt, against] = faces.count(f);
        if (withIt != 1 || against != 1)
            refuse(mesh, f,
                   "a surface triangle between two volumes has " + std::to_string(withIt) + " and " + std::to_string(against) +
                       " tetrahedra on its two sides, not 1 and 1");
        between.push_back(f);
    }
    std::sort(outer.begin(), outer.end());
    // Every other face: inner, so one tetrahedron on each side.
    const auto defect = faces.firstDefect(threads, [&](const Face& f, std::size_t withIt, std::size_t against) -> std::optional<std::string> {
        if (withIt + against > 2) return "a face is shared by " + std::to_string(withIt + against) + " tetrahedra";
        if (withIt + against == 2 && withIt != 1) return std::string("two tetrahedra lie on the same side of a face (the mesh folds)");
        if (withIt + against == 1 && !std::binary_search(outer.begin(), outer.end(), f))
            return std::string("an inner face belongs to one tetrahedron only (a crack)");
        return std::nullopt;
    });
    if (defect) refuse(mesh, defect->first, defect->second);
    // The volumes, each within 1e-9 of itself (and of the largest's 1e-12, for rounding).
    std::vector<double> filled(target.volume.size(), 0.0);
    for (std::size_t k = 0; k < mesh.tetrahedra.size(); ++k)
        if (mesh.tow[k] < filled.size()) filled[mesh.tow[k]] += mesh.tetrahedronVolume(k);
    double largest = 0.0;
    for (double v : target.volume) largest = std::max(largest, std::abs(v));
    for (std::size_t t = 0; t < filled.size(); ++t)
        if (!(std::abs(filled[t] - target.volume[t]) <= 1e-9 * std::abs(target.volume[t]) + 1e-12 * largest)) {
            std::ostringstream text;
            text.precision(12);
            text << "the volume mesh does not fill " << (t < target.name.size() ? target.name[t] : "a volume") << ": its tetrahedra add up to "
                 << filled[t] << ", its surface encloses " << target.volume[t];
            throw Error(ErrorCode::Internal, text.str());
        }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
