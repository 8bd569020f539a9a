// Roller-rig kinematics: eq. 2 creepages, the free wheelset speed from the moment balance of the two longitudinal
// contact forces, the longitudinal springs (roller_rig_kinematics.hpp; paper 000 §2 eqs. 1-2, §3.1).
#include "conforma/roller_rig_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(RollerRigKinematicsStatus status) {
  switch (status) {
    case RollerRigKinematicsStatus::Converged: return "converged";
    case RollerRigKinematicsStatus::Measured: return "measured";
    case RollerRigKinematicsStatus::NotConverged: return "not_converged";
    case RollerRigKinematicsStatus::NoContact: return "no_contact";
    case RollerRigKinematicsStatus::ContactError: return "contact_error";
  }
  return "unknown";
}

double RollerRigCreepage(double roller_speed_rad_s, double roller_radius_m, double wheelset_speed_rad_s,
                         double wheel_radius_m) {
  const double V = roller_speed_rad_s * roller_radius_m;
  require_positive(V, "roller surface speed omega_i R_i");
  require_finite(wheelset_speed_rad_s, "wheelset speed omega_3");
  require_positive(wheel_radius_m, "wheel rolling radius r_i");
  return (V - wheelset_speed_rad_s * wheel_radius_m) / V;  // paper 000 eq. 2
}

double RollerRigEq2WheelsetSpeed(const std::array<double, 2>& w, const std::array<double, 2>& R,
                                 const std::array<double, 2>& r) {
  for (int i = 0; i < 2; ++i) {
    require_positive(w[i], "roller speed omega_i");
    require_positive(R[i], "roller rolling radius R_i");
    require_positive(r[i], "wheel rolling radius r_i");
  }
  // paper 000 eq. 2 with xi_1 = -xi_2: 2 = omega_3 (r_1/(omega_1 R_1) + r_2/(omega_2 R_2))
  return 2.0 / (r[0] / (w[0] * R[0]) + r[1] / (w[1] * R[1]));
}

namespace {
constexpr double kMaxRigLateralVelocity_m_s = 10.0;
}  // namespace

void RollerRigKinematicsOptions::validate() const {
  contact.validate();
  require_positive(balance_tolerance, "RollerRigKinematicsOptions.balance_tolerance");
  require_non_negative(load_acceptance, "RollerRigKinematicsOptions.load_acceptance");
  if (max_evaluations < 2) throw InputError("RollerRigKinematicsOptions.max_evaluations must be >= 2");
}

WheelContactOptions RollerRigContactOptions(const RollerRigSetup& setup) {
  setup.validate();
  WheelContactOptions o;
  o.model = ContactModel::Hertz;
  o.fastsim_elements = 20;  // paper 000 §3.4: 20 x 20 elements
  o.candidate_strip_width_m *= setup.length_factor;
  o.patch_combine_distance_m *= setup.length_factor;
  o.exact_element_size_m *= setup.length_factor;
  o.load_balance = LoadBalance::Pressure;
  o.material = setup.wheel_material;
  return o;
}

