// NumPy arrays to and from the library's point and index vectors.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"

namespace towgeom::python {

namespace py = pybind11;

/// A C-contiguous float64 array, converted (copied) when the caller's is not one.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// An (n, columns) view of @p count rows of @p columns elements of type T starting at @p data,
/// kept alive by @p owner (the Python object holding the vector): no copy. Writes are refused
/// (the array is read-only) so the library's data cannot change behind its back.
template <class T>
py::array rowsView(const T* data, std::size_t count, std::size_t columns, py::handle owner)
{
    py::array view(py::dtype::of<T>(), {count, columns}, {columns * sizeof(T), sizeof(T)}, data, owner);
    view.attr("setflags")(py::arg("write") = false);
    return view;
}

/// An (n,) read-only view of @p count elements, kept alive by @p owner.
template <class T>
py::array vectorView(const T* data, std::size_t count, py::handle owner)
{
    py::array view(py::dtype::of<T>(), {count}, {sizeof(T)}, data, owner);
    view.attr("setflags")(py::arg("write") = false);
    return view;
}

/// Points as an (n, 3) view (Point3 is three doubles, laid out as double[3]).
inline py::array pointsView(const std::vector<Point3>& points, py::handle owner)
{
    static_assert(sizeof(Point3) == 3 * sizeof(double), "Point3 must be three packed doubles");
    return rowsView(points.empty() ? nullptr : &points.front().x, points.size(), 3, owner);
}

/// Index triples as an (n, 3) uint64 view.
inline py::array trianglesView(const std::vector<std::array<std::size_t, 3>>& triangles, py::handle owner)
{
    static_assert(sizeof(std::array<std::size_t, 3>) == 3 * sizeof(std::size_t), "triangles must be packed");
    return rowsView(triangles.empty() ? nullptr : triangles.front().data(), triangles.size(), 3, owner);
}

/// Points as a new (n, 3) float64 array.
py::array_t<double> pointsArray(const std::vector<Point3>& points);

/// Index triples as a new (n, 3) uint64 array.
py::array_t<std::size_t> trianglesArray(const std::vector<std::array<std::size_t, 3>>& triangles);

/// The rows of an (n, 3) array as points; throws ValueError naming @p what for another shape.
std::vector<Point3> toPoints(const DoubleArray& array, const std::string& what);

/// The rows of an (n, 3) array of integers as index triples, each checked against @p nodeCount;
/// TypeError for floating-point or other non-integer arrays (no silent truncation).
std::vector<std::array<std::size_t, 3>> toTriangles(const py::handle& indices, std::size_t nodeCount, const std::string& what);

}  // namespace towgeom::python
