// Plausibility warnings of one wheel's contact (contact_plausibility.hpp; limits: docs/physics-reference.md §13).
#include "conforma/contact_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace conforma {

namespace {
template <class... Args>
std::string Format(const char* format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);  // the whole message, never truncated
  std::string text(n > 0 ? static_cast<size_t>(n) : 0u, '\0');
  if (n > 0) std::snprintf(text.data(), text.size() + 1, format, args...);
  return text;
}
}  // namespace

std::vector<std::string> ContactPlausibilityWarnings(const WheelContactReport& report,
                                                     const WheelsetTrackGeometry& geometry,
                                                     const WheelContactOptions& options) {
  std::vector<std::string> out;
  // friction: the constant mu, or the law's static value mu(0)
  const bool law = !options.friction_law.is_constant();
  const double mu = law ? options.friction_law.static_value() : options.friction_coefficient;
  if (!IsPlausibleFriction(mu))
    out.push_back(Format("friction_coefficient: %s = %g is outside the plausible range %g to %g of wheel-rail "
                         "contact (dry steel ~0.3-0.6, wet or contaminated down to ~0.05); check --mu",
                         law ? "the friction law's static value mu(0)" : "the friction coefficient mu", mu,
                         kMinPlausibleFriction, kMaxPlausibleFriction));
  if (report.status == WheelContactStatus::NotConverged) {
    const double consistency = report.pressure_vertical_force_N - report.candidate_load_N;
    if (options.load_balance == LoadBalance::TotalConsistent && report.candidate_searches > 1 &&
        !report.patches.empty() &&
        std::fabs(consistency) > std::max(options.load_tolerance, kCandidateLoadTolerance) * options.vertical_load_N)
      // docs/physics-reference.md §3.6.1 step 4: the patches' candidates were found for another load than the one
      // the pressure forces carry
      out.push_back(Format("candidates_not_consistent: the contact candidates were found for %.1f N, the pressure "
                           "forces carry %.1f N (%+.3f %% of the wheel load) after %d candidate searches (no fixed "
                           "point: the patches change with the candidates' load); the solution nearest to one is "
                           "reported",
                           report.candidate_load_N, report.pressure_vertical_force_N,
                           100.0 * consistency / options.vertical_load_N, report.candidate_searches));
    if (options.vertical_load_N >= 0.0 && !report.patches.empty()) {
      // the balanced force (WheelContactOptions::load_balance): the total vertical force by default
      const bool total = BalancesTotalVerticalForce(options);
      const double carried = BalancedVerticalForce(report, options);
      out.push_back(Format("load_not_converged: load control did not converge: the patches carry %.1f N (%s) of "
                           "the wheel load %.1f N (%.2f %%) after %d evaluations; the forces are those of the last "
                           "iterate",
                           carried, total ? "total vertical force, pressure and creep forces" : "pressure forces",
                           options.vertical_load_N, 100.0 * carried / options.vertical_load_N,
                           report.load_iterations));
    } else
      out.push_back(Format("load_not_converged: load control found no push-down that carries the wheel load "
                           "%.1f N; no patch is reported",
                           options.vertical_load_N));
  }
  const double r0 = geometry.NominalRadius(report.side);
  for (size_t j = 0; j < report.patches.size(); ++j) {
    const PatchReport& p = report.patches[j];
    // rolling radius on the tread: r = r0 + z_wheel(y_c) (profile.hpp: wheel z above the taping line)
    const double offset = p.rolling_radius_m - r0;
    if (std::fabs(p.contact_angle_rad) <= kTreadContactAngleRad && std::fabs(offset) > kMaxTreadRadiusOffsetM) {
      // the profile's height at the taping line (y = 0): near 0 when its z origin is right; then a flat patch this
      // far from r0 lies off the tread (flange tip or back: the wheelset has run past flange contact), and a z shift
      // would be the wrong advice (fuzzing, session 24: y = 30 mm)
      double z_taping = 0.0;
      if (geometry.WheelProfileAt(report.side, 0.0, &z_taping, nullptr, nullptr) &&
          std::fabs(z_taping) <= kMaxTreadRadiusOffsetM) {
        out.push_back(Format(
            "nominal_radius: patch %zu is flat (contact angle %.1f deg) but at wheel-profile y = %.1f mm, %.1f mm "
            "above the taping line (rolling radius %.1f mm, r0 = %.1f mm): it lies off the tread, on the flange tip "
            "or back, while the profile's z origin is at the taping line (z = %+.1f mm at y = 0): the wheelset is "
            "beyond flange contact (lateral shift or yaw too large: derailed)",
            j, p.contact_angle_rad * 180.0 / M_PI, p.y_contact_wheel_m * 1e3, offset * 1e3, p.rolling_radius_m * 1e3,
            r0 * 1e3, z_taping * 1e3));
      } else {
        const std::string creepage =
            options.creepages_given ? "" : Format("; the axle rolling at V / r0 gives xi = %.4f here", p.xi);
        out.push_back(Format(
            "nominal_radius: patch %zu is on the tread (contact angle %.1f deg) at wheel-profile y = %.1f mm, where "
            "the rolling radius r0 + z_wheel = %.1f mm is %+.1f mm from the nominal radius r0 = %.1f mm (limit "
            "%.0f mm): the wheel profile's z origin is not at the taping line (z_wheel = %+.1f mm on the tread)%s. "
            "Shift the wheel profile's z by %+.1f mm so that z = 0 at the taping line (--wheel-z-shift-mm) and give the wheel's taping-line radius as the "
            "nominal radius (--r0-mm); --r0-mm alone does not help, the rolling radius is r0 + z_wheel",
            j, p.contact_angle_rad * 180.0 / M_PI, p.y_contact_wheel_m * 1e3, p.rolling_radius_m * 1e3, offset * 1e3,
            r0 * 1e3, kMaxTreadRadiusOffsetM * 1e3, offset * 1e3, creepage.c_str(), -offset * 1e3));
      }
    }
    if (p.pmax_Pa > kMaxPlausiblePressurePa)
      out.push_back(Format("pressure_limit: patch %zu has a maximum pressure of %.0f MPa, above %.0f MPa (4 x the "
                           "shakedown limit of rail steel, docs/physics-reference.md §13): the half-space "
                           "solution is meaningless here; usually a noisy, truncated or sharp-edged profile (smooth "
                           "it) or an extreme load",
                           j, p.pmax_Pa * 1e-6, kMaxPlausiblePressurePa * 1e-6));
  }
  return out;
}

}  // namespace conforma
