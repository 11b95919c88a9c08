// The size a cell's face is meshed at: the finest tow's size where tows cross the face, growing
// with the distance to the nearest tow node elsewhere (Cell::faceSizeGrowth, faceSizeMax).
#pragma once

#include <CGAL/Bbox_2.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "cell/axis.hpp"
#include "mesh/mesh_cdt.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The two in-plane axes of a face across axis @p a, in increasing order.
inline std::array<int, 2> inPlane(int a) { return a == 0 ? std::array<int, 2>{1, 2} : a == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1}; }

/// The tows' surface nodes, for the distance from a point of a face to the nearest tow.
using NodeTraits = CGAL::Search_traits_3<mesh2::K>;
using NearestNode = CGAL::Orthogonal_k_neighbor_search<NodeTraits>;

/// How a face's edge length grows away from the tows (Cell::faceSizeGrowth, faceSizeMax).
struct FaceGrading {
    double growth = 0.0;                        ///< per unit of distance from the nearest tow
    double maxFactor = 1.0;                     ///< at most this times the tows' size
    const NearestNode::Tree* towNodes = nullptr;  ///< every tow's surface nodes (built)
};

/// The edge length wanted at a point of a face: the tows' size within each cut's bounding box
/// (where its cap is), elsewhere growing with the distance to the nearest tow node (in 3D, so a
/// face is finer where a tow passes close to it without crossing it). A periodic cell's min face
/// is also the max face: its point there counts too (@p planes: both coordinates).
class FaceSize {
public:
    FaceSize(const std::vector<std::vector<mesh2::K::Point_2>>& cuts, int axis, std::vector<double> planes, double h, const FaceGrading& grading)
        : axis_(axis), planes_(std::move(planes)), h_(h), grading_(grading)
    {
        for (const auto& cut : cuts) boxes_.push_back(CGAL::bbox_2(cut.begin(), cut.end()));
    }
    double operator()(const mesh2::K::Point_2& p) const
    {
        const double hMax = h_ * grading_.maxFactor;
        if (grading_.growth == 0.0 || hMax <= h_) return h_;
        for (const CGAL::Bbox_2& b : boxes_)
            if (p.x() >= b.xmin() && p.x() <= b.xmax() && p.y() >= b.ymin() && p.y() <= b.ymax()) return h_;
        if (!grading_.towNodes || grading_.towNodes->empty()) return hMax;
        const auto [b, c] = inPlane(axis_);
        double nearest2 = std::numeric_limits<double>::infinity();
        for (const double at : planes_) {
            Point3 q;
            coord(q, axis_) = at;
            coord(q, b) = p.x();
            coord(q, c) = p.y();
            const NearestNode search(*grading_.towNodes, mesh2::K::Point_3(q.x, q.y, q.z), 1);
            nearest2 = std::min(nearest2, search.begin()->second);
        }
        return std::min(hMax, h_ + grading_.growth * std::sqrt(nearest2));
    }

private:
    int axis_;
    std::vector<double> planes_;
    double h_;
    FaceGrading grading_;
    std::vector<CGAL::Bbox_2> boxes_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
