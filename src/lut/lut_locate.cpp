// Cell of one axis of a contact look-up table (lut_locate.hpp).
#include "lut_locate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "conforma/error.hpp"

namespace conforma {

void LocateOnLutAxis(const std::vector<double>& axis, double v, const char* name, const char* unit, double unit_scale,
                     size_t* i, double* t) {
  const double lo = axis.front(), hi = axis.back();
  if (!std::isfinite(v) || v < lo || v > hi) {
    char text[256];
    std::snprintf(text, sizeof text, "contact LUT: %s = %.9g %s is outside the table [%.9g, %.9g] %s (not extrapolated)",
                  name, v * unit_scale, unit, lo * unit_scale, hi * unit_scale, unit);
    throw InputError(text);
  }
  size_t k = static_cast<size_t>(std::upper_bound(axis.begin(), axis.end(), v) - axis.begin());
  k = std::min(std::max<size_t>(k, 1), axis.size() - 1) - 1;
  *i = k;
  *t = (v - axis[k]) / (axis[k + 1] - axis[k]);
}

}  // namespace conforma
