#include "report_json.hpp"

#include <cstdio>
#include <type_traits>

#include "conforma/geometry.hpp"
#include "conforma/wheel_contact_fields.hpp"

namespace conforma::cli {

// The keys and values of the field tables (conforma/wheel_contact_fields.hpp).
nlohmann::json ToJson(const PatchReport& p) {
  nlohmann::json out = nlohmann::json::object();
  VisitPatchFields(p, [&out](const char* key, const auto& value) { out[key] = value; });
  return out;
}

nlohmann::json ToJson(const WheelContactReport& r) {
  nlohmann::json out = nlohmann::json::object();
  VisitWheelReportFields(r, [&out](const char* key, const auto& value) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, WheelsetPose>) {
      nlohmann::json pose = nlohmann::json::object();
      VisitPoseFields(value, [&pose](const char* pose_key, double x) { pose[pose_key] = x; });
      out[key] = pose;
    } else {
      out[key] = value;
    }
  });
  nlohmann::json patches = nlohmann::json::array();
  for (const PatchReport& p : r.patches) patches.push_back(ToJson(p));
  out["patches"] = patches;
  return out;
}

void PrintPatchTableHeader(std::ostream& out, const std::string& label_name) {
  char line[320];
  std::snprintf(line, sizeof line,
                "%8s %9s %9s %12s %10s %10s %7s %9s %9s %9s %12s %7s %7s %6s\n", label_name.c_str(), "model",
                "conformal", "y_rail[mm]", "delta[rad]", "r_roll[mm]", "Fn[kN]", "pmax[MPa]", "area[mm2]",
                "width[mm]", "alpha_c[deg]", "Fx[kN]", "Fy[kN]", "Mz[Nm]");
  out << line
      << "   (conformal: alpha_c above the conformity threshold; y_rail: contact point on the rail profile; delta: "
         "contact angle, + gauge side; r_roll: rolling radius; Fn, Fx, Fy, Mz: normal force, creep forces along x "
         "and the rail profile, spin moment on the wheel)\n";
}

void PrintPatchRow(std::ostream& out, const std::string& label, const PatchReport& p) {
  char line[320];
  std::snprintf(line, sizeof line,
                "%8s %9s %9s %12.3f %10.4f %10.2f %7.2f %9.1f %9.2f %9.2f %12.1f %7.3f %7.3f %6.2f\n",
                label.c_str(), to_string(p.model), p.is_conformal ? "yes" : "no", p.y_contact_rail_m * 1e3,
                p.contact_angle_rad, p.rolling_radius_m * 1e3, p.fn_N * 1e-3, p.pmax_Pa * 1e-6, p.area_m2 * 1e6,
                p.width_m * 1e3, p.alpha_c_deg, p.fx_N * 1e-3, p.fy_N * 1e-3, p.mz_Nm);
  out << line;
}

void PrintWarnings(std::ostream& out, const std::string& label, const WheelContactReport& report) {
  for (const std::string& warning : report.warnings) out << "warning: " << label << ": " << warning << "\n";
}

}  // namespace conforma::cli
