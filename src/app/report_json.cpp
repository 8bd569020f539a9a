#include "report_json.hpp"

#include <cstdio>

#include "conforma/geometry.hpp"

namespace conforma::cli {

nlohmann::json ToJson(const PatchReport& p) {
  return {{"normal_status", p.normal_status},   {"tangential_status", p.tangential_status},
          {"fn_N", p.fn_N},                     {"fx_N", p.fx_N},
          {"fy_N", p.fy_N},                     {"mz_Nm", p.mz_Nm},
          {"pmax_Pa", p.pmax_Pa},               {"p0_Pa", p.p0_Pa},
          {"area_m2", p.area_m2},               {"a_m", p.a_m},
          {"b_m", p.b_m},                       {"width_m", p.width_m},
          {"length_m", p.length_m},             {"approach_m", p.approach_m},
          {"contact_angle_rad", p.contact_angle_rad}, {"y_contact_rail_m", p.y_contact_rail_m},
          {"z_contact_rail_m", p.z_contact_rail_m}, {"y_contact_wheel_m", p.y_contact_wheel_m},
          {"rolling_radius_m", p.rolling_radius_m}, {"lead_m", p.lead_m},
          {"xi", p.xi},                         {"eta", p.eta},
          {"phi_per_m", p.phi_per_m},           {"alpha_c_deg", p.alpha_c_deg},
          {"is_conformal", p.is_conformal},     {"adhesion_area_m2", p.adhesion_area_m2},
          {"slip_area_m2", p.slip_area_m2},     {"frictional_power_W", p.frictional_power_W},
          {"vertical_force_N", p.vertical_force_N}, {"lateral_force_N", p.lateral_force_N},
          {"model", to_string(p.model)},          {"auto_alpha_c_deg", p.auto_alpha_c_deg}};
}

nlohmann::json ToJson(const WheelContactReport& r) {
  nlohmann::json patches = nlohmann::json::array();
  for (const PatchReport& p : r.patches) patches.push_back(ToJson(p));
  return {{"side", to_string(r.side)},
          {"model", to_string(r.model)},
          {"status", to_string(r.status)},
          {"pose", {{"y_m", r.pose.lateral_m}, {"z_m", r.pose.vertical_m}, {"roll_rad", r.pose.roll_rad},
                    {"yaw_rad", r.pose.yaw_rad}}},
          {"vertical_force_N", r.vertical_force_N},
          {"pressure_vertical_force_N", r.pressure_vertical_force_N},
          {"lateral_force_N", r.lateral_force_N},
          {"load_iterations", r.load_iterations},
          {"patches", patches}};
}

void PrintPatchTableHeader(std::ostream& out) {
  out << "   case   patch y_cp_rail[mm] angle[rad] r_roll[mm] Fn[kN]  pmax[MPa] area[mm2] width[mm] alpha_c[deg]"
         "  Fx[kN]  Fy[kN] Mz[Nm]\n";
}

void PrintPatchRow(std::ostream& out, const std::string& label, const PatchReport& p) {
  char line[256];
  std::snprintf(line, sizeof line, "%8s %5s %12.3f %10.4f %10.2f %7.2f %9.1f %9.2f %9.2f %12.1f %7.3f %7.3f %6.2f\n",
                label.c_str(), p.is_conformal ? "conf" : "", p.y_contact_rail_m * 1e3, p.contact_angle_rad,
                p.rolling_radius_m * 1e3, p.fn_N * 1e-3, p.pmax_Pa * 1e-6, p.area_m2 * 1e6, p.width_m * 1e3,
                p.alpha_c_deg, p.fx_N * 1e-3, p.fy_N * 1e-3, p.mz_Nm);
  out << line;
}

}  // namespace conforma::cli
