#pragma once
// Conformity index of a contact patch (paper 003 §4.3, eq. 13; docs/physics-reference.md §9): the opening angle
//     alpha_c = max over p1, p2 in the contact of arccos(n(p1) . n(p2))
// For a prismatic patch whose normals turn in one plane (the rail profile plane) this is the spread of the
// normal angle over the contact, max alpha - min alpha. The patch is flagged conformal above a threshold
// (18 degrees in paper 003; an engineering criterion, not a physical limit).
#include <vector>

namespace conforma {

// Conformity-index threshold above which a patch counts as conformal: paper 003 §4.3's 18 deg (the KP models'
// is_conformal flag), and the 17.7 deg measured by `conforma threshold` on the new S1002 / 60E1 1:20 pair at a 5 %
// difference (docs/physics-reference.md §9.1; the `auto` model's default).
constexpr double kConformityThresholdDeg = 18.0;
constexpr double kMeasuredConformityThresholdDeg = 17.7;

struct ConformityIndex {
  double alpha_c_deg = 0.0;
  bool is_conformal = false;
};

// From the normal angles (rad, relative to any fixed direction in the profile plane) sampled over the contact:
// its edges and its strips. Empty input gives alpha_c = 0. Throws InputError for a non-finite angle or threshold.
ConformityIndex ComputeConformityIndex(const std::vector<double>& normal_angles_in_contact_rad,
                                       double threshold_deg = kConformityThresholdDeg);

}  // namespace conforma
