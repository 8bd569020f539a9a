// Axle rolling speed from the torque balance (axle_rolling_speed.hpp, docs/physics-reference.md §12.3).
#include "conforma/axle_rolling_speed.hpp"

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/root_finding.hpp"

namespace conforma {

void AxleRollingSpeedOptions::validate() const {
  require_finite(applied_torque_Nm, "applied_torque_Nm");
  require_positive(torque_tolerance_Nm, "torque_tolerance_Nm");
  require_positive(first_step, "first_step");
  require_positive(max_excursion, "max_excursion");
  if (!(max_excursion > first_step)) throw InputError("option 'max_excursion' must be larger than 'first_step'");
}

const char* to_string(AxleRollingSpeedStatus status) {
  switch (status) {
    case AxleRollingSpeedStatus::Converged: return "converged";
    case AxleRollingSpeedStatus::NotConverged: return "not_converged";
    case AxleRollingSpeedStatus::ContactFailed: return "contact_failed";
  }
  return "?";
}

AxleRollingSpeedResult SolveAxleRollingSpeed(const WheelsetTrackGeometry& geometry, const WheelsetPose& pose,
                                             const WheelsetVelocity& velocity,
                                             const std::array<double, 2>& vertical_load_N,
                                             const WheelContactOptions& contact_options,
                                             const WheelContactFunction& contact, double nominal_radius_m,
                                             const AxleRollingSpeedOptions& options) {
  options.validate();
  require_positive(velocity.forward_speed_m_s, "forward_speed_m_s");
  require_positive(nominal_radius_m, "nominal_radius_m");
  if (!contact) throw InputError("axle rolling speed: no contact function given");
  const double V = velocity.forward_speed_m_s, r0 = nominal_radius_m;
  const double u_start = velocity.axle_angular_velocity_rad_s * r0 / V - 1.0;

  AxleRollingSpeedResult result;
  bool contact_failed = false;
  // residual(u) = sum F_x r_p - T_applied at Omega = V (1 + u) / r0; the reports of the last evaluation are kept
  auto residual = [&](double u) {
    WheelsetVelocity v = velocity;
    v.axle_angular_velocity_rad_s = V * (1.0 + u) / r0;
    double torque = 0.0;
    ++result.contact_evaluations;
    for (Side side : {Side::Left, Side::Right}) {
      const int i = side_index(side);
      WheelContactOptions o = contact_options;
      o.vertical_load_N = vertical_load_N[i];
      result.reports[i] = contact(geometry, side, pose, v, o);
      if (result.reports[i].status != WheelContactStatus::Ok) contact_failed = true;
      for (const PatchReport& p : result.reports[i].patches) torque += p.fx_N * p.rolling_radius_m;
    }
    result.axle_angular_velocity_rad_s = v.axle_angular_velocity_rad_s;
    result.contact_torque_Nm = torque;
    result.residual_Nm = torque - options.applied_torque_Nm;
    return result.residual_Nm;
  };
  auto finish = [&](AxleRollingSpeedStatus status) {
    result.status = contact_failed ? AxleRollingSpeedStatus::ContactFailed : status;
    return result;
  };

  const double f0 = residual(u_start);
  if (contact_failed) return finish(AxleRollingSpeedStatus::ContactFailed);
  if (std::fabs(f0) <= options.torque_tolerance_Nm) return finish(AxleRollingSpeedStatus::Converged);
  // the residual rises with u: step towards the root, doubling, until it changes sign
  const double direction = f0 < 0.0 ? 1.0 : -1.0;
  double u_near = u_start, f_near = f0, step = options.first_step;
  for (;;) {
    const double u_far = u_start + direction * step;
    const double f_far = residual(u_far);
    if (contact_failed) return finish(AxleRollingSpeedStatus::ContactFailed);
    if (std::fabs(f_far) <= options.torque_tolerance_Nm) return finish(AxleRollingSpeedStatus::Converged);
    if ((f_far > 0.0) != (f_near > 0.0)) {
      const double low = direction > 0.0 ? u_near : u_far, high = direction > 0.0 ? u_far : u_near;
      const double f_low = direction > 0.0 ? f_near : f_far, f_high = direction > 0.0 ? f_far : f_near;
      int iterations = 0;
      double f_root = 0.0;
      SolveIncreasingRoot(residual, low, high, f_low, f_high, options.torque_tolerance_Nm, &iterations, &f_root);
      if (contact_failed) return finish(AxleRollingSpeedStatus::ContactFailed);
      return finish(std::fabs(f_root) <= options.torque_tolerance_Nm ? AxleRollingSpeedStatus::Converged
                                                                     : AxleRollingSpeedStatus::NotConverged);
    }
    if (step >= options.max_excursion) return finish(AxleRollingSpeedStatus::NotConverged);
    u_near = u_far, f_near = f_far;
    step = std::min(2.0 * step, options.max_excursion);
  }
}

}  // namespace conforma
