#include "arrays.hpp"

#include <algorithm>

namespace towgeom::python {

py::array_t<double> pointsArray(const std::vector<Point3>& points)
{
    py::array_t<double> out({points.size(), std::size_t{3}});
    if (!points.empty()) std::copy_n(&points.front().x, 3 * points.size(), out.mutable_data());
    return out;
}

py::array_t<std::size_t> trianglesArray(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    py::array_t<std::size_t> out({triangles.size(), std::size_t{3}});
    if (!triangles.empty()) std::copy_n(triangles.front().data(), 3 * triangles.size(), out.mutable_data());
    return out;
}

std::vector<Point3> toPoints(const DoubleArray& array, const std::string& what)
{
    if (array.ndim() != 2 || array.shape(1) != 3) {
        std::string shape;
        for (py::ssize_t k = 0; k < array.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(array.shape(k));
        throw py::value_error(what + " must be an (n, 3) array of coordinates, not one of shape (" + shape + ")");
    }
    std::vector<Point3> points(static_cast<std::size_t>(array.shape(0)));
    if (!points.empty()) std::copy_n(array.data(), 3 * points.size(), &points.front().x);
    return points;
}

std::vector<std::array<std::size_t, 3>> toTriangles(const py::handle& indices, std::size_t nodeCount, const std::string& what)
{
    const py::array given = py::array::ensure(indices);
    if (!given || (given.dtype().kind() != 'i' && given.dtype().kind() != 'u'))
        throw py::type_error(what + ": triangles must be an array of integer node indices");
    const auto array = given.cast<py::array_t<long long, py::array::c_style | py::array::forcecast>>();
    if (array.ndim() != 2 || array.shape(1) != 3)
        throw py::value_error(what + " must be an (n, 3) array of node indices");
    std::vector<std::array<std::size_t, 3>> triangles(static_cast<std::size_t>(array.shape(0)));
    const long long* index = array.data();
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const long long i = index[3 * t + k];
            if (i < 0 || static_cast<std::size_t>(i) >= nodeCount)
                throw py::value_error(what + ": triangle " + std::to_string(t) + " names node " + std::to_string(i) + ", not one of the " +
                                      std::to_string(nodeCount) + " nodes");
            triangles[t][k] = static_cast<std::size_t>(i);
        }
    return triangles;
}

}  // namespace towgeom::python
