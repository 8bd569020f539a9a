#pragma once
// Wheel flange reference dimensions Sd (flange thickness), Sh (flange height) and qR (flange slope measure)
// by the standard definitions (EN 15313 / UIC; paper 001 §7.2, paper 003 §7):
//   P0   point on the taping line (y = taping_line_y), z0 its height;
//   Sh = z(flange tip) - z0;
//   Sd = horizontal distance from the flange back (y = flange_back_y) to the flange-face point 10 mm above P0;
//   qR = horizontal distance between the flange-face point 2 mm below the flange tip and the Sd point.
// The flange face is the field-side face of the flange (between the tip and the tread).
#include <Eigen/Core>

#include "conforma/profile.hpp"

namespace conforma {

struct WheelDimensions {
  double sd_m = 0.0;  // flange thickness
  double sh_m = 0.0;  // flange height
  double qr_m = 0.0;  // flange slope measure
  // points used (y, z) [m]
  Eigen::Vector2d p0 = Eigen::Vector2d::Zero();        // taping line point
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();       // flange tip (highest point of the flange)
  Eigen::Vector2d sd_point = Eigen::Vector2d::Zero();  // flange face at z0 + 10 mm
  Eigen::Vector2d qr_point = Eigen::Vector2d::Zero();  // flange face at z_tip - 2 mm
};

// Throws InputError if the profile is not a wheel, the taping line is outside the profile, or there is no
// flange (no point at least 10 mm above P0 on the flange side of the taping line, or a face that does not come
// down to z0 + 10 mm between the tip and the taping line).
WheelDimensions MeasureWheelDimensions(const Profile& wheel, double flange_back_y_m = -0.070,
                                       double taping_line_y_m = 0.0);

}  // namespace conforma
