// Kinematic curving estimate (wear_simulation.hpp): the geometric fallback of the
// quasi-static provider. Rigid-bogie curving: both wheelsets parallel to the frame on the chord (angle of attack
// -/+ a/R), leading wheelset at flange contact, trailing wheelset at the pure-rolling shift (Delta r = -2 b0 r0 c).
#include <cmath>

#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {

namespace {

// Lateral shift where r_L - r_R = target (scan from 0 towards the outer rail, linear interpolation), clipped.
double PureRollingShift(const WheelsetTrackGeometry& g, double target, double limit) {
  double prev_y = 0.0;
  WheelsetPose guess;
  EquilibriumResult e0 = g.SolveRigidEquilibrium(0.0, 0.0);
  double prev_d = e0.rolling_radius_difference_m;
  if (std::abs(target) <= std::abs(prev_d)) return 0.0;
  const int n = 200;
  for (int i = 1; i <= n; ++i) {
    const double y = limit * i / n;
    const EquilibriumResult e = g.SolveRigidEquilibrium(y, 0.0, guess);
    if (e.status == EquilibriumStatus::NoContact) continue;
    guess = e.pose;
    const double d = e.rolling_radius_difference_m;
    if ((d - target) * (prev_d - target) <= 0.0 && d != prev_d) return prev_y + (y - prev_y) * (target - prev_d) / (d - prev_d);
    prev_y = y;
    prev_d = d;
  }
  return limit;
}

}  // namespace

KinematicsSeries KinematicCurvingEstimate(const Scenario& sc, const WheelsetTrackGeometry& g, const TrackClass& tc) {
  const VehicleParameters& v = sc.vehicle;
  const double c = TrackClassCurvature(tc);
  const double V = tc.speed_m_s;
  const double r0 = v.nominal_wheel_radius_m, b0 = v.contact_half_distance_m, a = 0.5 * v.wheelbase_m;
  const double g_acc = 9.81;
  // unbalanced lateral acceleration and quasi-static load transfer (as kinematics_quasistatic.hpp)
  const double sign = c > 0 ? 1.0 : (c < 0 ? -1.0 : 0.0);
  const double a_nc = V * V * c - g_acc * tc.cant_m * sign / sc.kinematics.cant_base_m;
  const double dQ = v.carried_mass_per_wheelset_kg() * a_nc * v.load_transfer_height_m / (2.0 * b0);
  const double Q0 = v.static_wheel_load_N(g_acc);
  KinematicsSeries s;
  s.source = "kinematic estimate " + tc.name;
  auto make = [&](int ws, double y, double psi, double dy, double dpsi, double weight) {
    KinematicsSample k;
    k.wheelset = ws;
    k.weight = weight;
    const EquilibriumResult e = g.SolveRigidEquilibrium(y, psi);
    k.pose = e.pose;
    k.pose.lateral_m = y;
    k.pose.yaw_rad = psi;
    k.velocity.forward_speed_m_s = V;
    k.velocity.lateral_velocity_m_s = dy;
    k.velocity.yaw_rate_rad_s = V * c + dpsi;
    k.velocity.axle_angular_velocity_rad_s = V / r0;
    // c > 0: the left wheel is inner (loses load for a_nc > 0)
    k.vertical_load_N[0] = std::max(0.0, Q0 - dQ);
    k.vertical_load_N[1] = std::max(0.0, Q0 + dQ);
    k.track_curvature_per_m = c;
    s.samples.push_back(k);
  };
  if (c == 0.0) {
    const double A = sc.kinematics.tangent_amplitude_m;
    const int n = A > 0.0 ? sc.kinematics.tangent_phases : 1;
    double k_wave = 0.0;
    if (A > 0.0) {
      const EquilibriumResult e = g.SolveRigidEquilibrium(-A, 0.0);
      const double lambda = std::max(1e-3, -e.rolling_radius_difference_m / (2.0 * A));
      k_wave = 1.0 / std::sqrt(r0 * b0 / lambda);  // 2 pi / L_K
    }
    for (int ws = 0; ws < 2; ++ws)
      for (int i = 0; i < n; ++i) {
        const double th = 2.0 * M_PI * i / n;
        make(ws, A * std::sin(th), A * k_wave * std::cos(th), V * A * k_wave * std::cos(th),
             -V * A * k_wave * k_wave * std::sin(th), 1.0 / n);
      }
    return s;
  }
  const double y_flange = FlangeContactShift(g, sign);
  const double y_roll = PureRollingShift(g, -2.0 * b0 * r0 * c, y_flange);
  make(0, y_flange, -a * c, 0.0, 0.0, 1.0);
  make(1, y_roll, a * c, 0.0, 0.0, 1.0);
  return s;
}

}  // namespace conforma
