// The extension module _vibroimpact; python/vibroimpact/__init__.py re-exports it.

#include "bindings.hpp"

PYBIND11_MODULE(_vibroimpact, m) {
    m.doc() = "vibroimpact: vibro-impact dynamics of MEMS beams (compiled part; import vibroimpact)";
    vi::python::bind_errors(m);
    vi::python::bind_case(m);
    vi::python::bind_analyses(m);
    vi::python::bind_sweep(m);
    vi::python::bind_uq(m);
    vi::python::bind_design(m);
    vi::python::bind_paper(m);
    m.attr("__version__") = VI_VERSION;  // CMake's project VERSION
}
