// decompose.cpp -- Hertel-Mehlhorn convex decomposition of a triangulated polygon.
// (Being ported from the numba kernels; bound into minkowski2d._core._ext.)
#include <nanobind/nanobind.h>

namespace nb = nanobind;

namespace mk_bind {
void bind_decompose(nb::module_& m) { (void)m; }
}  // namespace mk_bind
