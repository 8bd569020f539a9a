// conforma contact: the contact of one wheelset pose (both wheels or one), any model, table or JSON.
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli_checks.hpp"
#include "cli_setup.hpp"
#include "commands.hpp"
#include "contact_status.hpp"
#include "conforma/error.hpp"
#include "contact_fields_export.hpp"
#include "report_json.hpp"

namespace conforma::cli {

namespace {
struct ContactCommand {
  TrackArgs track;
  ContactArgs contact;
  double y_mm = 0.0, yaw_mrad = 0.0, approach_mm = 0.05;
  std::optional<double> roll_mrad;
  std::string side = "both";
  std::optional<double> xi, eta, phi_per_m;
  bool json = false;
  ContactFieldsArgs fields;  // --fields DIR, --fields-format

  void run() const {
    const auto geometry = track.make_geometry();
    WheelContactOptions options = contact.options();
    fields.check_writable();  // before solving
    options.keep_fields = fields.enabled();
    require_finite(y_mm, "--y-mm");
    RequireWheelsetYaw(yaw_mrad * 1e-3, "option --yaw-mrad");
    RequireApproach(approach_mm * 1e-3, "option --approach-mm (in m)");
    if (xi || eta || phi_per_m) {
      options.creepages_given = true;
      options.creepages = {xi.value_or(0.0), eta.value_or(0.0), phi_per_m.value_or(0.0)};
    }
    // vertical position and roll: rigid contact of both wheels unless the roll is given
    const EquilibriumResult eq = geometry->SolveRigidEquilibrium(y_mm * 1e-3, yaw_mrad * 1e-3);
    if (eq.status == EquilibriumStatus::NoContact) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "no rigid contact of the wheelset at --y-mm %.6g, --yaw-mrad %.6g: the wheels do not reach the "
                    "rails (check the lateral shift and yaw, the gauge and flange-back distance, and the profiles)",
                    y_mm, yaw_mrad);
      throw InputError(text);
    }
    WheelsetPose pose = eq.pose;
    if (roll_mrad) {
      require_finite(*roll_mrad, "--roll-mrad");
      pose.roll_rad = *roll_mrad * 1e-3;
    }
    if (options.vertical_load_N < 0.0) pose.vertical_m -= approach_mm * 1e-3;  // approach mode
    const double r0 = geometry->setup().nominal_radius_m[0];
    const WheelsetVelocity velocity = contact.rolling_velocity(r0);
    nlohmann::json out = {{"model", contact.model}, {"wheels", nlohmann::json::array()}};
    if (fields.enabled()) out["fields_files"] = nlohmann::json::array();
    if (!json) {
      std::cout << "conforma contact: wheel " << track.wheel << " on rail " << track.rail << ", model " << contact.model
                << ", y = " << y_mm << " mm, yaw = " << yaw_mrad << " mrad, roll = " << pose.roll_rad * 1e3
                << " mrad\n";
      PrintPatchTableHeader(std::cout, "wheel");
    }
    std::vector<WheelContactReport> reports;  // for the status check after the output
    for (Side s : {Side::Left, Side::Right}) {
      if (side != "both" && side != to_string(s)) continue;
      const WheelContactReport r = SolveWheelContact(*geometry, s, pose, velocity, options);
      reports.push_back(r);
      for (const std::string& file : fields.write(r, std::cerr)) out["fields_files"].push_back(file);
      if (json) {
        out["wheels"].push_back(ToJson(r));
      } else {
        if (r.patches.empty() && r.status == WheelContactStatus::NoContact && options.vertical_load_N <= 0.0)
          std::cout << "   " << to_string(s) << ": " << to_string(r.status) << "\n";
        for (const PatchReport& p : r.patches) PrintPatchRow(std::cout, to_string(s), p);
        PrintWheelStatus(std::cout, r, options.vertical_load_N);
      }
      PrintWarnings(std::cerr, std::string(to_string(s)) + " wheel", r);  // also in the JSON ("warnings")
    }
    if (json) std::cout << out.dump(2) << "\n";
    std::cout.flush();
    ThrowIfIncomplete(reports, options.vertical_load_N);
  }
};
}  // namespace

void RegisterContactCommand(CLI::App& app) {
  auto cmd = std::make_shared<ContactCommand>();
  CLI::App* sub = app.add_subcommand("contact", "contact patches of one wheelset pose");
  cmd->track.add_to(sub);
  cmd->contact.add_to(sub);
  sub->add_option("--y-mm", cmd->y_mm, "lateral shift of the wheelset (+ towards the left rail)");
  sub->add_option("--yaw-mrad", cmd->yaw_mrad, "yaw angle");
  sub->add_option("--roll-mrad", cmd->roll_mrad, "roll angle (default: rigid contact on both rails)");
  sub->add_option("--approach-mm", cmd->approach_mm, "push-down below rigid contact when --load-N < 0");
  sub->add_option("--side", cmd->side, "left, right or both")->check(CLI::IsMember({"left", "right", "both"}));
  sub->add_option("--xi", cmd->xi, "given longitudinal creepage (instead of the kinematics)");
  sub->add_option("--eta", cmd->eta, "given lateral creepage");
  sub->add_option("--phi-per-m", cmd->phi_per_m, "given spin creepage [1/m]");
  sub->add_flag("--json", cmd->json, "machine-readable output");
  cmd->fields.add_to(sub);
  sub->callback([cmd]() { cmd->run(); });
}

}  // namespace conforma::cli
