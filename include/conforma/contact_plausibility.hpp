#pragma once
// Plausibility warnings of one wheel's contact (not errors: the solve is kept, the report says what looks wrong).
// Filled by SolveWheelContact into WheelContactReport::warnings, so that the command line, Python and the C API
// all carry them. Each warning is one line "code: message" with the measured numbers and what fixes it. Limits
// and their sources: docs/physics-reference.md §13.
//
//   nominal_radius        a patch on the tread (|contact angle| <= kTreadContactAngleRad) whose rolling radius
//                         r0 + z_wheel(y_c) is more than kMaxTreadRadiusOffsetM from the nominal radius r0: the
//                         wheel profile's z origin is not at the taping line (profile.hpp), so the axle, rolling at
//                         V / r0, slips by xi ~ -(r - r0) / r0 under nominally pure rolling; or, when the profile's
//                         height at y = 0 is within kMaxTreadRadiusOffsetM of 0, the patch lies on the flange tip or
//                         back (the wheelset is beyond flange contact), and the message says that instead
//   friction_coefficient  mu (the constant one, or the static value mu(0) and the sliding limit of a friction law)
//                         outside [kMinPlausibleFriction, kMaxPlausibleFriction]
//   pressure_limit        a patch's maximum pressure above kMaxPlausiblePressurePa
//   load_not_converged    load control did not reach the wheel load (status NotConverged)
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

constexpr double kMinPlausibleFriction = 0.05;  // -, wet / contaminated rail (docs/physics-reference.md §13)
constexpr double kMaxPlausibleFriction = 1.0;   // -, above clean dry steel on steel (§13)
// mu within [kMinPlausibleFriction, kMaxPlausibleFriction]: the one test of every friction warning (contact's
// friction_coefficient, `dynamics --friction`, a scenario's track classes)
constexpr bool IsPlausibleFriction(double mu) { return !(mu < kMinPlausibleFriction || mu > kMaxPlausibleFriction); }
// Pa: 4 x the elastic shakedown limit of rail steel in free rolling, p0 = 4 k with k ~ 0.3 GPa (§13)
constexpr double kMaxPlausiblePressurePa = 5e9;
constexpr double kMaxTreadRadiusOffsetM = 10e-3;  // m: |r - r0| on the tread (§13)
constexpr double kTreadContactAngleRad = 0.2;     // rad (11.5 deg): patches flatter than this are on the tread

// The warnings of a finished report (its patches, status and loads) solved with these options on this geometry.
std::vector<std::string> ContactPlausibilityWarnings(const WheelContactReport& report,
                                                     const WheelsetTrackGeometry& geometry,
                                                     const WheelContactOptions& options);

}  // namespace conforma
