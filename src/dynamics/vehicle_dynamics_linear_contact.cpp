// Linear wheelset contact parameters (vehicle_dynamics_linear_contact.hpp).
#include "conforma/vehicle_dynamics_linear_contact.hpp"

#include "conforma/error.hpp"
#include "conforma/kalker.hpp"

namespace conforma {

void LinearWheelsetContact::validate() const {
  require_positive(f11_N, "linear contact f11_N");
  require_positive(f22_N, "linear contact f22_N");
  require_positive(conicity, "linear contact conicity");
  require_non_negative(contact_angle_parameter, "linear contact contact_angle_parameter");
  require_finite(roll_coefficient_per_m, "linear contact roll_coefficient_per_m");
}

LinearWheelsetContact LinearContactFromEllipse(double a_m, double b_m, const Material& material) {
  require_positive(a_m, "ellipse semi-axis a_m");
  require_positive(b_m, "ellipse semi-axis b_m");
  const CreepCoefficients k = KalkerCoefficients(a_m / b_m, material.poisson_ratio);
  LinearWheelsetContact c;
  const double Gab = material.shear_modulus_Pa * a_m * b_m;  // docs/physics-reference.md §2.2: F_x = -G a b C11 xi
  c.f11_N = Gab * k.c11;
  c.f22_N = Gab * k.c22;
  return c;
}

}  // namespace conforma
