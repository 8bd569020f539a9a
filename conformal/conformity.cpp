// Conformity index, paper 003 eq. 13 (docs/physics-reference.md §9).
#include "conforma/conformity.hpp"

#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

ConformityIndex ComputeConformityIndex(const std::vector<double>& normal_angles_in_contact_rad, double threshold_deg) {
  require_finite(threshold_deg, "conformity_threshold_deg");
  ConformityIndex index;
  if (normal_angles_in_contact_rad.empty()) return index;
  for (double angle : normal_angles_in_contact_rad) require_finite(angle, "normal angle in contact (alpha_rad)");
  const auto [lowest, highest] =
      std::minmax_element(normal_angles_in_contact_rad.begin(), normal_angles_in_contact_rad.end());
  // In one plane the largest arccos(n1 . n2) over pairs is the spread of the angles (eq. 13), capped at 180 deg.
  index.alpha_c_deg = std::min(*highest - *lowest, M_PI) * 180.0 / M_PI;
  index.is_conformal = index.alpha_c_deg > threshold_deg;
  return index;
}

}  // namespace conforma
