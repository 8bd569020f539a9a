#pragma once
// Cell of one axis of a contact look-up table (contact_lut.hpp), shared by the evaluation of the contact and of the
// tabulated rigid equilibrium.
#include <cstddef>
#include <vector>

namespace conforma {

// Lower index *i of the cell of `axis` holding v and the fraction *t in [0, 1]. InputError naming the axis (name,
// value in `unit` = SI x unit_scale) outside the axis: a table is never extrapolated.
void LocateOnLutAxis(const std::vector<double>& axis, double v, const char* name, const char* unit, double unit_scale,
                     std::size_t* i, double* t);

}  // namespace conforma
