// Conversion between numpy arrays and the core's plain types; the one place that fixes dtypes and layouts:
// points are float64 (n, 2) or (n, 3), C-contiguous; index arrays are int64 (m, k); flags are int8.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <string>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse::bindings {
namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

inline void require_shape(const py::array& a, std::size_t cols, const char* name) {
  bool ok = a.ndim() == 2 && static_cast<std::size_t>(a.shape(1)) == cols;
  if (a.ndim() == 1 && a.shape(0) == 0) ok = true;  // an empty list converts to shape (0,)
  if (!ok)
    throw InvalidInput(std::string(name) + " must have shape (n, " + std::to_string(cols) + ")");
}

inline std::vector<Point2> to_points2(const DoubleArray& a, const char* name = "points") {
  require_shape(a, 2, name);
  std::vector<Point2> out(a.ndim() == 2 ? a.shape(0) : 0);
  auto* d = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {d[2 * i], d[2 * i + 1]};
  return out;
}

inline std::vector<Point3> to_points3(const DoubleArray& a, const char* name = "points") {
  require_shape(a, 3, name);
  std::vector<Point3> out(a.ndim() == 2 ? a.shape(0) : 0);
  auto* d = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
  return out;
}

inline DoubleArray from_points3(const std::vector<Point3>& pts) {
  DoubleArray a({static_cast<py::ssize_t>(pts.size()), py::ssize_t{3}});
  auto* d = a.mutable_data();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    d[3 * i] = pts[i].x;
    d[3 * i + 1] = pts[i].y;
    d[3 * i + 2] = pts[i].z;
  }
  return a;
}

template <std::size_t K>
std::vector<std::array<int, K>> to_index_rows(const IndexArray& a, std::size_t n_points, const char* name) {
  require_shape(a, K, name);
  std::vector<std::array<int, K>> out(a.ndim() == 2 ? a.shape(0) : 0);
  auto* d = a.data();
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t k = 0; k < K; ++k) {
      auto v = d[K * i + k];
      if (v < 0 || static_cast<std::size_t>(v) >= n_points)
        throw InvalidInput(std::string(name) + " row " + std::to_string(i) + " refers to point " +
                           std::to_string(v) + ", but there are " + std::to_string(n_points) + " points");
      out[i][k] = static_cast<int>(v);
    }
  return out;
}

inline DoubleArray from_points2(const std::vector<Point2>& pts) {
  DoubleArray a({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
  auto* d = a.mutable_data();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    d[2 * i] = pts[i].x;
    d[2 * i + 1] = pts[i].y;
  }
  return a;
}

template <std::size_t K>
IndexArray from_index_rows(const std::vector<std::array<int, K>>& rows) {
  IndexArray a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(K)});
  auto* d = a.mutable_data();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = 0; k < K; ++k) d[K * i + k] = rows[i][k];
  return a;
}

template <class T>
py::array_t<T> from_vector(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace nonobtuse::bindings
