// conforma sweep: the wheelset over a lateral sweep (the default main job: S1002 on 60E1 at 1:40), one row per
// contact patch of the chosen wheel, for one or more models; --csv for a machine-readable table.
#include <cstdio>
#include <iostream>

#include "cli_checks.hpp"
#include "cli_setup.hpp"
#include "commands.hpp"
#include "conforma/error.hpp"
#include "contact_status.hpp"
#include "exit_status.hpp"
#include "report_json.hpp"

namespace conforma::cli {

namespace {
struct SweepCommand {
  TrackArgs track;
  ContactArgs contact;
  double from_mm = -8.0, to_mm = 10.0, step_mm = 1.0, yaw_per_y_mrad_per_mm = 0.0;
  std::string models = "hertz,kp,conformal";
  std::string side = "left";
  bool csv = false;

  void run() {
    require_finite(from_mm, "--from-mm");
    require_finite(to_mm, "--to-mm");
    require_positive(step_mm, "--step-mm");
    const std::vector<std::string> names = SplitCommaList(models, "--models");
    if (names.empty()) throw InputError("option --models: no contact model given");
    if (to_mm < from_mm) throw InputError("option --to-mm must be >= --from-mm");
    require_finite(yaw_per_y_mrad_per_mm, "--yaw-per-y");
    RequireWheelsetYaw(yaw_per_y_mrad_per_mm * from_mm * 1e-3, "option --yaw-per-y x --from-mm");
    RequireWheelsetYaw(yaw_per_y_mrad_per_mm * to_mm * 1e-3, "option --yaw-per-y x --to-mm");
    // at most 100,000 poses (a sweep of 1e-9 mm steps asked for 1.8e10 and ran until killed)
    constexpr double kMaxSweepPoses = 1e5;
    if ((to_mm - from_mm) / step_mm + 1.0 > kMaxSweepPoses) {
      char text[200];
      std::snprintf(text, sizeof text, "--from-mm .. --to-mm by --step-mm gives %.6g poses, more than %.0f",
                    (to_mm - from_mm) / step_mm + 1.0, kMaxSweepPoses);
      throw InputError(text);
    }
    const auto geometry = track.make_geometry();
    std::vector<WheelContactOptions> model_options;  // built and validated once per model
    for (const std::string& m : names) {
      ContactArgs c = contact;
      c.model = m;
      model_options.push_back(c.options());  // InputError for an unknown model
    }
    const Side s = side == "right" ? Side::Right : Side::Left;
    const WheelsetVelocity velocity = contact.rolling_velocity(geometry->setup().nominal_radius_m[0]);
    if (csv) {
      std::cout << "model,y_mm,yaw_mrad,delta_r_mm,patch,y_cp_rail_mm,contact_angle_rad,rolling_radius_mm,fn_N,pmax_MPa,"
                   "area_mm2,width_mm,alpha_c_deg,is_conformal,fx_N,fy_N,mz_Nm,wheel_status\n";
    } else {
      std::cout << "conforma sweep: wheel " << track.wheel << " on rail " << track.rail << " ("
                << (track.inclination.empty() ? "default inclination" : track.inclination) << "), " << side
                << " wheel, " << contact.load_N * 1e-3 << " kN, V = " << contact.speed_m_s << " m/s, mu = "
                << contact.friction << "\n";
    }
    WheelsetPose guess;
    std::vector<WheelContactReport> reports;  // every wheel solved, for the status check after the table
    std::vector<double> no_rigid_contact;      // y [mm] of the poses without rigid contact
    for (int k = 0; from_mm + k * step_mm <= to_mm + 1e-9; ++k) {
      const double y_mm = from_mm + k * step_mm, yaw_mrad = yaw_per_y_mrad_per_mm * y_mm;
      const EquilibriumResult eq = geometry->SolveRigidEquilibrium(y_mm * 1e-3, yaw_mrad * 1e-3, guess);
      if (eq.status == EquilibriumStatus::NoContact) {
        no_rigid_contact.push_back(y_mm);
        if (!csv) std::cout << "y = " << y_mm << " mm: no rigid contact\n";
        for (const std::string& name : names)  // the CSV names the pose too (it had the header only)
          if (csv) std::cout << name << ',' << y_mm << ',' << yaw_mrad << ",,,,,,,,,,,,,,," << "no_rigid_contact\n";
        continue;
      }
      guess = eq.pose;
      if (!csv) {
        char head[160];
        std::snprintf(head, sizeof head, "\ny = %+.2f mm, yaw = %.2f mrad, roll = %.4f mrad, delta_r = %.4f mm\n", y_mm,
                      yaw_mrad, eq.pose.roll_rad * 1e3, eq.rolling_radius_difference_m * 1e3);
        std::cout << head;
        PrintPatchTableHeader(std::cout);
      }
      for (size_t m = 0; m < names.size(); ++m) {
        const std::string& name = names[m];
        const WheelContactReport r = SolveWheelContact(*geometry, s, eq.pose, velocity, model_options[m]);
        reports.push_back(r);
        if (r.patches.empty() && !csv) std::cout << std::string(8 - std::min<size_t>(8, name.size()), ' ') << name
                                                 << ": " << to_string(r.status) << "\n";
        if (r.patches.empty() && csv)
          std::cout << name << ',' << y_mm << ',' << yaw_mrad << ',' << eq.rolling_radius_difference_m * 1e3
                    << ",,,,,,,,,,,,,," << to_string(r.status) << '\n';
        int j = 0;
        for (const PatchReport& p : r.patches) {
          if (csv) {
            std::cout << name << ',' << y_mm << ',' << yaw_mrad << ',' << eq.rolling_radius_difference_m * 1e3 << ','
                      << j++ << ',' << p.y_contact_rail_m * 1e3 << ',' << p.contact_angle_rad << ','
                      << p.rolling_radius_m * 1e3 << ',' << p.fn_N << ',' << p.pmax_Pa * 1e-6 << ','
                      << p.area_m2 * 1e6 << ',' << p.width_m * 1e3 << ',' << p.alpha_c_deg << ',' << p.is_conformal
                      << ',' << p.fx_N << ',' << p.fy_N << ',' << p.mz_Nm << ',' << to_string(r.status) << '\n';
          } else {
            PrintPatchRow(std::cout, name, p);
          }
        }
        if (!csv) PrintWheelStatus(std::cout, r, contact.load_N);
        PrintWarnings(std::cerr, name + " at y = " + std::to_string(y_mm) + " mm", r);
      }
    }
    std::cout.flush();
    ThrowIfIncomplete(reports, contact.load_N);  // the table is complete; a non-converged wheel is exit 4
    if (!no_rigid_contact.empty()) {
      char text[240];
      std::snprintf(text, sizeof text,
                    "no rigid contact of the wheelset at %zu of the poses (y = %g ... %g mm): the wheels do not reach "
                    "the rails there (rows with wheel_status no_rigid_contact)",
                    no_rigid_contact.size(), no_rigid_contact.front(), no_rigid_contact.back());
      throw IncompleteResult(ExitCode::PartialResult, text);
    }
  }
};
}  // namespace

void RegisterSweepCommand(CLI::App& app) {
  auto cmd = std::make_shared<SweepCommand>();
  CLI::App* sub = app.add_subcommand("sweep", "lateral sweep of a wheelset: contact patches per model");
  cmd->track.add_to(sub);
  cmd->contact.add_to(sub);
  sub->add_option("--from-mm", cmd->from_mm, "first lateral shift");
  sub->add_option("--to-mm", cmd->to_mm, "last lateral shift");
  sub->add_option("--step-mm", cmd->step_mm, "step of the lateral shift");
  sub->add_option("--yaw-per-y", cmd->yaw_per_y_mrad_per_mm, "yaw angle per lateral shift [mrad/mm]");
  sub->add_option("--models", cmd->models, "comma-separated models (hertz,kp,kpec,conformal,reference)");
  sub->add_option("--side", cmd->side, "left or right wheel")->check(CLI::IsMember({"left", "right"}));
  sub->add_flag("--csv", cmd->csv, "CSV table instead of the report");
  sub->callback([cmd]() { cmd->run(); });
}

}  // namespace conforma::cli
