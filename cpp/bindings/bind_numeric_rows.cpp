// The readers' fast path: plain numeric rows of a text block (conversion only).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include "convert.h"
#include "nonobtuse/numeric_rows.h"

namespace nonobtuse::bindings {

void bind_numeric_rows(py::module_& m) {
  m.def(
      "parse_numeric_rows",
      [](const py::bytes& text, std::size_t rows, std::size_t width,
         const std::vector<int>& integer_columns) -> std::optional<DoubleArray> {
        char* data = nullptr;
        Py_ssize_t size = 0;
        PyBytes_AsStringAndSize(text.ptr(), &data, &size);
        std::optional<std::vector<double>> values;
        {
          py::gil_scoped_release release;
          values = parse_numeric_rows(std::string_view(data, static_cast<std::size_t>(size)), rows, width,
                                      integer_columns);
        }
        if (!values) return std::nullopt;
        DoubleArray a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(width)});
        std::copy(values->begin(), values->end(), a.mutable_data());
        return a;
      },
      py::arg("text"), py::arg("rows"), py::arg("width"), py::arg("integer_columns"),
      "ASCII text of `rows` lines of exactly `width` plain decimal numbers as a (rows, width) float64 array\n"
      "(integer_columns: integer literals, |x| < 2^53), or None for anything else (numeric_rows.h).");
}

}  // namespace nonobtuse::bindings
