// Rigid two-rail equilibrium of a wheelset: for a given lateral shift and yaw, the vertical position and
// roll for which both wheels touch their rails (smallest vertical separation zero on each side).
#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"
#include "conforma/geometry.hpp"
#include "conforma/root_finding.hpp"

namespace conforma {

EquilibriumResult WheelsetTrackGeometry::SolveRigidEquilibrium(double lateral_m, double yaw_rad,
                                                               const WheelsetPose& guess,
                                                               const EquilibriumOptions& options) const {
  require_finite(lateral_m, "lateral_m");
  require_finite(yaw_rad, "yaw_rad");
  require_finite(guess.vertical_m, "guess.vertical_m");
  require_finite(guess.roll_rad, "guess.roll_rad");
  require_positive(options.tolerance_m, "EquilibriumOptions.tolerance_m");
  EquilibriumResult out;
  WheelsetPose pose = guess;
  pose.lateral_m = lateral_m;
  pose.yaw_rad = yaw_rad;
  // The vertical gap of a wheel grows exactly by dz when the wheelset is lifted by dz, so for a given roll
  // the left wheel touches at z*(phi) = z - g_left(z, phi). The remaining condition is the 1-D root
  // F(phi) = g_right(z*(phi), phi) = 0; F is continuous (a minimum over contact candidates) and decreases
  // with phi (lever about -(track half width)). Secant steps safeguarded by a bracket (Illinois).
  double y_contact;
  auto F = [&](double phi, double* z_star, bool* ok) {
    WheelsetPose p = pose;
    p.roll_rad = phi;
    double gl, gr;
    *ok = MinimumVerticalGap(Side::Left, p, &gl, &y_contact, options.max_touching_contact_angle_rad);
    if (!*ok) return 0.0;
    p.vertical_m -= gl;
    *z_star = p.vertical_m;
    *ok = MinimumVerticalGap(Side::Right, p, &gr, &y_contact, options.max_touching_contact_angle_rad);
    return gr;
  };
  bool ok;
  if (!options.include_roll) {
    // Each wheel is lowered onto its own rail independently (roll held at guess.roll_rad): a single
    // vertical position would leave one wheel with a gap or an interpenetration, and the contact point of a
    // wheel that does not touch is then shifted along the rail normal (by about gap sin(delta) cos(delta)),
    // which made Delta r(-y) differ from -Delta r(y) for a symmetric wheelset by up to 3 mm at the flange.
    double gap[2];
    for (int s = 0; s < 2; ++s) {
      ok = MinimumVerticalGap(s == 0 ? Side::Left : Side::Right, pose, &gap[s], &y_contact,
                              options.max_touching_contact_angle_rad);
      if (!ok) {
        out.pose = pose;
        return out;
      }
    }
    for (int s = 0; s < 2; ++s) {
      const Side side = s == 0 ? Side::Left : Side::Right;
      WheelsetPose lowered = pose;
      lowered.vertical_m -= gap[s];
      out.contact.wheel[s] = RigidContact(side, lowered);
    }
    pose.vertical_m -= gap[0];  // reported pose: the left wheel touching
    out.pose = pose;
    if (out.contact.wheel[0].points.empty() || out.contact.wheel[1].points.empty()) return out;
    out.status = EquilibriumStatus::Converged;
    out.rolling_radius_difference_m =
        out.contact.wheel[0].points.front().rolling_radius_m - out.contact.wheel[1].points.front().rolling_radius_m;
    return out;
  }
  double z0, z1;
  double phi0 = pose.roll_rad;
  double f0 = F(phi0, &z0, &ok);
  if (!ok) {
    out.pose = pose;
    return out;
  }
  out.status = EquilibriumStatus::NotConverged;
  // dF/dphi = (y_right - y_left) of the contact points, about -1.5 m: first secant step from that estimate
  const double slope_estimate = -2.0 * wheel_origin_eta_;
  double phi1 = phi0 - f0 / slope_estimate;
  double f1 = F(phi1, &z1, &ok);
  if (!ok) { phi1 = phi0; f1 = f0; z1 = z0; }
  // bracket
  double a = phi0, fa = f0, za = z0, b = phi1, fb = f1, zb = z1;
  int it = 0;
  for (; it < options.max_iterations && fa * fb > 0; ++it) {  // expand towards the root
    const double step = (b - a) * 1.6;
    a = b; fa = fb; za = zb;
    b = b + (step == 0.0 ? 1e-4 : step);
    fb = F(b, &zb, &ok);
    if (!ok) break;
  }
  double phi = b, fphi = fb, zphi = zb;
  // the true residual F(phi) of the end taken (the Illinois step scales the bracket's stored values): F is a function
  // of phi alone, so its value where the end was evaluated is the value at the end
  double fphi_true = fb, fa_true = fa, fb_true = fb;
  if (ok && fa * fb <= 0) {
    IllinoisBracket bracket(a, fa, b, fb);  // the one root finder's step (root_finding.hpp); z rides along
    for (; it < options.max_iterations; ++it) {
      if (std::abs(bracket.f_low()) < std::abs(bracket.f_high())) {
        phi = bracket.low(); fphi = bracket.f_low(); zphi = za; fphi_true = fa_true;
      } else {
        phi = bracket.high(); fphi = bracket.f_high(); zphi = zb; fphi_true = fb_true;
      }
      if (std::abs(fphi) < options.tolerance_m) break;
      const double c = bracket.FalsePosition();  // regula falsi with the Illinois modification
      double zc;
      const double fc = F(c, &zc, &ok);
      if (!ok) break;
      const bool on_low_side = !(fc * bracket.f_high() > 0);
      bracket.Replace(c, fc, on_low_side);
      (on_low_side ? za : zb) = zc;
      (on_low_side ? fa_true : fb_true) = fc;
      if (std::abs(bracket.high() - bracket.low()) < 1e-15) break;
    }
  }
  if (ok && std::abs(fphi_true) < options.tolerance_m) out.status = EquilibriumStatus::Converged;
  out.iterations = it;
  pose.roll_rad = phi;
  pose.vertical_m = zphi;
  out.pose = pose;
  out.contact = RigidContacts(pose);
  if (out.contact.wheel[0].points.empty() || out.contact.wheel[1].points.empty()) {
    out.status = EquilibriumStatus::NoContact;
    return out;
  }
  out.rolling_radius_difference_m =
      out.contact.wheel[0].points.front().rolling_radius_m - out.contact.wheel[1].points.front().rolling_radius_m;
  return out;
}

}  // namespace conforma
