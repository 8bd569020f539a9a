// Output files of a wear run (wear_output.hpp).
#include "wear_output.hpp"

#include "conforma/dynamic_kinematics.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "conforma/error.hpp"
#include "exit_status.hpp"
#include "conforma/profile_io.hpp"

namespace conforma::cli {

std::string Num3(int i) {
  char b[16];
  std::snprintf(b, sizeof b, "%03d", i);
  return b;
}

namespace {

std::string StepTag(const WearStepRecord& s) {
  return (s.rail_step > 0 ? "r" + Num3(s.rail_step) + "_" : std::string()) + "step_" + Num3(s.step);
}

void SaveBoth(const Profile& p, const std::string& base) {
  SaveProfileSimpack(p, base + (p.kind() == ProfileKind::Wheel ? ".prw" : ".prr"));
  SaveProfileCsv(p, base + ".csv");
}

}  // namespace

void BeginWearOutput(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create output folder: " + ec.message());
}

void WriteWearStep(const std::string& dir, const WearStepRecord& s) {
  const std::string tag = StepTag(s);
  SaveBoth(s.wheel, dir + "/wheel_" + tag);
  std::ofstream out(dir + "/wear_" + tag + ".csv");
  if (!out) throw InputError(dir + "/wear_" + tag + ".csv: cannot write");
  out << "# wear distribution of " << tag << ": wheel arc length s (grid of the profile BEFORE the step), wheel wear "
         "rate (mean of all wheels, mm of depth per km travelled, raw), depth removed in the step (smoothed, scaled to the cap);"
         " rail depth per wheel passage (left/right rail, arc length on the mounted rail)\n";
  out << "s_mm,wheel_rate_mm_per_km,removed_mm\n";
  out << std::setprecision(10);
  for (size_t i = 0; i < s.wheel_depth_per_metre.size(); ++i)
    out << s.wheel_depth_per_metre.s(i) * 1e3 << "," << s.wheel_depth_per_metre.depth_m[i] * 1e6 << ","
        << (i < s.removed_depth.size() ? s.removed_depth.depth_m[i] * 1e3 : 0.0) << "\n";
  std::ofstream rail(dir + "/rail_wear_" + tag + ".csv");
  rail << "side,s_mm,depth_per_passage_nm\n" << std::setprecision(10);
  for (int k = 0; k < 2; ++k)
    for (size_t i = 0; i < s.rail_depth_per_passage[k].size(); ++i)
      rail << (k == 0 ? "left," : "right,") << s.rail_depth_per_passage[k].s(i) * 1e3 << ","
           << s.rail_depth_per_passage[k].depth_m[i] * 1e9 << "\n";
}

void FinishWearOutput(const std::string& dir, const WearSimulationResult& r) {
  SaveBoth(r.initial_wheel, dir + "/wheel_step_000");
  SaveBoth(r.initial_rail[0], dir + "/rail_left_000");
  SaveBoth(r.initial_rail[1], dir + "/rail_right_000");
  std::ofstream out(dir + "/steps.csv");
  if (!out) throw InputError(dir + "/steps.csv: cannot write");
  out << "rail_step,step,km,step_km,max_depth_mm,sd_mm,sh_mm,qr_mm,tread_wear_mm,flange_wear_mm,wall_s,"
         "max_curvature_1_m,samples,failed_contacts,approximate_contacts,hertz_fallback_contacts,kinematics_fallbacks,"
         "depth_cap_mm,patches_hertz,patches_kp,patches_kpec,patches_conformal,overhang_cut_mm2,"
         "cut_area_scale,cut_area_conserved\n";
  out << std::setprecision(8);
  const WheelDimensions& d0 = r.initial_dimensions;
  out << "0,0,0,0,0," << d0.sd_m * 1e3 << "," << d0.sh_m * 1e3 << "," << d0.qr_m * 1e3 << ",0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1,1\n";
  for (const WearStepRecord& s : r.steps) {
    out << s.rail_step << "," << s.step << "," << s.km << "," << s.step_km << "," << s.max_depth_m * 1e3 << ","
        << s.dimensions.sd_m * 1e3 << "," << s.dimensions.sh_m * 1e3 << "," << s.dimensions.qr_m * 1e3 << ","
        << s.tread_wear_m * 1e3 << "," << s.flange_wear_m * 1e3 << "," << s.wall_s << ","
        << s.validity.max_abs_curvature_1_m << "," << s.samples << "," << s.failed_contacts << "," << s.approximate_contacts << "," << s.hertz_fallback_contacts << "," << s.kinematics_fallbacks << ","
        << s.depth_cap_m * 1e3;
    for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal})
      out << "," << s.patches_by_model[static_cast<int>(m)];
    out << "," << s.overhang_cut_area_m2 * 1e6 << "," << s.cut_area_scale << "," << (s.cut_area_conserved ? 1 : 0) << "\n";
  }
  // why each kinematics fallback of steps.csv happened (class: reason; replacement), one row per class and step
  std::ofstream fb(dir + "/kinematics_fallbacks.csv");
  if (!fb) throw InputError(dir + "/kinematics_fallbacks.csv: cannot write");
  fb << "rail_step,step,fallback\n";
  for (const WearStepRecord& s : r.steps)
    for (const std::string& why : s.kinematics_fallback_reasons) {
      std::string quoted = "\"";
      for (char ch : why) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
      fb << s.rail_step << "," << s.step << "," << quoted << "\"\n";
    }
  for (size_t k = 0; k < r.rails.size(); ++k) {
    SaveBoth(r.rails[k][0], dir + "/rail_left_" + Num3(static_cast<int>(k + 1)));
    SaveBoth(r.rails[k][1], dir + "/rail_right_" + Num3(static_cast<int>(k + 1)));
  }
  std::ofstream st(dir + "/status.txt");
  st << to_string(r.status) << "\n" << r.message << "\n";
  const std::string incomplete = IncompleteReason(r);  // lost contacts too: "completed" alone would hide them
  if (!incomplete.empty()) st << "incomplete: " << incomplete << "\n";
}

