#pragma once
// Grids of the contact look-up table (contact_lut.hpp): the default grid of `conforma lut build` (docs/architecture.md
// "Contact look-up table": chosen on the default scenario's pair, S1002 / 50E4 1:20) and the extension of a grid to
// cover a range, used by the wear loop's `dynamic` provider with a table (dynamic_kinematics.hpp,
// docs/physics-reference.md §16.7).
#include <string>
#include <vector>

#include "conforma/contact_lut.hpp"

namespace conforma {

// The axes as text: comma-separated items, each a value or "min:max:step" (ParseContactLutAxis). The defaults are the
// default grid: y -10 .. 10 mm by 0.1 mm, refined to 0.05 mm over 5.5 <= |y| <= 8 mm (where S1002 meets the flange
// on 50E4 1:20 and the contact point moves fast); yaw -8 .. 8 mrad by 2 mrad; Q 20 .. 95 kN by 15 kN.
struct ContactLutGridText {
  std::string lateral_mm = "-10:10:0.1,-8:-5.5:0.05,5.5:8:0.05";
  std::string yaw_mrad = "-8:8:2";
  std::string load_kN = "20:95:15";
};

// Comma-separated items, each a value or "min:max:step" (inclusive; max itself when reached within step/1000),
// scaled by `scale` (to SI), sorted, values closer than 1e-9 of the span merged: "-10:10:0.1,5.5:8:0.05" refines a
// range. InputError naming `name` for text that is not of this form.
std::vector<double> ParseContactLutAxis(const std::string& text, const std::string& name, double scale);

// The three axes parsed (mm, mrad, kN to SI) and validated; the names of the errors are `--y-mm`, `--yaw-mrad`,
// `--load-kN` (the options of `conforma lut build`).
ContactLutGrid ParseContactLutGrid(const ContactLutGridText& text);

// ParseContactLutGrid of the defaults above.
ContactLutGrid DefaultContactLutGrid();

// The grid extended outward until it covers |y| <= lateral_abs_m, |psi| <= yaw_abs_rad and load_min_N <= Q <=
// load_max_N: each end gets new values at the spacing of its outermost interval (a load below that spacing halves
// instead, loads stay > 0). Values inside are kept as they are. InputError for a non-finite or negative range or
// load_min_N <= 0.
ContactLutGrid CoverContactLutGrid(ContactLutGrid grid, double lateral_abs_m, double yaw_abs_rad, double load_min_N,
                                   double load_max_N);

}  // namespace conforma
