// Similitude rules of scaled roller rigs (conforma/similitude.hpp, docs/physics-reference.md §7.6).
#include "conforma/similitude.hpp"

#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(SimilitudeRule rule) {
  return rule == SimilitudeRule::ContactStress ? "contact_stress" : "weight";
}

SimilitudeRule SimilitudeRuleFromName(const std::string& name) {
  if (name == "contact_stress") return SimilitudeRule::ContactStress;
  if (name == "weight") return SimilitudeRule::Weight;
  throw InputError("similitude rule '" + name + "': expected contact_stress or weight");
}

const char* to_string(SimilitudeQuantity quantity) {
  switch (quantity) {
    case SimilitudeQuantity::Length: return "length";
    case SimilitudeQuantity::Time: return "time";
    case SimilitudeQuantity::Speed: return "speed";
    case SimilitudeQuantity::AngularSpeed: return "angular_speed";
    case SimilitudeQuantity::Acceleration: return "acceleration";
    case SimilitudeQuantity::Mass: return "mass";
    case SimilitudeQuantity::Force: return "force";
    case SimilitudeQuantity::Stiffness: return "stiffness";
    case SimilitudeQuantity::Damping: return "damping";
    case SimilitudeQuantity::ContactSemiAxis: return "contact_semi_axis";
    case SimilitudeQuantity::ContactPressure: return "contact_pressure";
    case SimilitudeQuantity::CreepCoefficient: return "creep_coefficient";
    case SimilitudeQuantity::Creepage: return "creepage";
  }
  return "?";
}

void SimilitudeOptions::validate() const { require_positive(length_factor, "similitude length_factor"); }

double SimilitudeFactor(SimilitudeQuantity quantity, const SimilitudeOptions& options) {
  options.validate();
  const double phi = options.length_factor;
  // Exponents of phi. Base rules (§7.6): ContactStress: speed 1, time phi, force phi^2; Weight: acceleration 1,
  // time phi^(1/2), force phi^3. Both: length phi, mass phi^3 (same density), creepage 1. Derived: angular speed =
  // speed / length, acceleration = speed / time, stiffness = force / length, damping = force / speed. Hertz with the
  // same E* and all radii times phi (§1.2: a ~ (N R / E*)^(1/3), p0 ~ N / a^2): semi-axis (N phi)^(1/3), pressure
  // N / (N phi)^(2/3); creep coefficient G a b C11 ~ a^2 (a/b and C11 unchanged).
  const bool stress = options.rule == SimilitudeRule::ContactStress;
  const double force = stress ? 2.0 : 3.0;
  const double time = stress ? 1.0 : 0.5;
  const double speed = 1.0 - time;
  const double semi_axis = (force + 1.0) / 3.0;
  double exponent = 0.0;
  switch (quantity) {
    case SimilitudeQuantity::Length: exponent = 1.0; break;
    case SimilitudeQuantity::Time: exponent = time; break;
    case SimilitudeQuantity::Speed: exponent = speed; break;
    case SimilitudeQuantity::AngularSpeed: exponent = speed - 1.0; break;
    case SimilitudeQuantity::Acceleration: exponent = speed - time; break;
    case SimilitudeQuantity::Mass: exponent = 3.0; break;
    case SimilitudeQuantity::Force: exponent = force; break;
    case SimilitudeQuantity::Stiffness: exponent = force - 1.0; break;
    case SimilitudeQuantity::Damping: exponent = force - speed; break;
    case SimilitudeQuantity::ContactSemiAxis: exponent = semi_axis; break;
    case SimilitudeQuantity::ContactPressure: exponent = force - 2.0 * semi_axis; break;
    case SimilitudeQuantity::CreepCoefficient: exponent = 2.0 * semi_axis; break;
    case SimilitudeQuantity::Creepage: exponent = 0.0; break;
  }
  return std::pow(phi, exponent);
}

double ScaleToModel(double full_scale_value, SimilitudeQuantity quantity, const SimilitudeOptions& options) {
  require_finite(full_scale_value, "similitude full-scale value");
  return full_scale_value * SimilitudeFactor(quantity, options);
}

double ScaleToFull(double model_value, SimilitudeQuantity quantity, const SimilitudeOptions& options) {
  require_finite(model_value, "similitude model value");
  return model_value / SimilitudeFactor(quantity, options);
}

}  // namespace conforma
