// Stand-in for python/bind_wear.cpp when the wear loop (include/conforma/wear_simulation.hpp) is not part of the
// build: wear() and scenario() raise NotImplementedError naming what is missing.
#include <pybind11/pybind11.h>

#include "module_parts.hpp"

namespace conforma::python {

void BindWear(pybind11::module_& m) {
  m.attr("has_wear") = false;
  m.def(
      "wear",
      [](pybind11::args, pybind11::kwargs) -> pybind11::object {
        PyErr_SetString(PyExc_NotImplementedError,
                        "conforma.wear: this build has no wear loop (include/conforma/wear_simulation.hpp missing)");
        throw pybind11::error_already_set();
      },
      "Not available in this build (no wear loop).");
}

}  // namespace conforma::python