namespace {

// Ok, or load control stopped short within the acceptance of the load (see RollerRigKinematicsOptions).
bool Usable(const WheelContactReport& r, const WheelContactOptions& o, double acceptance) {
  if (r.status == WheelContactStatus::Ok) return true;
  return r.status == WheelContactStatus::NotConverged && !r.patches.empty() &&
         std::abs(BalancedVerticalForce(r, o) - o.vertical_load_N) <= acceptance * o.vertical_load_N;
}

struct SideState {
  double R = 0.0, r = 0.0, V = 0.0, y = 0.0, load = 0.0;
};

double SumFx(const WheelContactReport& rep, double* moment) {
  double fx = 0.0, m = 0.0;
  for (const PatchReport& p : rep.patches) {
    fx += p.fx_N;
    m += p.fx_N * p.rolling_radius_m;  // moment about the axle of the wheel's longitudinal force
  }
  *moment = m;
  return fx;
}

// The solve proper, on validated input.
RollerRigKinematicsResult SolveOnProfiles(const WheelsetTrackGeometry& geometry, const RollerRigSetup& setup,
                                          const RollerRigKinematicsInput& in, const RollerRigKinematicsOptions& options,
                                          bool measured) {
  RollerRigKinematicsResult res;
  WheelsetPose pose;
  pose.lateral_m = in.lateral_m;
  pose.yaw_rad = in.yaw_rad;
  std::array<SideState, 2> st;
  std::array<WheelsetPose, 2> side_pose;
  for (Side side : {Side::Left, Side::Right}) {
    const int k = side_index(side);
    if (!(in.wheel_load_N[k] > 0.0)) {
      res.status = RollerRigKinematicsStatus::NoContact;
      res.message = std::string("no load on the ") + to_string(side) + " wheel";
      return res;
    }
    // each wheel starts its load control touching its roller (worn profiles: the mounted roller keeps its highest,
    // unworn point at z = 0 while the contact sinks into the groove)
    double gap = 0.0, gap_y = 0.0;
    side_pose[k] = pose;
    if (geometry.MinimumVerticalGap(side, pose, &gap, &gap_y)) side_pose[k].vertical_m -= gap;
    const WheelContactResult rc = geometry.RigidContact(side, side_pose[k]);
    if (rc.status != ContactStatus::Ok || rc.points.empty()) {
      res.status = RollerRigKinematicsStatus::NoContact;
      res.message = std::string("the ") + to_string(side) + " wheel does not face its roller";
      return res;
    }
    const RigidContactPoint& p = rc.points.front();
    st[k].R = p.roller_rolling_radius_m;                    // R_r + roller profile height (geometry §1.7)
    st[k].r = p.rolling_radius_m;
    st[k].V = in.roller_speed_rad_s[k] * st[k].R;           // paper 000 eq. 13
    st[k].y = p.wheel_point_m.y();
    st[k].load = in.wheel_load_N[k];
    if (!(st[k].R > 0.0) || !(st[k].r > 0.0)) throw InputError("roller rig: non-positive rolling radius at the contact");
  }
  WheelContactCache cache;  // the normal problem is reused along the root find (pressure load balance)
  // Rolling radii at the loaded contact (largest patch of the normal solution): the roller's at the reference point,
  // R_r + z_roller; the wheel's effective r - delta (approach delta): the contact solver's kinematics push the wheel
  // centre down by delta onto the undeformed roller surface, so its creepage is eq. 2 with these radii.
  for (Side side : {Side::Left, Side::Right}) {
    const int k = side_index(side);
    WheelContactOptions o = options.contact;
    o.vertical_load_N = st[k].load;
    o.solve_tangential = false;
    WheelsetVelocity v;
    v.forward_speed_m_s = st[k].V;
    v.axle_angular_velocity_rad_s = st[k].V / st[k].r;
    const WheelContactReport rep = SolveWheelContactCached(geometry, side, side_pose[k], v, o, cache);
    if (!Usable(rep, o, options.load_acceptance) || rep.patches.empty()) {
      res.status = RollerRigKinematicsStatus::NoContact;
      res.message = std::string("the ") + to_string(side) + " wheel's normal contact failed: " + to_string(rep.status);
      return res;
    }
    const PatchReport* big = MainPatch(rep);
    st[k].R = setup.roller_radius_m + big->z_contact_rail_m;
    st[k].r = big->rolling_radius_m - big->approach_m;
    st[k].V = in.roller_speed_rad_s[k] * st[k].R;  // paper 000 eq. 13
  }
  res.eq2_wheelset_speed_rad_s = RollerRigEq2WheelsetSpeed(in.roller_speed_rad_s, {st[0].R, st[1].R}, {st[0].r, st[1].r});
  std::array<WheelContactReport, 2> last;
  std::array<double, 2> last_fx{0.0, 0.0}, last_m{0.0, 0.0};
  bool contact_failed = false;
  double last_w3 = 0.0;
  auto evaluate = [&](double w3) {
    ++res.evaluations;
    last_w3 = w3;
    double g = in.axle_torque_Nm;
    for (Side side : {Side::Left, Side::Right}) {
      const int k = side_index(side);
      WheelsetVelocity v;
      v.forward_speed_m_s = st[k].V;
      v.lateral_velocity_m_s = in.lateral_velocity_m_s;
      v.axle_angular_velocity_rad_s = w3;
      WheelContactOptions o = options.contact;
      o.vertical_load_N = st[k].load;
      last[k] = SolveWheelContactCached(geometry, side, side_pose[k], v, o, cache);
      if (!Usable(last[k], o, options.load_acceptance)) contact_failed = true;
      last_fx[k] = SumFx(last[k], &last_m[k]);
      g += last_m[k];
    }
    return g;
  };

  double w3 = 0.0, g = 0.0;
  if (measured || options.eq2_wheelset_speed) {
    w3 = measured ? in.wheelset_speed_rad_s : res.eq2_wheelset_speed_rad_s;
    g = evaluate(w3);
    res.status = RollerRigKinematicsStatus::Measured;
  } else {
    double lo = std::min(st[0].V / st[0].r, st[1].V / st[1].r), hi = std::max(st[0].V / st[0].r, st[1].V / st[1].r);
    double f_lo = evaluate(lo);
    const double scale_lo = std::abs(last_m[0]) + std::abs(last_m[1]);
    double f_hi = hi > lo ? evaluate(hi) : f_lo;
    const double scale_hi = std::abs(last_m[0]) + std::abs(last_m[1]);
    double floor = 0.0;
    for (int k = 0; k < 2; ++k)
      floor += options.contact.effective_friction_law()(0.0) * st[k].load * st[k].r;
    const double tol = options.balance_tolerance * (scale_lo + scale_hi) + 1e-14 * floor;
    // an applied axle torque may put the root outside [lo, hi]: widen by the span (or 1 % of lo) until bracketed
    for (int grow = 0; grow < 30 && (f_lo > 0.0 || f_hi < 0.0); ++grow) {
      const double span = std::max(hi - lo, 0.01 * lo);
      if (f_lo > 0.0) f_lo = evaluate(lo = std::max(lo - span, 0.5 * lo));
      if (f_hi < 0.0) f_hi = evaluate(hi = hi + span);
    }
    if (contact_failed) {
      res.status = RollerRigKinematicsStatus::NotConverged;
      res.message = "a contact solve failed while bracketing the wheelset speed";
    } else if (std::abs(f_lo) <= tol) {
      w3 = lo, g = evaluate(lo);
      res.status = RollerRigKinematicsStatus::Converged;
    } else if (std::abs(f_hi) <= tol) {
      w3 = hi, g = evaluate(hi);
      res.status = RollerRigKinematicsStatus::Converged;
    } else if (f_lo > 0.0 || f_hi < 0.0) {
      res.status = RollerRigKinematicsStatus::NotConverged;
      res.message = "no bracket of the wheelset speed (axle torque beyond the creep-force capacity?)";
      w3 = res.eq2_wheelset_speed_rad_s, g = evaluate(w3);
    } else {
      // first approximation (eq. 2) narrows the bracket, then TOMS 748
      const double w0 = std::clamp(res.eq2_wheelset_speed_rad_s, lo, hi);
      const double g0 = evaluate(w0);
      if (std::abs(g0) <= tol) {
        w3 = w0, g = g0;
      } else {
        if (g0 < 0.0) lo = w0, f_lo = g0; else hi = w0, f_hi = g0;
        // Brent-type bracketing (Boost TOMS 748): robust where g is nearly flat (both contacts sliding) or steps
        // (a contact point jumping between patches); stops when |g| meets the tolerance or the bracket collapses.
        double last_g = g0;
        auto f = [&](double x) { return last_g = evaluate(x); };
        auto done = [&](double a, double b) { return std::abs(last_g) <= tol || std::abs(b - a) <= 1e-13 * std::abs(b); };
        boost::uintmax_t max_iter = static_cast<boost::uintmax_t>(std::max(1, options.max_evaluations - res.evaluations));
        const std::pair<double, double> br = boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, done, max_iter);
        // converged: the last evaluation is the root (its contacts are reported); else the collapsed bracket's middle
        if (std::abs(last_g) <= tol) {
          w3 = last_w3;
        } else {
          w3 = 0.5 * (br.first + br.second);
          f(w3);
        }
        g = last_m[0] + last_m[1] + in.axle_torque_Nm;
      }
      res.status = std::abs(g) <= tol && !contact_failed && res.evaluations <= options.max_evaluations
                       ? RollerRigKinematicsStatus::Converged
                                                         : RollerRigKinematicsStatus::NotConverged;
      if (res.status != RollerRigKinematicsStatus::Converged)
        res.message = contact_failed ? "a contact solve failed during the wheelset-speed root find"
                                     : "wheelset-speed root find did not meet the moment tolerance";
    }
  }
  if (res.status == RollerRigKinematicsStatus::Measured && contact_failed) {
    res.status = RollerRigKinematicsStatus::NotConverged;
    res.message = "a contact solve failed at the measured wheelset speed";
  }
  res.wheelset_speed_rad_s = w3;
  res.axle_moment_residual_Nm = g;
  for (int k = 0; k < 2; ++k) {
    RollerRigContactResult& c = res.contact[k];
    c.report = last[k];
    c.roller_rolling_radius_m = st[k].R;
    c.wheel_rolling_radius_m = st[k].r;
    c.roller_surface_speed_m_s = st[k].V;
    c.eq2_creepage = RollerRigCreepage(in.roller_speed_rad_s[k], st[k].R, w3, st[k].r);
    c.fx_N = last_fx[k];
    c.contact_y_m = st[k].y;
    for (const PatchReport& p : last[k].patches) {
      c.fy_N += p.fy_N;
      c.fn_N += p.fn_N;
    }
    if (const PatchReport* p = MainPatch(last[k])) {
      c.xi = p->xi, c.eta = p->eta, c.phi_per_m = p->phi_per_m;
      // the radii of the final solve (its approach differs from the first normal solve's within the load tolerance)
      c.roller_rolling_radius_m = setup.roller_radius_m + p->z_contact_rail_m;
      c.wheel_rolling_radius_m = p->rolling_radius_m - p->approach_m;
      c.eq2_creepage = RollerRigCreepage(in.roller_speed_rad_s[k], c.roller_rolling_radius_m, w3, c.wheel_rolling_radius_m);
    }
  }
  // Longitudinal springs (quasi-static): force and moment about z of springs and contact forces on the wheelset
  const double S = -(res.contact[0].fx_N + res.contact[1].fx_N);
  const double D = (st[0].y * res.contact[0].fx_N + st[1].y * res.contact[1].fx_N) / setup.spring_half_spacing_m;
  res.spring_force_N = {0.5 * (S - D), 0.5 * (S + D)};
  const double uL = -res.spring_force_N[0] / setup.longitudinal_stiffness_N_per_m;
  const double uR = -res.spring_force_N[1] / setup.longitudinal_stiffness_N_per_m;
  res.longitudinal_displacement_m = 0.5 * (uL + uR);
  res.yaw_deflection_rad = (uR - uL) / (2.0 * setup.spring_half_spacing_m);
  return res;
}

}  // namespace

