// The wear loop of the simulation layer with the caller's own contact and kinematics functions (issue 12): this
// program links only Conforma::simulation and never calls SolveWheelContact. The contact is a fixed elliptic patch
// (semi-axes a along x, b across) at the rigid contact point of each wheel, with a parabolic pressure carrying the
// wheel load and full-slip traction mu p opposing a constant small longitudinal slip; the kinematics are one
// centred wheelset per track class. Checks (exit status 1 with a message when one fails):
//   - both wheel steps complete, every wheel contact is used (none failed), the wear is > 0;
//   - each step removes exactly the scenario's depth cap (the step length is chosen for that; one sub-step per step);
//   - the removed depth lies where the patch was: its maximum within the patch's lateral extent (plus the
//     smoothing), and next to nothing far from it.
// Usage: link_simulation_own_contact SCENARIO.yaml   (tests/link/CMakeLists.txt: scenarios/default_metro.yaml)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>

#include "conforma/error.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

using namespace conforma;

namespace {

constexpr double kSemiAxisX = 6e-3;  // a [m]
constexpr double kSemiAxisS = 4e-3;  // b [m]
constexpr double kSlip = 2e-3;       // constant longitudinal slip (slip velocity / V)
constexpr int kCells = 20;           // cells per semi-axis

// Wheel-profile y of the patch centres of the current wheel step (reset after each step's checks), and the count of
// contacts over the run.
std::mutex patch_mutex;
double step_patch_y_min = HUGE_VAL, step_patch_y_max = -HUGE_VAL;
int contacts = 0;

WheelContactReport OwnContact(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                              const WheelsetVelocity& /*velocity*/, const WheelContactOptions& options) {
  WheelContactReport report;
  report.side = side;
  report.model = options.model;
  report.pose = pose;
  const WheelContactResult rigid = geometry.RigidContact(side, pose);
  if (rigid.points.empty()) return report;  // NoContact
  const RigidContactPoint& cp = rigid.points.front();

  const double load = options.vertical_load_N;
  const double p0 = 2.0 * load / (M_PI * kSemiAxisX * kSemiAxisS);  // parabolic: integral = p0 pi a b / 2
  const double dx = kSemiAxisX / kCells, ds = kSemiAxisS / kCells;
  PatchReport patch;
  patch.model = options.model;
  patch.normal_status = patch.tangential_status = "own";
  patch.a_m = kSemiAxisX;
  patch.b_m = kSemiAxisS;
  patch.contact_angle_rad = cp.contact_angle_rad;
  patch.y_contact_rail_m = cp.rail_profile_m.x();
  patch.z_contact_rail_m = cp.rail_profile_m.y();
  patch.y_contact_wheel_m = cp.wheel_profile_m.x();
  patch.rolling_radius_m = cp.rolling_radius_m;
  patch.lead_m = cp.lead_m;
  patch.reference_s_on_rail_m = cp.rail_s_m;
  for (int i = -kCells; i < kCells; ++i) {
    for (int j = -kCells; j < kCells; ++j) {
      const double x = (i + 0.5) * dx, s = (j + 0.5) * ds;
      const double r2 = (x * x) / (kSemiAxisX * kSemiAxisX) + (s * s) / (kSemiAxisS * kSemiAxisS);
      if (r2 >= 1.0) continue;
      ContactCell c;
      c.x_m = x;
      c.s_m = s;
      c.rail_s_m = cp.rail_s_m + s;
      c.wheel_y_m = cp.wheel_profile_m.x() + s;
      c.area_m2 = dx * ds;
      c.length_x_m = dx;
      c.pressure_Pa = p0 * (1.0 - r2);
      c.slip_x = kSlip;
      c.traction_x_Pa = -options.friction_coefficient * c.pressure_Pa;  // full slip, opposing the slip
      c.in_slip = true;
      patch.fn_N += c.pressure_Pa * c.area_m2;
      patch.fx_N += c.traction_x_Pa * c.area_m2;
      patch.pmax_Pa = std::max(patch.pmax_Pa, c.pressure_Pa);
      patch.area_m2 += c.area_m2;
      patch.slip_area_m2 += c.area_m2;
      patch.cells.push_back(c);
    }
  }
  patch.vertical_force_N = patch.fn_N;
  report.vertical_force_N = report.pressure_vertical_force_N = patch.fn_N;
  report.patches.push_back(std::move(patch));
  report.status = WheelContactStatus::Ok;
  std::lock_guard<std::mutex> lock(patch_mutex);
  ++contacts;
  step_patch_y_min = std::min(step_patch_y_min, cp.wheel_profile_m.x());
  step_patch_y_max = std::max(step_patch_y_max, cp.wheel_profile_m.x());
  return report;
}

// One centred, unyawed wheelset per class, rolling freely at the class speed, static wheel loads.
KinematicsFunction CentredWheelset(const Scenario& scenario) {
  return [&scenario](const WheelsetTrackGeometry& /*geometry*/, const TrackClass& track_class, int /*class_index*/) {
    KinematicsSeries series;
    series.source = "own centred wheelset";
    KinematicsSample k;
    const double v = track_class.speed_m_s, r0 = scenario.vehicle.nominal_wheel_radius_m;
    k.velocity = {v, 0.0, 0.0, v / r0};
    k.vertical_load_N[0] = k.vertical_load_N[1] = scenario.vehicle.static_wheel_load_N();
    series.samples.push_back(k);
    return series;
  };
}

int failures = 0;
void Check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

// Checks of one wheel step, called by the wear loop right after the step (WearSimulationOptions::on_step).
void CheckStep(const Profile& wheel_before, const WearStepRecord& s) {
  const std::string step = "step " + std::to_string(s.step) + ": ";
  Check(s.samples > 0 && s.failed_contacts == 0 && s.hertz_fallback_contacts == 0,
        step + std::to_string(s.samples) + " samples, " + std::to_string(s.failed_contacts) + " failed contacts");
  Check(s.step_km > 0.0 && s.wheel_depth_per_metre.max_depth_m() > 0.0, step + "wear produced");
  Check(s.depth_cap_m > 0.0 && std::fabs(s.max_depth_m - s.depth_cap_m) <= 1e-9 * s.depth_cap_m,
        step + "max removed depth " + std::to_string(s.max_depth_m * 1e3) + " mm = cap " +
            std::to_string(s.depth_cap_m * 1e3) + " mm");
  // where the removed depth is (its grid follows the arc length of the profile the step started from): the
  // wheel-profile y of its maximum, and the largest depth far from this step's patches
  std::lock_guard<std::mutex> lock(patch_mutex);
  const double lo = step_patch_y_min - kSemiAxisS, hi = step_patch_y_max + kSemiAxisS;  // the patches' extent
  const double smoothing = 2e-3, reach = 10e-3;
  const WearDistribution& d = s.removed_depth;
  size_t imax = 0;
  double far = 0.0;
  for (size_t i = 0; i < d.size(); ++i) {
    if (d.depth_m[i] > d.depth_m[imax]) imax = i;
    const double y = wheel_before.position(d.s(i)).x();
    if (y < lo - reach || y > hi + reach) far = std::max(far, d.depth_m[i]);
  }
  const double y_max = wheel_before.position(d.s(imax)).x();
  Check(y_max >= lo - smoothing && y_max <= hi + smoothing,
        step + "deepest wear at wheel y = " + std::to_string(y_max * 1e3) + " mm, patches between " +
            std::to_string(lo * 1e3) + " and " + std::to_string(hi * 1e3) + " mm");
  Check(far <= 0.01 * s.max_depth_m, step + "largest depth more than " + std::to_string(reach * 1e3) +
                                         " mm outside the patches: " + std::to_string(far * 1e6) + " um");
  step_patch_y_min = HUGE_VAL;
  step_patch_y_max = -HUGE_VAL;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENARIO.yaml\n", argv[0]);
    return 2;
  }
  try {
    Scenario scenario = LoadScenario(argv[1]);
    scenario.update.substeps = 1;  // one update per step, so that a step removes exactly the cap (§8.12)
    WearSimulationOptions options;
    options.contact.model = ContactModel::Hertz;  // only a label here: the contact function above ignores it
    options.steps = 2;
    options.total_km = 0.0;  // no distance limit: each step removes the depth cap
    Profile wheel_before = scenario.wheel;
    options.on_step = [&wheel_before](const WearStepRecord& s) {
      CheckStep(wheel_before, s);
      wheel_before = s.wheel;
    };
    const WearSimulationResult r = RunWearSimulation(scenario, options, &OwnContact, CentredWheelset(scenario));

    Check(r.status == WearSimulationStatus::Completed && r.steps.size() == 2,
          std::string("two wheel steps completed (status ") + to_string(r.status) + ", " +
              std::to_string(r.steps.size()) + " steps; " + r.message + ")");
    Check(contacts > 0, "the own contact function was called " + std::to_string(contacts) + " times");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("%s\n", failures == 0 ? "PASSED" : "FAILED");
  return failures == 0 ? 0 : 1;
}
