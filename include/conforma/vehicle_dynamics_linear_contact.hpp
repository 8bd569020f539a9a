#pragma once
// Linear wheel-rail contact of the time-domain model (Wickens' linear wheelset: A. H. Wickens, "Fundamentals of
// Rail Vehicle Dynamics", Swets & Zeitlinger 2003; Garg & Dukkipati 1984; chapters and equation numbers not checked, docs/physics-reference.md
// §16.3): Kalker's linear creep forces with constant coefficients, the equivalent conicity for the rolling-radius
// difference, and the lateral gravitational stiffness from the contact-angle parameter. Per wheelset, in the
// local track frame, with y_r, psi_r, dy_r/dt relative to the actual rails and Omega = V / r0 (1 + w):
//   xi_L,R  = -/+ (lambda y_r / r0 + b0 (dpsi/dt + V c) / V) - w       (r_L,R = r0 +/- lambda y_r)
//   eta     = dy_r/dt / V - psi_r                                       (both wheels)
//   F_x,L,R = -f11 xi_L,R,   F_y = -f22 eta (each wheel; forces on the wheel, Kalker's sign)
//   Y   = -2 f22 (dy_r/dt / V - psi_r) - (W epsilon / b0) y_r           (W = Q_L + Q_R)
//   M_z = -b0 (F_x,L - F_x,R) = -2 f11 b0 (lambda y_r / r0 + b0 (dpsi/dt + V c) / V)
//   T   = r0 (F_x,L + F_x,R) = 2 f11 r0 w
// Spin creep (f23, f33) and the yaw gravitational stiffness are left out (Wickens' simplest consistent model).
#include "conforma/material.hpp"

namespace conforma {

// validate() throws InputError naming the field.
struct LinearWheelsetContact {
  double f11_N = 1.0e7;                  // longitudinal creep coefficient per wheel, G a b C11, N, > 0
  double f22_N = 8.7e6;                  // lateral creep coefficient per wheel, G a b C22, N, > 0
  double conicity = 0.2;                 // equivalent conicity lambda, > 0
  double contact_angle_parameter = 0.0;  // epsilon (Wickens): lateral gravitational stiffness W epsilon / b0, >= 0
  // d(roll)/dy of the wheelset for the gyroscopic yaw moment -I_wy Omega dphi/dt; < 0: lambda / b0 (coned wheels)
  double roll_coefficient_per_m = -1.0;
  void validate() const;
};

// Kalker's coefficients for a Hertzian ellipse of semi-axes a (along x) and b at Poisson's ratio nu:
// f11 = G a b C11, f22 = G a b C22 (kalker.hpp; docs/physics-reference.md §2.2). Other fields default.
LinearWheelsetContact LinearContactFromEllipse(double a_m, double b_m, const Material& material);

}  // namespace conforma
