#pragma once
// Pieces of the Python module shared between its source files (python/*.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conforma/profile.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma::python {

pybind11::array_t<double> Column(const std::vector<double>& values);
pybind11::array_t<double> PointsArray(const std::vector<Eigen::Vector2d>& points);
pybind11::dict DimensionsDict(const WheelDimensions& dimensions);
ProfileKind KindFrom(const std::string& name);
// wear(scenario, model) and scenario(...) (python/bind_wear.cpp).
void BindWear(pybind11::module_& m);

}  // namespace conforma::python
