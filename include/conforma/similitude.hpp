#pragma once
// Similitude (scaling) rules of scaled roller rigs (docs/physics-reference.md §7.6): the factor by which a quantity of
// the full-scale vehicle is multiplied to give the scaled model's value (model = factor * full), for a length scale
// phi (model / full, e.g. 0.2 for a 1:5 rig) and one of two rules. Both keep the materials (E, G, nu, density) and
// the creepages (dimensionless) of the full scale.
//   ContactStress: the same speed and the same contact pressure (time phi, force phi^2): the contact ellipse scales
//                  with phi, every stress is the same; the weight (mass phi^3 times g) does not follow, so the axle
//                  load must be set by a preload. The scaling of Jaschinski et al. (1999) for the DLR 1:5 rig [MEM].
//   Weight:        the same gravity (Froude: time and speed phi^(1/2), force phi^3 = mass phi^3 times g): the rig's
//                  own weight is similar, the elastic contact is not (with the same E the ellipse scales by
//                  phi^(4/3), the pressure by phi^(1/3)). Paper 000 §5.1 counts loads this way: 37 kg per wheel at
//                  1:5 is "around 10 tons/axle" (2 x 37 kg x 125 = 9.25 t).
#include <string>

namespace conforma {

// ContactStress: same speed and contact stresses (force phi^2); Weight: same gravity (force phi^3). See above.
enum class SimilitudeRule { ContactStress, Weight };
const char* to_string(SimilitudeRule rule);            // "contact_stress", "weight"
SimilitudeRule SimilitudeRuleFromName(const std::string& name);  // the names above; InputError otherwise

enum class SimilitudeQuantity {
  Length,            // profiles, radii, displacements, m
  Time,              // s
  Speed,             // m/s
  AngularSpeed,      // rad/s (and frequencies, 1/s)
  Acceleration,      // m/s^2
  Mass,              // kg (same density)
  Force,             // N: axle loads, creep forces, spring forces
  Stiffness,         // N/m
  Damping,           // N s/m
  ContactSemiAxis,   // Hertz a, b with the same E and all radii times phi (phi or phi^(4/3), from the force)
  ContactPressure,   // Hertz p0 (1 or phi^(1/3))
  CreepCoefficient,  // G a b C11, N per unit creepage (phi^2 or phi^(8/3))
  Creepage,          // dimensionless, 1
};
const char* to_string(SimilitudeQuantity quantity);

// validate(): InputError unless 0 < length_factor (finite).
struct SimilitudeOptions {
  double length_factor = 0.2;                         // phi = model / full, > 0 (1:5 rig: 0.2)
  SimilitudeRule rule = SimilitudeRule::ContactStress;  // which similitude (see SimilitudeRule)
  void validate() const;
};

// model = factor * full for the quantity (the table of docs/physics-reference.md §7.6).
double SimilitudeFactor(SimilitudeQuantity quantity, const SimilitudeOptions& options);
// Full-scale value -> model value, and back (exact inverses).
double ScaleToModel(double full_scale_value, SimilitudeQuantity quantity, const SimilitudeOptions& options);
double ScaleToFull(double model_value, SimilitudeQuantity quantity, const SimilitudeOptions& options);

}  // namespace conforma
