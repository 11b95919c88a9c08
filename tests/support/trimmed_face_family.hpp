// A randomized family of trimmed tool faces (a random bicubic patch trimmed by a random ellipse in
// its parameters, some with a hole) written as STEP, and OpenCASCADE's own answers about a face
// read back (BRepExtrema distances, BRepGProp area): oracles independent of towgeom's
// classification of points on a face.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <towgeom/point.hpp>

namespace towgeom::testing {

/// What writeRandomTrimmedPatch() made.
struct RandomTrimmedPatch {
    Point3 inside;      ///< a point on the face (the ellipse's centre, or beside the hole)
    bool hole = false;  ///< whether the face has a hole
};

/// Writes to the STEP file @p path one face: a clamped bicubic B-spline patch over about
/// [0, 4] x [0, 3] (6 x 5 poles, heights random within +-0.4), trimmed by an ellipse of random
/// centre, axes and turn inside its (u,v) square, and, when @p hole, with a circular hole of
/// random place and radius (0.005 to 0.06 of the square: often narrower than a curve's point
/// spacing) inside it. The same @p seed gives the same face.
RandomTrimmedPatch writeRandomTrimmedPatch(const std::string& path, unsigned seed, bool hole);

/// Face 0 of a STEP file as OpenCASCADE reads it, measured by OpenCASCADE.
class FaceOracle {
public:
    explicit FaceOracle(const std::string& stepPath);
    /// The distance from @p p to the face (0 on it, within its trimming curves).
    double toFace(const Point3& p) const;
    /// The distance from @p p to the face's boundary (its edges).
    double toBoundary(const Point3& p) const;
    double area() const;  ///< the face's area (BRepGProp)
    /// The largest tolerance of its edges: how far their curves on the face may stray from their
    /// 3D curves (a boolean's intersection edges are approximations).
    double edgeTolerance() const;
    double size() const;  ///< the diagonal of its bounding box

private:
    struct Data;
    std::shared_ptr<const Data> data_;
};

}  // namespace towgeom::testing