WearSimulationResult RunWearWithOutput(const Scenario& scenario, WearSimulationOptions options, const std::string& dir,
                                       const std::string& label, int steps_total, double* wall_s,
                                       ProgressMode mode) {
  BeginWearOutput(dir);
  // wheel steps restart at 1 in every rail step: counted over all rail steps
  const int rail_steps = !scenario.rail_steps.fixed && scenario.rail_steps.steps > 0 ? scenario.rail_steps.steps : 1;
  auto progress = std::make_shared<ProgressReporter>(label, static_cast<double>(steps_total) * rail_steps, "step",
                                                     mode, std::cerr);
  options.on_step = [dir, steps_total, progress](const WearStepRecord& s) {
    WriteWearStep(dir, s);
    char detail[160];
    std::snprintf(detail, sizeof detail, "%s%.0f km, Sd %.2f qR %.2f mm, %.1f s/step",
                  s.rail_step > 0 ? ("rail step " + std::to_string(s.rail_step) + ", ").c_str() : "", s.km,
                  s.dimensions.sd_m * 1e3, s.dimensions.qr_m * 1e3, s.wall_s);
    progress->Update(static_cast<double>(s.rail_step) * std::max(0, steps_total) + s.step, detail);
  };
  // every provider of the scenario, the time-domain `dynamic` one included (dynamic_kinematics.hpp)
  if (!options.kinematics_factory) options.kinematics_factory = &MakeWearKinematics;
  const auto t0 = std::chrono::steady_clock::now();
  WearSimulationResult result = RunWearSimulation(scenario, options);
  progress->Finish();
  *wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  FinishWearOutput(dir, result);
  return result;
}

void PrintRunWarnings(const std::string& label, const WearSimulationResult& r) {
  for (const WearStepRecord& s : r.steps) {
    if (s.failed_contacts > 0)
      std::printf("  WARNING: [%s] step %d: %d of %d wheel contacts FAILED (no wear taken from them; steps.csv "
                  "failed_contacts)\n",
                  label.c_str(), s.step, s.failed_contacts, s.failed_contacts + s.samples);
    if (s.kinematics_fallbacks > 0) {
      std::printf("  note: [%s] step %d: %d track class(es) used a kinematics fallback (steps.csv kinematics_fallbacks):\n",
                  label.c_str(), s.step, s.kinematics_fallbacks);
      for (const std::string& why : s.kinematics_fallback_reasons) std::printf("        %s\n", why.c_str());
    }
    if (!s.cut_area_conserved)
      std::printf("  note: [%s] step %d: the overhang cut could not keep the step's wear area (no scaling of the "
                  "depth around the cut balanced it); the lip was cut on top of the wear, %.4g mm^2 (steps.csv "
                  "cut_area_conserved)\n",
                  label.c_str(), s.step, s.overhang_cut_area_m2 * 1e6);
  }
  if (r.status != WearSimulationStatus::Completed)
    std::printf("  WARNING: [%s] stopped: %s %s\n", label.c_str(), to_string(r.status), r.message.c_str());
  std::fflush(stdout);
}

void WriteLostContactWarnings(std::ostream& md, const std::string& label, const WearSimulationResult& r) {
  for (const WearStepRecord& s : r.steps)
    if (s.failed_contacts > 0)
      md << "**WARNING: " << label << " step " << s.step << ": " << s.failed_contacts << " of "
         << s.failed_contacts + s.samples
         << " wheel contacts failed; no wear was taken from them (steps.csv failed_contacts).**\n\n";
}

void ThrowIfIncomplete(const std::vector<std::pair<std::string, const WearSimulationResult*>>& runs) {
  std::string what;
  for (const auto& [label, result] : runs) {
    const std::string reason = IncompleteReason(*result);
    if (!reason.empty()) what += (what.empty() ? "" : "; ") + label + ": " + reason;
  }
  if (!what.empty()) throw IncompleteResult(ExitCode::PartialResult, what);
}

}  // namespace conforma::cli