RollerRigKinematicsResult SolveRollerRigKinematics(const WheelsetTrackGeometry& geometry, const RollerRigSetup& setup,
                                                   const RollerRigKinematicsInput& in,
                                                   const RollerRigKinematicsOptions& options) {
  setup.validate();
  options.validate();
  require_finite(in.lateral_m, "rig lateral shift y");
  require_finite(in.yaw_rad, "rig yaw");
  require_finite(in.lateral_velocity_m_s, "rig lateral velocity");
  if (std::fabs(in.lateral_velocity_m_s) > kMaxRigLateralVelocity_m_s) {  // (1e300 ended as "traction is not finite")
    char text[200];
    std::snprintf(text, sizeof text, "rig lateral velocity = %g m/s is beyond +-%g m/s (unit?)", in.lateral_velocity_m_s,
                  kMaxRigLateralVelocity_m_s);
    throw InputError(text);
  }
  require_finite(in.axle_torque_Nm, "rig axle torque");
  for (int i = 0; i < 2; ++i) {
    require_positive(in.roller_speed_rad_s[i], i == 0 ? "roller 1 speed omega_1" : "roller 2 speed omega_2");
    require_non_negative(in.wheel_load_N[i], i == 0 ? "left wheel load" : "right wheel load");
    RequireWheelLoad(in.wheel_load_N[i], i == 0 ? "left wheel load" : "right wheel load");
  }
  const bool measured = !std::isnan(in.wheelset_speed_rad_s);
  if (measured) require_positive(in.wheelset_speed_rad_s, "measured wheelset speed omega_3");

  try {
    return SolveOnProfiles(geometry, setup, in, options, measured);
  } catch (const InputError& e) {
    // the input was validated above: what a contact solve rejects now is the state of the worn profiles
    RollerRigKinematicsResult res;
    res.status = RollerRigKinematicsStatus::ContactError;
    res.message = std::string("contact solve failed on the current profiles: ") + e.what();
    return res;
  }
}

}  // namespace conforma
