// Grids of the contact look-up table (contact_lut_grid.hpp).
#include "conforma/contact_lut_grid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "conforma/error.hpp"

namespace conforma {

std::vector<double> ParseContactLutAxis(const std::string& text, const std::string& name, double scale) {
  std::vector<double> v;
  try {
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
      if (item.empty()) continue;
      if (item.find(':') == std::string::npos) {
        size_t used = 0;
        v.push_back(std::stod(item, &used) * scale);
        if (used != item.size()) throw InputError("");
        continue;
      }
      double lo, hi, step;
      char c1, c2;
      std::istringstream in(item);
      if (!(in >> lo >> c1 >> hi >> c2 >> step) || c1 != ':' || c2 != ':' || !(step > 0.0) || !(hi > lo))
        throw InputError("");
      const long n = std::lround(std::floor((hi - lo) / step + 1e-3));
      if (n > 100000) throw InputError("");
      for (long k = 0; k <= n; ++k) v.push_back((lo + k * step) * scale);
    }
  } catch (const std::exception&) {
    throw InputError(name + " '" + text + "': expected values and min:max:step ranges, comma-separated");
  }
  std::sort(v.begin(), v.end());
  if (!v.empty()) {
    const double tol = 1e-9 * std::max(1e-30, v.back() - v.front());
    std::vector<double> merged{v[0]};
    for (double x : v)
      if (x - merged.back() > tol) merged.push_back(x);
    v = merged;
  }
  return v;
}

ContactLutGrid ParseContactLutGrid(const ContactLutGridText& text) {
  ContactLutGrid g;
  g.lateral_m = ParseContactLutAxis(text.lateral_mm, "--y-mm", 1e-3);
  g.yaw_rad = ParseContactLutAxis(text.yaw_mrad, "--yaw-mrad", 1e-3);
  g.load_N = ParseContactLutAxis(text.load_kN, "--load-kN", 1e3);
  g.validate();
  return g;
}

ContactLutGrid DefaultContactLutGrid() { return ParseContactLutGrid(ContactLutGridText{}); }

namespace {

// Prepends / appends values at the end intervals' spacing until [lo, hi] is covered.
void Cover(std::vector<double>* v, double lo, double hi, bool positive) {
  while (v->front() > lo) {
    const double step = (*v)[1] - (*v)[0];
    const double x = v->front() - step;
    v->insert(v->begin(), positive && x <= 0.0 ? 0.5 * v->front() : x);
  }
  while (v->back() < hi) v->push_back(v->back() + (v->back() - (*v)[v->size() - 2]));
}

}  // namespace

ContactLutGrid CoverContactLutGrid(ContactLutGrid grid, double lateral_abs_m, double yaw_abs_rad, double load_min_N,
                                   double load_max_N) {
  grid.validate();
  if (!(std::isfinite(lateral_abs_m) && lateral_abs_m >= 0.0 && std::isfinite(yaw_abs_rad) && yaw_abs_rad >= 0.0))
    throw InputError("contact LUT grid cover: lateral and yaw ranges must be finite and >= 0");
  if (!(std::isfinite(load_min_N) && std::isfinite(load_max_N) && load_min_N > 0.0 && load_max_N >= load_min_N))
    throw InputError("contact LUT grid cover: loads must be finite with 0 < load_min_N <= load_max_N");
  Cover(&grid.lateral_m, -lateral_abs_m, lateral_abs_m, false);
  Cover(&grid.yaw_rad, -yaw_abs_rad, yaw_abs_rad, false);
  Cover(&grid.load_N, load_min_N, load_max_N, true);
  grid.validate();
  return grid;
}

}  // namespace conforma
